// SPDX-License-Identifier: GPL-3.0-or-later
#include "consolerunner.h"

#include "session/rotatorsession.h"
#include "session/stopbeforeexit.h"
#include "tuning/homingrun.h"

#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace slew::console {
namespace {

using session::RotatorSession;

QString json(const QJsonObject &object)
{
    return QString::fromUtf8(QJsonDocument(object).toJson(QJsonDocument::Compact));
}

} // namespace

ConsoleRunner::ConsoleRunner(RotatorSession *session, bool json, QObject *parent)
    : QObject(parent), m_session(session), m_json(json), m_move(session)
{
    connect(&m_move, &session::MoveWatch::ended, this, &ConsoleRunner::moveEnded);
    m_deadline.setSingleShot(true);
    connect(&m_deadline, &QTimer::timeout, this, [this] {
        if (!m_started)
            finish(ExitCode::LinkFailure, tr("no answer from %1 within %2 s").arg(m_session->uri()).arg(m_connectTimeoutMs / 1000.0));
        else
            finish(ExitCode::Failed, tr("not there after %1 s; the rotator keeps going").arg(m_arrivalTimeoutMs / 1000.0));
    });
}

ConsoleRunner::~ConsoleRunner() = default;

void ConsoleRunner::run(const ConsoleCommand &command)
{
    m_command = command;
    m_running = true;
    m_started = false;
    m_seenConnected = m_session->isConnected();
    m_move.cancel();
    m_interrupted = false;
    m_deadline.start(m_connectTimeoutMs);
    m_connections << connect(m_session, &RotatorSession::stateChanged, this,
                             [this](RotatorSession::State state, const QString &detail) {
                                 if (state == RotatorSession::State::Connected)
                                     m_seenConnected = true;
                                 if (state == RotatorSession::State::Disconnected
                                     || state == RotatorSession::State::Reconnecting)
                                     // A port that never opened was not lost.
                                     finish(ExitCode::LinkFailure, m_seenConnected
                                                                       ? tr("link lost: %1").arg(detail)
                                                                       : tr("cannot connect: %1").arg(detail));
                                 else
                                     whenReady();
                             });
    m_connections << connect(m_session, &RotatorSession::capabilitiesChanged, this, [this] { whenReady(); });
    m_connections << connect(m_session, &RotatorSession::positionChanged, this, [this] { whenReady(); });
    whenReady();
}

void ConsoleRunner::whenReady()
{
    if (!m_running || m_started || !m_session->isConnected() || !m_session->capabilities().probed)
        return;
    // Everything but a raw line or a register wants to know where it is.
    const bool needsPosition = m_command.kind != ConsoleCommand::Kind::Raw
                               && m_command.kind != ConsoleCommand::Kind::ConfigGet
                               && m_command.kind != ConsoleCommand::Kind::ConfigSet;
    if (needsPosition && !m_session->hasPosition())
        return;
    m_started = true;
    m_deadline.stop();
    start();
}

void ConsoleRunner::start()
{
    using Kind = ConsoleCommand::Kind;
    switch (m_command.kind) {
    case Kind::Get:
        printPosition("position");
        finish(ExitCode::Ok);
        return;
    case Kind::Goto:
        startGoto();
        return;
    case Kind::Stop:
        m_session->stop(tr("slewctl stop"));
        emit output(m_json ? json({{QStringLiteral("event"), QStringLiteral("stopped")}}) : tr("stopped"));
        finishWhenSent();
        return;
    case Kind::Park:
        if (const auto parked = m_session->park(); !parked) {
            finish(ExitCode::Refused, parked.refusal);
            return;
        }
        emit output(m_json ? json({{QStringLiteral("event"), QStringLiteral("parking")}}) : tr("parking"));
        if (!m_command.wait) {
            finishWhenSent();
            return;
        }
        // Where the controller's park registers say, once read; else
        // wherever it comes to rest.
        watchMove(m_session->parkKnown()
                      ? std::optional<QPointF>(QPointF(m_session->parkAzimuth(), m_session->parkElevation()))
                      : std::nullopt);
        return;
    case Kind::Home:
        startHome();
        return;
    case Kind::Watch:
        startWatch();
        return;
    case Kind::Raw:
        startRaw();
        return;
    case Kind::ConfigGet:
    case Kind::ConfigSet:
        startConfig();
        return;
    case Kind::Help:
    case Kind::Quit:
        finish(ExitCode::Ok);
        return;
    }
}

