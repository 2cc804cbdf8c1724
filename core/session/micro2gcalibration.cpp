// SPDX-License-Identifier: GPL-3.0-or-later
#include "micro2gcalibration.h"

#include "controllerchannel.h"

#include "protocol/operations.h"

namespace slew::session {

using protocol::Message;
using protocol::Op;

namespace {

QString printable(const QByteArray &line)
{
    return QString::fromLatin1(line).trimmed().replace(u'\r', u' ');
}

} // namespace

Micro2gCalibration::Micro2gCalibration(ControllerChannel *channel) : m_channel(channel)
{
    channel->setListingReader([this](const Message &m) { return read(m); });
}

bool Micro2gCalibration::read(const Message &m)
{
    const QByteArrayView text = m.text.view();
    if (m.op == Op::AdcReadings) {
        const QList<protocol::Micro2gAdcReading> readings = protocol::readMicro2gAdcReadings(text);
        for (const protocol::Micro2gAdcReading &r : readings)
            emit adcReadingReceived(r.rotor, r.counts);
        return !readings.isEmpty();
    }
    // `ZnL mmm` read back is a command (a controller echoing what it heard),
    // not the answer to Z: it must not complete a request.
    const std::optional<protocol::Micro2gCalibration> c = protocol::readMicro2gCalibration(text);
    if (!c)
        return false;
    emit calibrationReceived(c->rotor, *c);
    return true;
}

CommandResult Micro2gCalibration::refuseUnlessSupported(Op op, const QString &what)
{
    if (m_channel->codec().supports(op))
        return {};
    return m_channel->refuse(tr("%1 has no %2").arg(m_channel->codec().name(), what));
}

CommandResult Micro2gCalibration::refuseUnlessCalibratable(int rotor, const QString &what)
{
    if (auto linked = m_channel->requireLink(); !linked)
        return linked;
    if (auto supported = refuseUnlessSupported(Op::Calibration, what); !supported)
        return supported;
    if (rotor < 1 || rotor > kRotors)
        return m_channel->refuse(tr("rotors are 1 to %1, not %2").arg(kRotors).arg(rotor));
    return {};
}

CommandResult Micro2gCalibration::request(int rotor)
{
    if (auto usable = refuseUnlessCalibratable(rotor, tr("calibration listing")); !usable)
        return usable;
    return queueCalibration(m_channel->codec().line({Message::query(Op::Calibration)}), rotor);
}

CommandResult Micro2gCalibration::set(int rotor, Point point, int value)
{
    if (auto usable = refuseUnlessCalibratable(rotor, tr("calibration command")); !usable)
        return usable;
    const bool range = point == Point::DegreeRange;
    if (range && (value < 90 || value > 540))
        return m_channel->refuse(tr("a degree range is 90 to 540, not %1").arg(value));
    if (!range && (value < 0 || value > 359))
        return m_channel->refuse(tr("a bearing is 0 to 359, not %1").arg(value));
    const char which = range ? 'D' : point == Point::LeftStop ? 'L' : 'R';
    const QByteArray argument = which + QByteArray(" ") + QByteArray::number(value).rightJustified(3, '0');
    const QByteArray line =
        m_channel->codec().line({Message::word(Op::Calibration, argument, rotor), Message::query(Op::Calibration)});
    const CommandResult queued = queueCalibration(line, rotor);
    // The controller drops its target when the scale under it changes.
    if (queued)
        m_channel->forgetActiveTarget();
    return queued;
}

CommandResult Micro2gCalibration::requestAdcReadings()
{
    if (auto linked = m_channel->requireLink(); !linked)
        return linked;
    if (auto supported = refuseUnlessSupported(Op::AdcReadings, tr("A/D listing")); !supported)
        return supported;
    const QByteArray line = m_channel->codec().line({Message::query(Op::AdcReadings)});
    Request r;
    r.line = line;
    r.expects[0] = Expectation{Op::AdcReadings, -1};
    r.expectCount = 1;
    r.attemptsLeft = m_channel->retries() + 1;
    r.purpose = RequestPurpose::User;
    r.done = [channel = m_channel, text = printable(line)](bool ok, const QString &reason) {
        if (!ok)
            channel->reportRequestFailed(text, reason); // as the session's own queries say it
    };
    // One on its way already: its answer serves this asker too. A
    // calibration page reads with every poll while the operator turns the rotor.
    return m_channel->queueRequest(std::move(r), ControllerChannel::SameLine::Shared);
}

CommandResult Micro2gCalibration::queueCalibration(const QByteArray &line, int rotor)
{
    Request r;
    r.line = line;
    // The answer is a line per rotor, 1 to 4 (docs/protocol.md): the request
    // ends with the last, so that on a line shared by the rotors' sessions
    // (transport/sharedline.h) none of it reaches another rotor's.
    r.expects[0] = Expectation{Op::Calibration, kRotors};
    r.expectCount = 1;
    // Sent once: a setting repeated after a lost answer would record the
    // reading of that later moment, not the one the operator saw.
    r.attemptsLeft = 1;
    r.purpose = RequestPurpose::User;
    r.done = [this, rotor](bool ok, const QString &reason) {
        if (!ok)
            emit calibrationFailed(rotor, reason);
    };
    return m_channel->queueRequest(std::move(r), ControllerChannel::SameLine::Queued);
}

} // namespace slew::session
