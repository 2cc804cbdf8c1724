// SPDX-License-Identifier: GPL-3.0-or-later
#include "controllerradio.h"

#include "input/logtext.h"
#include "radiolimits.h"
#include "session/controllerradiocommands.h"
#include "session/rotatorsession.h"

namespace slew::radio {

using session::ControllerRadioCommands;
using session::RotatorSession;

namespace {

// A reading the controller has not answered by then is given up: the
// session's own reply timeout and retries are well inside it.
constexpr int kReadTimeoutMs = 3000;

// What the Easycomm tables' lines carry (kHighestHz and kLongestMode in
// ControllerRadioCommands) is narrower than the shared limits.
// ControllerRadioCommands refuses the same on the line; checked here too so
// the refusal comes when the value is given (the pacer may send it much
// later), in the words every radio link uses.
constexpr double kLineHighestHz = ControllerRadioCommands::kHighestHz;
constexpr qsizetype kLineModeChars = ControllerRadioCommands::kLongestMode;

} // namespace

ControllerRadioLink::ControllerRadioLink(RotatorSession *session, QObject *parent)
    : RadioLink(parent), m_session(session)
{
    connect(&m_pacer, &CommandPacer::ready, this, &ControllerRadioLink::send);
    m_readTimeout.setSingleShot(true);
    m_readTimeout.setInterval(kReadTimeoutMs);
    connect(&m_readTimeout, &QTimer::timeout, this,
            [this] { finishRead(false, tr("the controller did not answer UP/DN")); });
    connect(session->radioCommands(), &ControllerRadioCommands::frequencyReported, this,
            [this](ControllerRadioCommands::Path path, double hz) { onReported(int(path), hz); });
    connect(session, &RotatorSession::stateChanged, this, [this](RotatorSession::State s, const QString &detail) {
        if (s != RotatorSession::State::Connected && m_state != State::Closed)
            setState(State::Closed, tr("the rotator's link: %1").arg(detail));
    });
}

void ControllerRadioLink::setState(State state, const QString &detail)
{
    if (state != State::Open) {
        m_pacer.clear();
        m_readTimeout.stop();
        m_readInFlight = false;
    }
    m_state = state;
    emit stateChanged(state, tr("%1: %2").arg(uri(), detail)); // named, as every link's detail (radiolink.h)
}

void ControllerRadioLink::open()
{
    if (!m_session->isConnected()) {
        setState(State::Closed, tr("connect the rotator first: the radio is behind its controller"));
        return;
    }
    if (!m_session->radioCommands()->isSupported()) {
        setState(State::Closed, tr("the controller's dialect has no station radio commands (UP, DN)"));
        return;
    }
    setState(State::Open, tr("the radio behind the controller, on %1").arg(m_session->uri()));
    // The first reading measures how long a round trip takes.
    readFrequencies();
}

void ControllerRadioLink::close()
{
    setState(State::Closed, tr("closed"));
}

bool ControllerRadioLink::canReadBack() const
{
    return false; // the controller tells what it was told, not where the dial is
}

void ControllerRadioLink::submit(const PacedCommand &command)
{
    // Refused in words, as every radio link refuses, rather than dropped.
    if (m_state != State::Open) {
        emit commandFailed(command.text, tr("not sent: %1 is not open").arg(uri()));
        return;
    }
    m_pacer.submit(command);
}

void ControllerRadioLink::setFrequency(CommandKind kind, const QString &line, double hz)
{
    // The shared limits first, so what no radio takes is refused in the
    // words every link uses; then what the line carries.
    const QString text = line + QString::number(hz, 'f', 0);
    QString why = limits::frequencyRefusal(hz);
    if (why.isEmpty() && hz > kLineHighestHz)
        why = tr("not sent: the controller's %1 line carries at most ten digits of hertz (%2 Hz)")
                  .arg(line)
                  .arg(kLineHighestHz, 0, 'f', 0);
    if (!why.isEmpty()) {
        emit commandFailed(text, why);
        return;
    }
    submit({kind, text, 0, hz, {}});
}

void ControllerRadioLink::setPathMode(CommandKind kind, const QString &line, const QString &mode, int passbandHz)
{
    // The passband does not reach the controller (DM/UM carry a mode name
    // only), but one out of range is refused as every link refuses it.
    const QString text = input::loggableText(line + mode, 60); // a refused name may hold a line end
    QString why = limits::modeRefusal(mode, passbandHz);
    if (why.isEmpty() && mode.size() > kLineModeChars)
        why = tr("not sent: the controller's %1 line carries a mode of at most %2 letters or digits")
                  .arg(line)
                  .arg(kLineModeChars);
    if (!why.isEmpty()) {
        emit commandFailed(text, why);
        return;
    }
    submit({kind, line + mode, 0, 0, mode});
}

void ControllerRadioLink::setReceiveHz(double hz)
{
    setFrequency(CommandKind::ReceiveFrequency, QStringLiteral("DN"), hz);
}

void ControllerRadioLink::setTransmitHz(double hz)
{
    setFrequency(CommandKind::TransmitFrequency, QStringLiteral("UP"), hz);
}

void ControllerRadioLink::setMode(const QString &mode, int passbandHz)
{
    setPathMode(CommandKind::Mode, QStringLiteral("DM"), mode, passbandHz);
}

void ControllerRadioLink::setTransmitMode(const QString &mode, int passbandHz)
{
    setPathMode(CommandKind::TransmitMode, QStringLiteral("UM"), mode, passbandHz);
}

void ControllerRadioLink::readFrequencies()
{
    // Refused while closed, as every command is; open, Easycomm I answers
    // nothing (it takes settings blind), so there is nothing to ask.
    if (m_state == State::Open && !m_session->radioCommands()->canRead())
        return;
    submit({CommandKind::Read, QStringLiteral("DN UP")});
}

void ControllerRadioLink::send(const PacedCommand &command)
{
    ControllerRadioCommands *radio = m_session->radioCommands();
    session::CommandResult result;
    switch (command.kind) {
    case CommandKind::ReceiveFrequency:
        // The newest: it replaced any older.
        result = radio->setFrequency(ControllerRadioCommands::Path::Downlink, command.hz);
        break;
    case CommandKind::TransmitFrequency:
        result = radio->setFrequency(ControllerRadioCommands::Path::Uplink, command.hz);
        break;
    case CommandKind::Mode:
        result = radio->setMode(ControllerRadioCommands::Path::Downlink, command.mode);
        break;
    case CommandKind::TransmitMode:
        result = radio->setMode(ControllerRadioCommands::Path::Uplink, command.mode);
        break;
    case CommandKind::Split:
        break;
    case CommandKind::Read:
        m_reading = {};
        m_readInFlight = true;
        m_readSince.start();
        m_readTimeout.start();
        result = radio->readFrequency(ControllerRadioCommands::Path::Downlink);
        if (result)
            result = radio->readFrequency(ControllerRadioCommands::Path::Uplink);
        if (!result) {
            finishRead(false, result.refusal);
            return;
        }
        emit commandSent(command.text);
        return; // finished when the answers are in
    }
    if (result)
        emit commandSent(command.text);
    else
        emit commandFailed(command.text, result.refusal);
    m_pacer.finished(); // a setting has no answer: written is done
}

void ControllerRadioLink::onReported(int path, double hz)
{
    if (!m_readInFlight)
        return;
    if (path == int(ControllerRadioCommands::Path::Downlink))
        m_reading.receiveHz = hz;
    else
        m_reading.transmitHz = hz;
    if (m_reading.receiveHz && m_reading.transmitHz)
        finishRead(true, {});
}

void ControllerRadioLink::finishRead(bool ok, const QString &why)
{
    if (!m_readInFlight)
        return;
    m_readInFlight = false;
    m_readTimeout.stop();
    if (ok) {
        // Each answer waits for the polls ahead of it in the session's
        // queue: the latency a command meets is about that long.
        m_latencyMs = int(m_readSince.elapsed());
        emit frequenciesRead(m_reading);
    } else {
        emit commandFailed(QStringLiteral("DN UP"), why);
    }
    m_pacer.finished();
}

} // namespace slew::radio