void ConsoleRunner::startGoto()
{
    if (const auto sent = m_session->gotoPosition(m_command.azimuth, m_command.elevation); !sent) {
        finish(ExitCode::Refused, sent.refusal);
        return;
    }
    const double targetAz = m_session->targetAzimuth(), targetEl = m_session->targetElevation();
    emit output(m_json ? json({{QStringLiteral("event"), QStringLiteral("moving")},
                               {QStringLiteral("target_az"), targetAz},
                               {QStringLiteral("target_el"), targetEl}})
                       : tr("moving to az %1 el %2").arg(targetAz, 0, 'f', 2).arg(targetEl, 0, 'f', 2));
    if (!m_command.wait) {
        finishWhenSent();
        return;
    }
    watchMove(QPointF(targetAz, targetEl));
}

void ConsoleRunner::watchMove(std::optional<QPointF> target)
{
    m_deadline.start(m_arrivalTimeoutMs);
    m_move.watch(target);
}

void ConsoleRunner::moveEnded(session::MoveWatch::Outcome outcome, QPointF, double offDeg)
{
    // Ctrl-C and a lost link are reported where they are handled.
    if (!m_running || m_interrupted)
        return;
    using Outcome = session::MoveWatch::Outcome;
    switch (outcome) {
    case Outcome::Arrived:
        printPosition("arrived");
        finish(ExitCode::Ok);
        return;
    case Outcome::StoppedShort:
    case Outcome::Stopped:
        // It moved and stopped elsewhere (a limit, an obstacle, a stop from
        // another client): say where and how far off, rather than wait on.
        printPosition("stopped");
        finish(ExitCode::Failed, tr("stopped %1° from the target").arg(offDeg, 0, 'f', 2));
        return;
    case Outcome::Replaced:
        printPosition("stopped");
        finish(ExitCode::Failed, tr("another target was sent before this one was reached"));
        return;
    case Outcome::Refused:
        finish(ExitCode::Refused, m_move.refusal());
        return;
    case Outcome::LinkLost:
        return;
    }
}

void ConsoleRunner::startHome()
{
    if (!m_command.wait) {
        if (const auto homing = m_session->home(); !homing) {
            finish(ExitCode::Refused, homing.refusal);
            return;
        }
        emit output(m_json ? json({{QStringLiteral("event"), QStringLiteral("homing")}}) : tr("homing"));
        finishWhenSent();
        return;
    }
    m_homing = std::make_unique<tuning::HomingRun>(m_session);
    connect(m_homing.get(), &tuning::HomingRun::succeeded, this, [this] {
        printPosition("homed");
        finish(ExitCode::Ok);
    });
    connect(m_homing.get(), &tuning::HomingRun::failed, this,
            [this](const QString &reason) {
                finish(m_homing->refusedByController() ? ExitCode::Refused : ExitCode::Failed,
                       tr("homing failed: %1").arg(reason));
            });
    connect(m_homing.get(), &tuning::HomingRun::cancelled, this,
            [this] { finish(ExitCode::Failed, tr("homing cancelled; the rotator was stopped")); });
    if (!m_homing->start(m_arrivalTimeoutMs / 1000.0))
        finish(ExitCode::Refused, m_homing->error());
}

void ConsoleRunner::startWatch()
{
    printPosition("position");
    m_tick.setSingleShot(false);
    m_tick.setInterval(int(std::lround(m_command.intervalSeconds * 1000)));
    m_connections << connect(&m_tick, &QTimer::timeout, this, [this] { printPosition("position"); });
    m_tick.start();
}

void ConsoleRunner::startRaw()
{
    // Only the answer to this line is wanted: nothing else is asked, and a
    // poll already on the wire is answered first.
    m_session->setPolling(false);
    m_rawSent = false;
    m_connections << connect(m_session, &RotatorSession::bytesReceived, this, [this](const QByteArray &bytes) {
        if (!m_rawSent) {
            // The session takes the reply off its queue after this signal.
            QTimer::singleShot(0, this, &ConsoleRunner::sendRawWhenQuiet);
            return;
        }
        m_rawAnswer += bytes;
        const qsizetype end = m_rawAnswer.indexOf('\n') >= 0 ? m_rawAnswer.indexOf('\n') : m_rawAnswer.indexOf('\r');
        if (end < 0)
            return;
        const QString answer = QString::fromLatin1(m_rawAnswer.left(end)).trimmed();
        emit output(m_json ? json({{QStringLiteral("sent"), m_command.text}, {QStringLiteral("answer"), answer}})
                           : answer);
        finish(ExitCode::Ok);
    });
    m_connections << connect(m_session, &RotatorSession::requestFailed, this, &ConsoleRunner::sendRawWhenQuiet);
    sendRawWhenQuiet();
}

