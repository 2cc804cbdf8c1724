// SPDX-License-Identifier: GPL-3.0-or-later
// RotatorSession: made, given its profile and options, and its link (open,
// lose, reconnect). The rest of it, a file a job: rotatorsession_replies.cpp
// (what comes back), rotatorsession_queries.cpp (the queue on the wire, the
// probe, polling), rotatorsession_moves.cpp (go-to, jog, stop, park),
// rotatorsession_registers.cpp (config and park registers) and
// rotatorsession_rawlines.cpp (the operator's raw lines).

#include "rotatorsession.h"

#include "connectionplan.h"
#include "controllerradiocommands.h"
#include "micro2gcalibration.h"

#include "input/logtext.h"
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

} // namespace

RotatorSession::RotatorSession(QObject *parent)
    : QObject(parent), m_codec(protocol::Codec::forDialect(m_profile.dialect)), m_queue(m_options.maxQueue)
{
    qRegisterMetaType<Telemetry>();
    qRegisterMetaType<Capabilities>();
    qRegisterMetaType<StatusWord>();
    m_clock.start();
    ControllerChannel *channel = this; // the helpers' narrow face of the session
    m_micro2g = std::make_unique<Micro2gCalibration>(channel);
    m_radioCommands = std::make_unique<ControllerRadioCommands>(channel);

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
    if (!m_codec->speaks(profile.dialect)) // a codec keeps what the replies taught it (SPID's resolution)
        m_codec = protocol::Codec::forDialect(profile.dialect, m_rotor);
    updateGateLimits(); // an azimuth-only dialect's (the codec's) has no elevation
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
        const int bytes = int(m_codec->queryPosition().size())
                          + m_codec->positionReplyBytes();
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
        if (m_codec->supports(Op::KeepAlive))
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
    m_codec->resetReading();
    m_frames.reset();
    m_checksum = m_link->hints().checksum;
    m_rotor = m_link->hints().rotor.value_or(0);
    m_codec->setRotor(m_rotor);
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
    else if (m_codec->supports(Op::KeepAlive))
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
    // target, even one repeated, must go out on the new link. Nothing is
    // driven any more; a held axis stays held until the operator clears it.
    m_activeTarget.reset();
    for (AxisMotionGuard &g : m_guards)
        g.release();
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

} // namespace slew::session
