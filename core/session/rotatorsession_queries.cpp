// SPDX-License-Identifier: GPL-3.0-or-later
// RotatorSession's queries: the request queue on the wire (one query at a
// time, timeouts and retries), the capability probe and polling.

#include "rotatorsession.h"

#include "transport/link.h"

#include <QIODevice>

#include <algorithm>

namespace slew::session {

using protocol::Message;
using protocol::Op;

namespace {
constexpr int kTelemetryGiveUpAfter = 3; // a query unanswered this often is not polled again
}

// --- Sending ----------------------------------------------------------------

CommandResult RotatorSession::refuse(const QString &reason)
{
    emit commandRefused(reason);
    return CommandResult{reason};
}

CommandResult RotatorSession::refuseMove(const QString &reason)
{
    emit moveRefused(reason);
    return refuse(reason);
}

CommandResult RotatorSession::queueRequest(Request request, SameLine same)
{
    if (auto linked = requireLink(); !linked)
        return linked;
    if (same == SameLine::Shared && m_queue.contains(request.line))
        return {}; // one is on its way: its answer serves this asker too
    if (m_queue.isFull())
        return refuse(tr("the controller is not keeping up: %1 requests already waiting").arg(m_queue.size()));
    wakePolling(); // whoever asks wants fresh answers
    enqueue(std::move(request));
    return {};
}

CommandResult RotatorSession::requireLink()
{
    if (m_state == State::Connected && m_link && m_link->isOpen())
        return {};
    return refuse(tr("not connected to a rotator"));
}

void RotatorSession::write(const QByteArray &line, LineKind kind)
{
    if (!m_link || line.isEmpty())
        return;
    // Requests keep their plain line (the queue compares them); the frame
    // is added on the way out.
    const QByteArray framed = m_checksum ? protocol::withChecksums(line) : line;
    if (!m_turnaround.hold(framed, kind == LineKind::Request, nowMs()))
        writeNow(framed);
}

void RotatorSession::writeNow(const QByteArray &bytes)
{
    if (!m_link || !m_link->isOpen())
        return;
    m_link->device()->write(bytes);
    emit bytesSent(bytes);
}

bool RotatorSession::enqueue(Request r)
{
    if (m_queue.isFull()) {
        const QString reason = tr("the controller is not keeping up: %1 requests already waiting").arg(m_queue.size());
        if (r.done)
            r.done(false, reason);
        return false;
    }
    m_queue.push(std::move(r));
    sendNext();
    return true;
}

void RotatorSession::sendNext()
{
    if (m_onWire || !m_link || !m_link->isOpen())
        return;
    Request *front = m_queue.front();
    if (!front)
        return;
    front->satisfied = 0;
    m_onWire = true;
    m_link->setAwaitingReply(true); // a shared line holds the wire for the answer
    write(front->line, LineKind::Request);
    m_refusals.noteRequestWritten();
    m_replyTimer.start(m_replyTimeoutMs);
}

void RotatorSession::onReplyTimeout()
{
    Request *front = m_queue.front();
    if (!front || !m_onWire)
        return;
    m_turnaround.replyEnded(nowMs()); // none came
    if (--front->attemptsLeft > 0) {
        m_onWire = false;
        sendNext();
        return;
    }
    finishFront(false, tr("no answer within %1 ms").arg(m_replyTimeoutMs));
}

void RotatorSession::finishFront(bool ok, const QString &reason)
{
    m_replyTimer.stop();
    m_onWire = false;
    m_turnaround.replyEnded(nowMs());
    if (m_link)
        m_link->setAwaitingReply(false);
    if (m_queue.isEmpty())
        return;
    Request r = m_queue.takeFront();
    if (ok)
        m_refusals.noteRequestAnswered();
    if (!ok && (r.purpose == RequestPurpose::Position || r.purpose == RequestPurpose::KeepAlive))
        ++m_failedPolls;
    if (r.done)
        r.done(ok, reason);
    sendNext();
}

// --- Probe and polling ------------------------------------------------------

void RotatorSession::startProbe()
{
    m_caps = Capabilities{};
    m_caps.velocity = m_codec->supports(Op::VelocityLeft);
    m_caps.moveCommands = m_codec->supports(Op::MoveLeft);
    m_caps.park = m_codec->supports(Op::Park);
    m_caps.reset = m_codec->supports(Op::Reset);
    m_caps.stop = m_codec->supports(Op::StopAzimuth);
    m_telemetryFailures.clear();

    struct Probe {
        Op op;
        int index;
        bool Capabilities::*flag;
    };
    const Probe probes[] = {
        {Op::Azimuth, -1, &Capabilities::positionFeedback}, {Op::Version, -1, &Capabilities::version},
        {Op::Status, -1, &Capabilities::status},            {Op::ErrorFlags, -1, &Capabilities::errors},
        {Op::ReadInput, 0, &Capabilities::inputs},          {Op::ConfigRead, 1, &Capabilities::config},
        {Op::Encoders, -1, &Capabilities::encoders},
    };
    m_probesOutstanding = 0;
    QList<Request> requests;
    for (const Probe &p : probes) {
        if (!m_codec->supports(p.op))
            continue;
        Request r;
        r.purpose = RequestPurpose::Probe;
        if (p.op == Op::Azimuth) {
            r.line = m_codec->queryPosition();
            r.expects = {Expectation{Op::Azimuth, -1}, Expectation{Op::Elevation, -1}};
            r.expectCount = 2;
            r.attemptsLeft = m_options.retries + 1;
        } else {
            r.line = m_codec->line({Message::query(p.op, p.index)});
            r.expects[0] = Expectation{p.op, p.index};
            r.expectCount = 1;
            r.attemptsLeft = 1; // a controller that lacks a command stays silent
        }
        r.done = [this, flag = p.flag](bool ok, const QString &) {
            m_caps.*flag = ok;
            // The park registers are part of the probe: a client that waits
            // for it to end (slewctl park) then parks where they say.
            if (flag == &Capabilities::config && ok)
                readParkRegistersInProbe();
            probeAnswered();
        };
        requests.append(std::move(r));
    }
    m_probesOutstanding = int(requests.size());
    if (requests.isEmpty()) {
        m_caps.probed = true; // Easycomm I: nothing to ask
        emit capabilitiesChanged(m_caps);
        return;
    }
    for (Request &r : requests)
        enqueue(std::move(r));
}

void RotatorSession::probeAnswered()
{
    if (--m_probesOutstanding > 0)
        return;
    m_caps.probed = true;
    emit capabilitiesChanged(m_caps);
    poll();
}

void RotatorSession::poll()
{
    if (m_state != State::Connected || !m_link || !m_link->isOpen() || !m_pollingEnabled || !m_caps.probed)
        return;
    // A velocity move runs until told otherwise, and only the polls see it
    // reach the profile's limits: never the slow rate while one runs.
    if (m_jogSpeed[0] != 0.0 || m_jogSpeed[1] != 0.0)
        m_pace.wake(nowMs());
    retimePolling();
    // A controller whose position did not read at connect is asked again,
    // less and less often, and each failure is said: a wrong dialect, a
    // controller still booting, a cable that comes loose all show there.
    const QByteArray positionLine = m_codec->queryPosition();
    const bool askPosition = !positionLine.isEmpty()
        && (m_caps.positionFeedback || nowMs() >= m_positionRetry.dueMs);
    if (askPosition && !m_queue.contains(positionLine)) {
        Request r;
        r.line = positionLine;
        r.expects = {Expectation{Op::Azimuth, -1}, Expectation{Op::Elevation, -1}};
        r.expectCount = 2;
        r.attemptsLeft = m_options.retries + 1;
        r.purpose = RequestPurpose::Position;
        if (!m_caps.positionFeedback) {
            r.done = [this](bool ok, const QString &reason) {
                if (ok || m_caps.positionFeedback)
                    return;
                const int delayMs = m_positionRetry.delayMs;
                m_positionRetry.dueMs = nowMs() + delayMs;
                m_positionRetry.delayMs = std::min(2 * delayMs, PositionRetry::kLongestMs);
                emit errorOccurred(tr("still no position read from the controller (%1); asking again in %2 s")
                                       .arg(reason)
                                       .arg(delayMs / 1000));
            };
        }
        enqueue(std::move(r));
    }
    if (m_pollCount++ % telemetryEveryPolls() != 0)
        return;

    auto ask = [&](Op op, int index) {
        const QByteArray line = m_codec->line({Message::query(op, index)});
        if (line.isEmpty() || m_queue.contains(line) || m_telemetryFailures.value(line) >= kTelemetryGiveUpAfter)
            return;
        Request r;
        r.line = line;
        r.expects[0] = Expectation{op, index};
        r.expectCount = 1;
        r.attemptsLeft = 1;
        r.purpose = RequestPurpose::Telemetry;
        r.done = [this, line](bool ok, const QString &) {
            if (ok)
                m_telemetryFailures.remove(line);
            else
                ++m_telemetryFailures[line];
        };
        enqueue(std::move(r));
    };
    if (m_caps.status)
        ask(Op::Status, -1);
    if (m_caps.errors)
        ask(Op::ErrorFlags, -1);
    if (m_caps.inputs) {
        for (int input : {0, 1, 2, 5, 6, 7, 8})
            ask(Op::ReadInput, input);
    }
    if (m_caps.config && firmwareTraits().commandedRegisters) {
        ask(Op::ConfigRead, 10);
        ask(Op::ConfigRead, 11);
    }
}

int RotatorSession::telemetryEveryPolls() const
{
    // A firmware that a busy line starves asks for its telemetry (status,
    // errors, inputs: nine lines) less often than the options say.
    const int intervalMs = std::max(1, m_pace.intervalMs(nowMs()));
    const int firmwareEvery = (firmwareTraits().telemetryEveryMs + intervalMs - 1) / intervalMs;
    return std::max({1, m_options.telemetryEvery, firmwareEvery});
}

void RotatorSession::keepAlive()
{
    // Polling already proves the link alive; the keep-alive only fills in
    // while it is paused.
    if (m_pollingEnabled || m_state != State::Connected || !m_link || !m_link->isOpen() || !m_caps.probed)
        return;
    const QByteArray line = m_codec->line({Message::query(Op::KeepAlive)});
    if (line.isEmpty() || m_queue.contains(line))
        return;
    Request r;
    r.line = line;
    r.expects[0] = Expectation{Op::KeepAlive, -1};
    r.expectCount = 1;
    r.attemptsLeft = m_options.retries + 1;
    r.purpose = RequestPurpose::KeepAlive;
    r.done = [this](bool ok, const QString &reason) {
        if (ok)
            return;
        // As with an unanswered poll: nothing vouches for the position now.
        onStale();
        emit errorOccurred(tr("no answer to the keep-alive: %1").arg(reason));
    };
    enqueue(std::move(r));
}

void RotatorSession::checkSoftLimits()
{
    // A velocity move runs until told otherwise; the profile's limits may be
    // tighter than the controller's own, so stop the axis at them.
    const model::RotatorLimits lim = m_gate.limits();
    if ((m_jogSpeed[0] > 0 && m_az >= lim.azMax) || (m_jogSpeed[0] < 0 && m_az <= lim.azMin)) {
        const QString why = tr("azimuth reached the profile limit at %1°").arg(m_az, 0, 'f', 1);
        stop(why, Axes::Azimuth);
        emit errorOccurred(tr("%1; stopped").arg(why));
    }
    if ((m_jogSpeed[1] > 0 && m_el >= lim.elMax) || (m_jogSpeed[1] < 0 && m_el <= lim.elMin)) {
        const QString why = tr("elevation reached the profile limit at %1°").arg(m_el, 0, 'f', 1);
        stop(why, Axes::Elevation);
        emit errorOccurred(tr("%1; stopped").arg(why));
    }
}

} // namespace slew::session