void ConsoleRunner::sendRawWhenQuiet()
{
    if (!m_running || m_rawSent || m_session->queuedRequests() > 0)
        return;
    m_rawSent = true;
    m_rawAnswer.clear();
    if (const auto sent = m_session->sendRaw(m_command.text); !sent) {
        finish(ExitCode::Refused, sent.refusal);
        return;
    }
    // Many commands have no answer: once the controller's reply time has
    // passed, say so and go.
    m_tick.setSingleShot(true);
    m_tick.setInterval(m_session->options().replyTimeoutMs);
    m_connections << connect(&m_tick, &QTimer::timeout, this, [this] {
        emit output(m_json ? json({{QStringLiteral("sent"), m_command.text}, {QStringLiteral("answer"), QJsonValue()}})
                           : tr("(no answer)"));
        finish(ExitCode::Ok);
    });
    m_tick.start();
}

void ConsoleRunner::startConfig()
{
    m_session->setPolling(false);
    const int reg = m_command.reg;
    const bool writing = m_command.kind == ConsoleCommand::Kind::ConfigSet;
    m_connections << connect(m_session, &RotatorSession::configValueReceived, this,
                             [this, reg, writing](int answered, const QString &value) {
                                 if (answered != reg)
                                     return;
                                 if (m_json)
                                     emit output(json({{QStringLiteral("register"), reg}, {QStringLiteral("value"), value}}));
                                 else
                                     emit output(QStringLiteral("CR%1 %2").arg(reg).arg(value));
                                 const bool same = !writing || value.toDouble() == m_command.text.toDouble()
                                                   || value == m_command.text;
                                 finish(same ? ExitCode::Ok : ExitCode::Failed,
                                        same ? QString() : tr("wrote %1, read back %2").arg(m_command.text, value));
                             });
    m_connections << connect(m_session, &RotatorSession::requestFailed, this,
                             [this](const QString &request, const QString &reason) {
                                 finish(ExitCode::Failed, tr("%1: %2").arg(request, reason));
                             });
    if (writing) {
        if (const auto written = m_session->writeConfig(reg, m_command.text); !written) {
            finish(ExitCode::Refused, written.refusal);
            return;
        }
    }
    if (const auto read = m_session->readConfig(reg); !read)
        finish(ExitCode::Refused, read.refusal);
}

void ConsoleRunner::interrupt()
{
    if (!m_running)
        return;
    const bool moving = m_command.wait && m_started;
    if (m_homing && m_homing->isRunning()) {
        m_homing->cancel(); // stops the rotator, then reports cancelled
        return;
    }
    if (moving) {
        m_deadline.stop();
        m_interrupted = true;
        session::stopThenCall(*m_session, tr("slewctl was interrupted"), this,
                              [this] { finish(ExitCode::Failed, tr("interrupted; the rotator was stopped")); });
        return;
    }
    finish(ExitCode::Ok);
}

void ConsoleRunner::printPosition(const char *event)
{
    const double az = m_session->azimuth(), el = m_session->elevation();
    if (m_json) {
        emit output(json({{QStringLiteral("event"), QString::fromLatin1(event)},
                          {QStringLiteral("az"), az},
                          {QStringLiteral("el"), el},
                          {QStringLiteral("stale"), m_session->positionStale()}}));
    } else {
        emit output(QStringLiteral("az %1 el %2%3")
                        .arg(az, 0, 'f', 2)
                        .arg(el, 0, 'f', 2)
                        .arg(m_session->positionStale() ? tr(" (stale)") : QString()));
    }
}

void ConsoleRunner::finishWhenSent(ExitCode code, const QString &problemText)
{
    // What the command wrote must leave before the program may end.
    m_deadline.stop();
    session::callWhenSent(*m_session, this, [this, code, problemText] { finish(code, problemText); });
}

void ConsoleRunner::finish(ExitCode code, const QString &problemText)
{
    if (!m_running)
        return;
    m_running = false;
    m_deadline.stop();
    m_tick.stop();
    for (const QMetaObject::Connection &c : std::as_const(m_connections))
        disconnect(c);
    m_connections.clear();
    if (!problemText.isEmpty())
        emit problem(m_json ? json({{QStringLiteral("error"), problemText}, {QStringLiteral("code"), int(code)}})
                            : problemText);
    if (m_homing) {
        m_homing->disconnect(this);
        m_homing.release()->deleteLater();
    }
    m_session->setPolling(true);
    emit finished(code);
}

} // namespace slew::console
