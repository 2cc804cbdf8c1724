// SPDX-License-Identifier: GPL-3.0-or-later
// RotatorSession, part four: the Micro-2g program's calibration listings
// (docs/protocol.md, "Micro-2g"). The setup wizard's calibration page asks
// for the A/D readings while the operator turns the rotor to its stops, sets
// each stop and the degree range, and reads back what the controller holds.

#include "rotatorsession.h"

#include "protocol/encoder.h"
#include "protocol/operations.h"

namespace slew::session {

using protocol::Message;
using protocol::Op;

namespace {

constexpr int kRotors = 4;

QString printable(const QByteArray &line)
{
    return QString::fromLatin1(line).trimmed().replace(u'\r', u' ');
}

} // namespace

bool RotatorSession::applyMicro2gListing(const Message &m)
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

CommandResult RotatorSession::requestCalibration(int rotor)
{
    if (auto linked = requireLink(); !linked)
        return linked;
    if (!protocol::dialectSupports(m_profile.dialect, Op::Calibration))
        return refuse(tr("%1 has no calibration listing").arg(protocol::dialectName(m_profile.dialect)));
    if (rotor < 1 || rotor > kRotors)
        return refuse(tr("rotors are 1 to %1, not %2").arg(kRotors).arg(rotor));
    return enqueueCalibration(protocol::encodeLine({Message::query(Op::Calibration)}, m_profile.dialect), rotor);
}

CommandResult RotatorSession::setCalibration(int rotor, CalibrationPoint point, int value)
{
    if (auto linked = requireLink(); !linked)
        return linked;
    const protocol::Dialect d = m_profile.dialect;
    if (!protocol::dialectSupports(d, Op::Calibration))
        return refuse(tr("%1 has no calibration command").arg(protocol::dialectName(d)));
    if (rotor < 1 || rotor > kRotors)
        return refuse(tr("rotors are 1 to %1, not %2").arg(kRotors).arg(rotor));
    const bool range = point == CalibrationPoint::DegreeRange;
    if (range && (value < 90 || value > 540))
        return refuse(tr("a degree range is 90 to 540, not %1").arg(value));
    if (!range && (value < 0 || value > 359))
        return refuse(tr("a bearing is 0 to 359, not %1").arg(value));
    const char which = range ? 'D' : point == CalibrationPoint::LeftStop ? 'L' : 'R';
    const QByteArray argument = which + QByteArray(" ") + QByteArray::number(value).rightJustified(3, '0');
    const QByteArray line = protocol::encodeLine(
        {Message::word(Op::Calibration, argument, rotor), Message::query(Op::Calibration)}, d);
    const CommandResult queued = enqueueCalibration(line, rotor);
    // The controller drops its target when the scale under it changes.
    if (queued)
        m_activeTarget.reset();
    return queued;
}

CommandResult RotatorSession::requestAdcReadings()
{
    if (auto linked = requireLink(); !linked)
        return linked;
    if (!protocol::dialectSupports(m_profile.dialect, Op::AdcReadings))
        return refuse(tr("%1 has no A/D listing").arg(protocol::dialectName(m_profile.dialect)));
    const QByteArray line = protocol::encodeLine({Message::query(Op::AdcReadings)}, m_profile.dialect);
    if (m_queue.contains(line))
        return {}; // one is on its way: its answer serves this asker too
    Request r;
    r.line = line;
    r.expects[0] = Expectation{Op::AdcReadings, -1};
    r.expectCount = 1;
    r.attemptsLeft = m_options.retries + 1;
    r.purpose = RequestPurpose::User;
    r.done = [this, text = printable(line)](bool ok, const QString &reason) {
        if (!ok)
            emit requestFailed(text, reason);
    };
    if (m_queue.isFull())
        return refuse(tr("the controller is not keeping up: %1 requests already waiting").arg(m_queue.size()));
    wakePolling(); // a calibration page reads with every poll while the operator turns the rotor
    enqueue(std::move(r));
    return {};
}

CommandResult RotatorSession::enqueueCalibration(const QByteArray &line, int rotor)
{
    if (m_queue.isFull())
        return refuse(tr("the controller is not keeping up: %1 requests already waiting").arg(m_queue.size()));
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
    wakePolling();
    enqueue(std::move(r));
    return {};
}

} // namespace slew::session
