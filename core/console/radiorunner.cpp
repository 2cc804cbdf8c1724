// SPDX-License-Identifier: GPL-3.0-or-later
#include "radiorunner.h"

#include "radio/frequencytext.h"

#include <QJsonDocument>
#include <QJsonObject>

namespace slew::console {

using radio::RadioLink;

RadioRunner::RadioRunner(RadioLink *link, bool json, QObject *parent) : QObject(parent), m_link(link), m_json(json)
{
    m_timeout.setSingleShot(true);
    connect(&m_timeout, &QTimer::timeout, this, [this] { finish(ExitCode::Failed, tr("the radio did not answer in time")); });
    connect(link, &RadioLink::stateChanged, this, &RadioRunner::onState);
    connect(link, &RadioLink::frequenciesRead, this, &RadioRunner::onRead);
    connect(link, &RadioLink::commandFailed, this, [this](const QString &command, const QString &why) {
        m_failed = true;
        finish(why.startsWith(QLatin1String("not sent")) ? ExitCode::Refused : ExitCode::Failed,
               tr("%1: %2").arg(command, why));
    });
}

void RadioRunner::run(const RadioCommand &command, int timeoutMs)
{
    m_command = command;
    m_timeout.start(timeoutMs);
    if (m_link->isOpen())
        send();
    else
        m_link->open();
}

void RadioRunner::onState(RadioLink::State state, const QString &detail)
{
    if (state == RadioLink::State::Open && !m_sent)
        send();
    else if (state == RadioLink::State::Closed)
        finish(ExitCode::LinkFailure, detail);
}

void RadioRunner::send()
{
    m_sent = true;
    switch (m_command.kind) {
    case RadioCommand::Kind::Read:
        break;
    case RadioCommand::Kind::SetReceive:
        m_link->setReceiveHz(m_command.hz);
        break;
    case RadioCommand::Kind::SetTransmit:
        m_link->setTransmitHz(m_command.hz);
        break;
    case RadioCommand::Kind::Split:
        m_link->setSplit(m_command.on);
        break;
    case RadioCommand::Kind::Mode:
        m_link->setMode(m_command.mode, 0);
        break;
    case RadioCommand::Kind::TransmitMode:
        m_link->setTransmitMode(m_command.mode, 0);
        break;
    }
    // The read goes after the command on the link, in turn: its answer
    // shows what the command did.
    if (!m_done)
        m_link->readFrequencies();
}

void RadioRunner::onRead(const radio::RadioFrequencies &f)
{
    if (m_done || !m_sent)
        return;
    if (m_json) {
        QJsonObject o;
        if (f.receiveHz)
            o.insert(QStringLiteral("receive_hz"), *f.receiveHz);
        if (f.transmitHz)
            o.insert(QStringLiteral("transmit_hz"), *f.transmitHz);
        emit output(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)));
    } else {
        // As the window writes them; --json has the hertz.
        QString line = tr("receive %1").arg(f.receiveHz ? radio::groupedMegahertz(*f.receiveHz) : tr("unknown"));
        if (f.transmitHz)
            line += tr(", transmit %1").arg(radio::groupedMegahertz(*f.transmitHz));
        emit output(line);
    }
    // A frequency set and read back differently: the radio moved it (its
    // step, its range) or someone else did.
    if (m_command.kind == RadioCommand::Kind::SetReceive && f.receiveHz && std::abs(*f.receiveHz - m_command.hz) >= 1
        && m_link->canReadBack()) {
        finish(ExitCode::Failed, tr("the radio reads %1 Hz, not the %2 Hz set")
                                     .arg(*f.receiveHz, 0, 'f', 0)
                                     .arg(m_command.hz, 0, 'f', 0));
        return;
    }
    finish(ExitCode::Ok);
}

void RadioRunner::finish(ExitCode code, const QString &why)
{
    if (m_done)
        return;
    m_done = true;
    m_timeout.stop();
    if (!why.isEmpty())
        emit problem(why);
    m_link->close();
    emit finished(code);
}

} // namespace slew::console
