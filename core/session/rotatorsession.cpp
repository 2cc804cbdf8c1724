// SPDX-License-Identifier: GPL-3.0-or-later
// RotatorSession, part one: the link (open, lose, reconnect) and what comes
// back on it. Parts two and three: rotatorsession_requests.cpp (queue,
// probe, polling) and rotatorsession_commands.cpp (moves, config, raw).

#include "rotatorsession.h"

#include "micro2gcalibration.h"
#include "profilehints.h"
#include "stationradio.h"

#include "input/logtext.h"
#include "protocol/encoder.h"
#include "protocol/operations.h"
#include "transport/link.h"
#include "transport/linkfactory.h"

#include <QDateTime>
#include <QIODevice>

#include <algorithm>
#include <cmath>

namespace slew::session {

using protocol::Message;
using protocol::Op;

namespace {

constexpr int kMaxReconnectDelayMs = 30000;
// How much of a controller's bad line a log line quotes (escaped).
constexpr int kQuotedChars = 60;

QString quoted(QByteArrayView bytes)
{
    return input::loggableText(QString::fromLatin1(bytes.first(std::min<qsizetype>(bytes.size(), 4 * kQuotedChars))),
                               kQuotedChars);
}
} // namespace

RotatorSession::RotatorSession(QObject *parent) : QObject(parent), m_queue(m_options.maxQueue)
{
    qRegisterMetaType<Telemetry>();
    qRegisterMetaType<Capabilities>();
    qRegisterMetaType<StatusWord>();
    m_clock.start();
    m_micro2g = std::make_unique<Micro2gCalibration>(this);
    m_stationRadio = std::make_unique<StationRadio>(this);

    m_replyTimer.setSingleShot(true);
    connect(&m_replyTimer, &LinkTimer::timeout, this, &RotatorSession::onReplyTimeout);
    connect(&m_turnaround, &LineTurnaround::released, this, &RotatorSession::writeNow);
    connect(&m_turnaround, &LineTurnaround::drained, this, &RotatorSession::heldLinesWritten);
    m_reconnectTimer.setSingleShot(true);
    connect(&m_reconnectTimer, &QTimer::timeout, this, &RotatorSession::openLink);
    m_staleTimer.setSingleShot(true);
    connect(&m_staleTimer, &LinkTimer::timeout, this, &RotatorSession::onStale);
    connect(&m_pollTimer, &LinkTimer::timeout, this, &RotatorSession::poll);
    connect(&m_keepAliveTimer, &LinkTimer::timeout, this, &RotatorSession::keepAlive);
    m_stopHoldTimer.setSingleShot(true);
    connect(&m_stopHoldTimer, &LinkTimer::timeout, this, &RotatorSession::sendStopHold);
    m_heldBackReport.setSingleShot(true);
    m_heldBackReport.setInterval(ControllerLogAllowance::kSummaryMs);
    connect(&m_heldBackReport, &LinkTimer::timeout, this, &RotatorSession::reportHeldBack);
    setProfile(m_profile);
}

RotatorSession::~RotatorSession()
{
    m_wantConnected = false;
    if (m_link) {
        m_link->disconnect(this);
        m_link->device()->disconnect(this);
        m_link->close();
    }
}

void RotatorSession::setProfile(const model::RotatorProfile &profile)
{
    m_profile = profile;
    updateGateLimits();
    m_parser.setDialect(profile.dialect);
    updatePollPace();
    m_keepAliveTimer.setInterval(std::max(100, m_options.keepAliveMs));
    emit profileChanged();
}

void RotatorSession::updatePollPace()
{
    int pollMs = 1000 / std::clamp(m_profile.pollHz, 1, 50);
    m_replyTimeoutMs = m_options.replyTimeoutMs;
    if (const std::optional<int> baud = m_link ? m_link->hints().baud : std::nullopt; baud && *baud > 0) {
        // One poll on the wire: the question and the answer, 10 bits a
        // byte (8N1). Polls take at most half the line, so a command always
        // finds room; an answer is waited for its time on the wire and more.
        const int bytes = int(protocol::encodeQueryPosition(m_profile.dialect, m_rotor).size())
                          + protocol::positionReplyBytes(m_profile.dialect);
        const int exchangeMs = int(std::ceil(bytes * 10 * 1000.0 / *baud));
        pollMs = std::max(pollMs, 2 * exchangeMs);
        m_replyTimeoutMs = std::max(m_replyTimeoutMs, exchangeMs + 300);
    }
    // A firmware that polling starves (its replies hold its loop) is
    // polled no faster than it keeps up with.
    pollMs = std::max(pollMs, firmwareTraits().shortestPollMs);
    m_turnaround.setTurnaroundMs(firmwareTraits().turnaroundMs);
    m_refusals.setWindowMs(m_replyTimeoutMs);
    m_pace.setIntervals(pollMs, int(std::lround(1000.0 / std::max(0.1, m_profile.restPollHz))));
    retimePolling();
}

int RotatorSession::staleAfterMs(int pollMs) const
{
    // Three polls missed, the last one with all its retries.
    return std::max(1500, 3 * pollMs + m_replyTimeoutMs * (m_options.retries + 1));
}

void RotatorSession::retimePolling()
{
    m_pollingAtRest = m_pace.resting(nowMs());
    // Restarted on a change, not only re-set: woken at rest, the next poll
    // comes one full interval from now, not up to a slow one later. The
    // stale timer follows, so a rotator polled once a second at rest is
    // not stale between two polls, and a woken one is missed as soon as
    // ever. Left alone when nothing changed: a restart would put the stale
    // alarm off for ever.
    const int interval = m_pace.intervalMs(nowMs());
    if (interval != m_pollTimer.interval())
        m_pollTimer.isActive() ? m_pollTimer.start(interval) : m_pollTimer.setInterval(interval);
    if (const int stale = staleAfterMs(interval); stale != m_staleTimer.interval())
        m_staleTimer.isActive() ? m_staleTimer.start(stale) : m_staleTimer.setInterval(stale);
}

void RotatorSession::wakePolling()
{
    m_pace.wake(nowMs());
    retimePolling();
}

void RotatorSession::setOptions(const Options &options)
{
    m_options = options;
    m_queue.setCapacity(options.maxQueue);
    setProfile(m_profile);
}

void RotatorSession::setPolling(bool enabled)
{
    m_pollingEnabled = enabled;
    if (m_state != State::Connected)
        return;
    // Paused, no poll timer runs: it would only wake the machine to do
    // nothing. A dialect with a keep-alive sends it instead.
    if (enabled) {
        m_keepAliveTimer.stop();
        m_pace.wake(nowMs());
        retimePolling();
        m_pollTimer.start();
    } else {
        m_pollTimer.stop();
        if (protocol::dialectSupports(m_profile.dialect, Op::KeepAlive))
            m_keepAliveTimer.start();
    }
}

qint64 RotatorSession::nowMs() const
{
    if (m_link && m_link->clockIsStepped()) {
        if (const std::optional<double> seconds = m_link->clockSeconds())
            return qint64(*seconds * 1000.0);
    }
    return m_clock.elapsed();
}

// --- Connection -------------------------------------------------------------

void RotatorSession::setState(State s, const QString &detail)
{
    m_state = s;
    emit stateChanged(s, detail);
}

void RotatorSession::connectTo(const QString &uri)
{
    m_wantConnected = false;
    m_reconnectTimer.stop();
    dropLink();
    m_uri = uri;
    m_wantConnected = true;
    m_reconnectAttempt = 0;
    openLink();
}

void RotatorSession::disconnectFromRotator()
{
    const bool had = m_link != nullptr || m_state != State::Disconnected;
    m_wantConnected = false;
    m_reconnectTimer.stop();
    dropLink();
    if (had)
        setState(State::Disconnected, tr("disconnected"));
}

void RotatorSession::openLink()
{
    transport::LinkResult made = m_linkMaker ? m_linkMaker(m_uri) : transport::createLink(m_uri);
    if (made.link) {
        if (const QString problem = hintNamesProblem(made.link->hints()); !problem.isEmpty()) {
            made.error = tr("%1: %2").arg(m_uri, problem);
            made.link.reset();
        }
    }
    if (!made.link) {
        m_wantConnected = false;
        setState(State::Disconnected, made.error);
        emit errorOccurred(made.error);
        return;
    }
    m_link = std::move(made.link);
    for (LinkTimer *t : {&m_replyTimer, &m_pollTimer, &m_staleTimer, &m_stopHoldTimer, &m_keepAliveTimer, &m_heldBackReport})
        t->followClockOf(m_link.get());
    m_turnaround.followClockOf(m_link.get());
    connect(m_link.get(), &transport::Link::opened, this, &RotatorSession::onLinkOpened);
    connect(m_link.get(), &transport::Link::failed, this, &RotatorSession::onLinkDown);
    connect(m_link.get(), &transport::Link::lost, this, &RotatorSession::onLinkDown);
    connect(m_link->device(), &QIODevice::readyRead, this, &RotatorSession::onReadyRead);
    connect(m_link.get(), &transport::Link::notice, this, &RotatorSession::errorOccurred);
    connect(m_link.get(), &transport::Link::limitsReported, this,
            [this](double azMin, double azMax, double elMin, double elMax) {
                m_linkLimits = model::RotatorLimits{azMin, azMax, elMin, elMax};
                updateGateLimits();
            });
    setState(m_reconnectAttempt > 0 ? State::Reconnecting : State::Connecting, tr("opening %1").arg(m_uri));
    m_link->open();
}

void RotatorSession::onLinkOpened()
{
    m_parser.reset();
    m_frames.reset();
    m_checksum = m_link->hints().checksum;
    m_rotor = m_link->hints().rotor.value_or(0);
    m_activeTarget.reset();
    m_echoes.reset();
    m_refusals.reset();
    m_positionRetry = {};
    m_positionReadOnLink = false; // the last link's position is shown, stale, but vouches for nothing
    m_reconnectAttempt = 0;
    m_failedPolls = 0;
    m_pollCount = 0;
    m_textLinesSkipped = 0;
    m_unreadableReplies = 0;
    m_refusedRequests = 0;
    m_pace.restart(nowMs()); // a new link: full rate until the rotator is seen at rest
    updatePollPace(); // at the rate of this link's line
    forgetParkRegisters();
    setState(State::Connected, tr("connected to %1").arg(m_uri));
    startProbe();
    if (m_pollingEnabled)
        m_pollTimer.start();
    else if (protocol::dialectSupports(m_profile.dialect, Op::KeepAlive))
        m_keepAliveTimer.start();
}

void RotatorSession::onLinkDown(const QString &reason)
{
    // Whether it never opened or went away, the way on is the same: retry
    // when the operator asked for it, else stay disconnected with the reason.
    emit errorOccurred(reason);
    if (m_wantConnected && m_options.autoReconnect) {
        scheduleReconnect(reason);
        return;
    }
    m_wantConnected = false;
    dropLink(reason);
    setState(State::Disconnected, reason);
}

void RotatorSession::scheduleReconnect(const QString &reason)
{
    dropLink(reason);
    const int delay = std::min(kMaxReconnectDelayMs, 500 << std::min(m_reconnectAttempt, 6));
    ++m_reconnectAttempt;
    setState(State::Reconnecting, tr("%1; retrying in %2 s").arg(reason).arg(delay / 1000.0, 0, 'f', 1));
    m_reconnectTimer.start(delay);
}

void RotatorSession::dropLink(const QString &reason)
{
    m_pollTimer.stop();
    m_keepAliveTimer.stop();
    m_replyTimer.stop();
    m_staleTimer.stop();
    m_stopHoldTimer.stop();
    m_turnaround.clear();
    m_onWire = false;
    m_jogSpeed = {0.0, 0.0};
    // Whatever the rotator was doing, the session no longer knows: the next
    // target, even one repeated, must go out on the new link.
    m_activeTarget.reset();
    clearBadFrames();
    clearUnreadable();
    // What the allowance held back is said now: the timer would not run
    // without a link, and the count belongs to this connection.
    m_heldBackReport.stop();
    reportHeldBack();
    if (m_link) {
        m_link->disconnect(this);
        m_link->device()->disconnect(this);
        m_link->close();
        // Not deleted here: we may be inside one of its signals.
        m_link.release()->deleteLater();
    }
    // Nothing is dropped silently: every waiting request hears why.
    const QString why = reason.isEmpty() ? tr("link closed") : reason;
    m_queue.failAll(why);
    if (!m_stale && hasPosition()) {
        m_stale = true;
        emit positionChanged(m_az, m_el, true);
    }
    m_stale = true;
    m_caps = Capabilities{};
    m_linkLimits.reset();
    updateGateLimits();
    emit capabilitiesChanged(m_caps);
}

// --- Receiving --------------------------------------------------------------

void RotatorSession::onReadyRead()
{
    if (!m_link)
        return;
    const QByteArray bytes = m_link->device()->readAll();
    if (bytes.isEmpty())
        return;
    emit bytesReceived(bytes);
    m_turnaround.noteReceived(nowMs());
    if (m_checksum)
        m_frames.feed(bytes, [this](protocol::FrameCheck check, QByteArrayView line) { onFrame(check, line); });
    else
        m_parser.feed(bytes, [this](const Message &m) { apply(m); });
}

void RotatorSession::onFrame(protocol::FrameCheck check, QByteArrayView line)
{
    if (check == protocol::FrameCheck::Good) {
        clearBadFrames();
        m_parser.feed(line, [this](const Message &m) { apply(m); });
        return;
    }
    // Refused whole: a damaged `AZ10.0` may read as `AZ11.0`. A query left
    // unanswered times out and is retried as if the line had been lost.
    ++m_checksumFailures;
    ++m_badFramesInARow;
    if (m_badFramesInARow == 1) { // the first of a run; the alarm speaks for the rest
        reportFromController(ControllerLogAllowance::Kind::Damaged,
                             tr("refused a reply with %1: '%2'")
                                 .arg(QString::fromLatin1(protocol::describe(check)), quoted(line.trimmed())));
    }
    if (m_badFramesInARow == kBadFramesAlarm) {
        wakePolling();
        emit badFramesAlarm(true, tr("%1 replies in a row failed their checksum; last: %2")
                                      .arg(kBadFramesAlarm)
                                      .arg(QString::fromLatin1(protocol::describe(check))));
    }
}

void RotatorSession::reportFromController(ControllerLogAllowance::Kind kind, const QString &line)
{
    const QStringList lines = m_controllerLog.take(kind, nowMs(), line);
    for (const QString &l : lines)
        emit errorOccurred(l);
    if (m_controllerLog.holdsBack() && !m_heldBackReport.isActive())
        m_heldBackReport.start();
}

void RotatorSession::reportHeldBack()
{
    if (const QString summary = m_controllerLog.takeSummary(); !summary.isEmpty())
        emit errorOccurred(summary);
}

void RotatorSession::noteUnreadable(const QString &reason)
{
    ++m_unreadableReplies;
    const qint64 now = nowMs();
    if (m_unreadable.noteUnreadable(now)) {
        wakePolling();
        emit unreadableRepliesAlarm(true, tr("the controller's replies are unreadable: %1 in the last %2 s (last: %3)")
                                              .arg(m_unreadable.inWindow(now))
                                              .arg(UnreadableReplies::kWindowSeconds)
                                              .arg(reason));
    }
}

void RotatorSession::clearUnreadable()
{
    const bool raised = m_unreadable.raised();
    m_unreadable.reset();
    if (raised)
        emit unreadableRepliesAlarm(false, {});
}

void RotatorSession::clearBadFrames()
{
    const bool raised = m_badFramesInARow >= kBadFramesAlarm;
    m_badFramesInARow = 0;
    if (raised)
        emit badFramesAlarm(false, {});
}

void RotatorSession::apply(const Message &m)
{
    if (m_echoes.isEcho(m, nowMs()))
        return;
    if (m.op != Op::Invalid && m.op != Op::Alarm && m_unreadable.noteReadable(nowMs()))
        emit unreadableRepliesAlarm(false, {});
    switch (m.op) {
    case Op::Azimuth:
        m_az = m.value + azimuthOffset();
        m_azFresh = true;
        if (m.lineEnd || m_elFresh)
            applyPosition();
        break;
    case Op::Elevation:
        m_el = m.value + elevationOffset();
        m_elFresh = true;
        applyPosition();
        break;
    case Op::Status:
        if (!m_status.valid || m_status.raw != quint16(m.value)) {
            m_status = StatusWord{quint16(m.value), true};
            emit statusChanged(m_status);
        }
        if (m_status.anyMoving())
            wakePolling(); // moving, whoever moved it
        break;
    case Op::ErrorFlags:
        if (m_errorFlags != int(m.value)) {
            m_errorFlags = int(m.value);
            wakePolling();
            emit errorFlagsChanged(m_errorFlags);
        }
        break;
    case Op::ReadInput:
        if (m.hasValue)
            applyInput(m.index, m.value);
        break;
    case Op::ConfigRead:
    case Op::ConfigValue:
        applyConfig(m.index, QString::fromLatin1(m.text.view().toByteArray()), m.hasValue, m.value);
        break;
    case Op::Version:
        m_version = QString::fromLatin1(m.text.view().toByteArray());
        emit versionChanged(m_version);
        break;
    case Op::Encoders:
        emit encodersChanged(m.encoders[0], m.encoders[1], m.encoders[2], m.encoders[3]);
        break;
    case Op::Calibration:
    case Op::AdcReadings:
        if (!m_listingReader || !m_listingReader(m))
            return;
        break;
    case Op::Alarm: {
        const QString text = QString::fromLatin1(m.text.view().toByteArray());
        if (protocol::isSpid(m_profile.dialect)) {
            // A SPID controller has no alarms: a text line among its frames
            // is MD-01 firmware logging. Skipped, said once, and no reason
            // to fail the poll it came before.
            if (m_textLinesSkipped++ == 0)
                emit errorOccurred(tr("the controller writes text lines among its replies (first: '%1'); "
                                      "they are skipped").arg(quoted(m.text.view().trimmed())));
            return;
        }
        // The controller may have refused the target, or stopped: resend it.
        m_activeTarget.reset();
        wakePolling(); // whatever follows an alarm is watched closely
        emit alarmReceived(text);
        reportFromController(ControllerLogAllowance::Kind::Alarm,
                             tr("controller alarm: %1").arg(quoted(m.text.view())));
        if (m_onWire)
            finishFront(false, tr("the controller answered with alarm %1").arg(text));
        return;
    }
    case Op::Refused:
        applyRefusal(m);
        return;
    case Op::Invalid: {
        // Nothing in it is used; a poll it stood in for times out and is
        // retried. Readable replies around it are used as ever.
        const QString reason = QString::fromLatin1(m.reason);
        // A refused SPID frame carries no text, only the reason.
        reportFromController(ControllerLogAllowance::Kind::Unreadable,
                             m.text.isEmpty() ? tr("unreadable reply: %1").arg(reason)
                                              : tr("unreadable reply '%1': %2").arg(quoted(m.text.view()), reason));
        noteUnreadable(reason);
        return;
    }
    case Op::UplinkFreq:
    case Op::DownlinkFreq:
    case Op::UplinkMode:
    case Op::DownlinkMode:
        m_stationRadio->read(m);
        break;
    default:
        break;
    }
    if (m_onWire && m_queue.offer(m)) {
        const Request *front = m_queue.front();
        if (front && front->complete())
            finishFront(true, {});
    }
}

void RotatorSession::applyRefusal(const Message &m)
{
    const QString answer = quoted(m.text.view());
    const RefusalOwner::Answer owner = m_refusals.take(m_onWire, nowMs());
    switch (owner.owner) {
    case RefusalOwner::Owner::Command: {
        QString why = tr("the controller refused '%1' (it answered '%2')").arg(quoted(owner.line.trimmed()), answer);
        // A controller without PARK (K3NG's Easycom) still reaches the
        // park position by a go-to: say which, so the operator can.
        if (owner.line == protocol::encodeLine({Message::query(Op::Park)}, m_profile.dialect))
            why += tr("; a go-to to the profile's park position, az %1 el %2, goes there instead")
                       .arg(m_profile.parkAz + azimuthOffset(), 0, 'f', 1)
                       .arg(m_profile.parkEl + elevationOffset(), 0, 'f', 1);
        m_activeTarget.reset();
        emit targetCleared();
        emit controllerRefusedMove(why);
        emit moveRefused(why);
        emit errorOccurred(why);
        return;
    }
    case RefusalOwner::Owner::Request:
        ++m_refusedRequests;
        finishFront(false, tr("the controller refused it (it answered '%1')").arg(answer));
        return;
    case RefusalOwner::Owner::Nobody: {
        // Nothing of ours to refuse: as good as an unreadable reply.
        const QString reason = tr("a refusal with no command waiting for it");
        reportFromController(ControllerLogAllowance::Kind::Unreadable,
                             tr("unreadable reply '%1': %2").arg(answer, reason));
        noteUnreadable(reason);
        return;
    }
    }
}

void RotatorSession::applyPosition()
{
    if (!hasPosition())
        return;
    m_azFresh = m_elFresh = false;
    m_failedPolls = 0;
    m_positionReadOnLink = true;
    if (m_caps.probed && !m_caps.positionFeedback) {
        // Read at last (a controller that was still booting, a cable put back).
        m_caps.positionFeedback = true;
        m_positionRetry = {};
        emit capabilitiesChanged(m_caps);
    }
    m_stale = false;
    m_pace.notePosition(m_az, m_el, nowMs()); // motion wakes the pace
    retimePolling();
    if (m_state == State::Connected)
        m_staleTimer.start();
    emit positionChanged(m_az, m_el, false);
    checkSoftLimits();
    if (protocol::isSpid(m_profile.dialect) && !m_caps.moveCommands)
        continueJogLegs();
}

void RotatorSession::applyInput(int index, double value)
{
    switch (index) {
    case 0: m_telemetry.temperature = value; break;
    case 1: m_telemetry.azEndStop = int(value); break;
    case 2: m_telemetry.elEndStop = int(value); break;
    case 5: m_telemetry.azLoad = value; break;
    case 6: m_telemetry.elLoad = value; break;
    case 7: m_telemetry.azVelocity = value; break;
    case 8: m_telemetry.elVelocity = value; break;
    default: return; // IP3/IP4 repeat the position we already poll
    }
    m_telemetry.timeMs = QDateTime::currentMSecsSinceEpoch();
    emit telemetryChanged(m_telemetry);
}

void RotatorSession::applyConfig(int reg, const QString &text, bool numeric, double value)
{
    emit configValueReceived(reg, text);
    if (!numeric)
        return;
    noteParkRegister(reg, value);
    if (reg == 10)
        m_commandedAz = value + azimuthOffset();
    else if (reg == 11)
        m_commandedEl = value + elevationOffset();
    else
        return;
    emit commandedChanged(m_commandedAz, m_commandedEl);
}

void RotatorSession::onStale()
{
    if (!m_stale && hasPosition()) {
        m_stale = true;
        emit positionChanged(m_az, m_el, true);
    }
}

} // namespace slew::session
