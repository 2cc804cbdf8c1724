// SPDX-License-Identifier: GPL-3.0-or-later
// RotatorSession's replies: what comes back on the link, read by the codec
// into messages and applied (position, status, alarms, registers, the
// radio commands' readings), the controller's refusals, and replies that do
// not read.

#include "rotatorsession.h"

#include "controllerradiocommands.h"
#include "micro2gcalibration.h"

#include "input/logtext.h"
#include "transport/link.h"

#include <QDateTime>
#include <QIODevice>

#include <algorithm>
#include <cmath>

namespace slew::session {

using protocol::Message;
using protocol::Op;

namespace {

// How much of a controller's bad line a log line quotes (escaped).
constexpr int kQuotedChars = 60;

QString quoted(QByteArrayView bytes)
{
    return input::loggableText(QString::fromLatin1(bytes.first(std::min<qsizetype>(bytes.size(), 4 * kQuotedChars))),
                               kQuotedChars);
}

} // namespace

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
        m_codec->feed(bytes, [this](const Message &m) { apply(m); });
}

void RotatorSession::onFrame(protocol::FrameCheck check, QByteArrayView line)
{
    if (check == protocol::FrameCheck::Good) {
        clearBadFrames();
        m_codec->feed(line, [this](const Message &m) { apply(m); });
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
        if (!m_codec->readsTextLines()) {
            // A controller of binary frames has no alarms: a text line among
            // its frames is firmware logging (the MD-01's). Skipped, said once, and no reason
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
        m_radioCommands->read(m);
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
        if (owner.line == m_codec->line({Message::query(Op::Park)}))
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
    checkMotion();
    checkSoftLimits();
    // A jog by set-position legs: the next leg before this one runs out.
    if (!m_codec->jogsItself()) {
        if (const std::optional<int> axis = m_jogLegs.wantsNext(m_jogSpeed, jogWhere()))
            jogBySetPosition(*axis == 0 ? Axis::Azimuth : Axis::Elevation, m_jogSpeed[size_t(*axis)]);
    }
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
