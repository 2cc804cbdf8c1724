// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulatorfirmware.h"

#include "protocol/encoder.h"

#include <QDateTime>

#include <charconv>
#include <cmath>
#include <utility>

namespace slew::sim {

using protocol::Dialect;
using protocol::Message;
using protocol::Op;
using protocol::formatNumber;

namespace {

// An input line that never ends (`AZ AZ AZ ...`) must not grow the answer
// without bound: past this size the answers leave as a line of their own.
constexpr qsizetype kMaxLineAnswers = 1024;
constexpr qsizetype kMaxAlarmText = 32;
constexpr int kMaxAlarmsPerChunk = 8;

QByteArray printable(QByteArrayView raw)
{
    QByteArray text;
    for (char c : raw.first(std::min(raw.size(), kMaxAlarmText))) {
        const auto u = static_cast<unsigned char>(c);
        text += (u > 0x20 && u < 0x7f) ? c : '?';
    }
    return text.isEmpty() ? QByteArray("?") : text;
}

} // namespace

SimulatorFirmware::SimulatorFirmware(SimulatedRotator &rotator, FirmwareCounters &counters, Dialect dialect)
    : m_rotator(rotator), m_counters(counters), m_dialect(dialect), m_parser(dialect)
{
    if (protocol::isSpid(dialect))
        configureSpid({});
}

void SimulatorFirmware::configureSpid(const SpidSettings &settings)
{
    if (protocol::isSpid(m_dialect))
        m_spid.emplace(m_rotator, m_counters, m_dialect, settings);
}

QByteArray SimulatorFirmware::version() const
{
    // SatNOGS clients look for their firmware's name at the front.
    if (m_dialect == Dialect::SatNogs)
        return "SatNOGS-v2.2-" + m_rotator.version();
    return m_rotator.version();
}

bool SimulatorFirmware::sendsAlarms() const
{
    return m_dialect == Dialect::Easycomm2 || m_dialect == Dialect::Easycomm3;
}

QByteArray SimulatorFirmware::receiveMicro2g(QByteArrayView bytes)
{
    // The program reads a line up to CR or LF; one longer than any command
    // is dropped whole, as the Easycomm reader does.
    constexpr qsizetype kLongestLine = protocol::InlineText::Capacity;
    QByteArray out;
    for (char c : bytes) {
        if (c != '\r' && c != '\n') {
            if (m_micro2gLine.size() < kLongestLine)
                m_micro2gLine += c;
            else
                m_micro2gOverlong = true;
            continue;
        }
        const QByteArray line = std::exchange(m_micro2gLine, {});
        if (std::exchange(m_micro2gOverlong, false)) {
            ++m_counters.overlong;
            out += "?> line too long\r\n";
            continue;
        }
        if (line.trimmed().isEmpty())
            continue; // the LF of a CR LF
        ++m_counters.lines;
        const QStringList replies = m_micro2g(QString::fromLatin1(line));
        bool refused = false;
        for (const QString &reply : replies) {
            refused = refused || reply.startsWith(QLatin1String("?>"));
            out += reply.toLatin1() + "\r\n";
        }
        if (refused)
            ++m_counters.malformed;
        else
            ++m_counters.commands;
    }
    return out;
}

QByteArray SimulatorFirmware::receive(QByteArrayView bytes)
{
    if (m_spid)
        return m_spid->receive(bytes);
    if (m_micro2g)
        return receiveMicro2g(bytes);
    QByteArray out;
    m_alarmsThisChunk = 0;
    m_suppressedAlarms = 0;
    m_parser.feed(bytes, [&](const Message &m) {
        handle(m, out);
        if (m.lineEnd)
            finishLine(out);
    });
    if (!bytes.isEmpty()) {
        const char last = bytes.back();
        m_awaitingLineEnd = last == ' ' || last == '\t' || last == ';';
    }
    if (m_suppressedAlarms > 0)
        out += "ALsuppressed:" + QByteArray::number(m_suppressedAlarms) + '\n';
    return out;
}

QByteArray SimulatorFirmware::endLine()
{
    if (m_spid)
        return {};
    if (m_micro2g)
        return receiveMicro2g("\r"); // a line the host never ended
    QByteArray out;
    m_awaitingLineEnd = false;
    m_parser.flush([&](const Message &m) { handle(m, out); });
    finishLine(out);
    return out;
}

void SimulatorFirmware::finishLine(QByteArray &out)
{
    ++m_counters.lines;
    if (m_lineAnswers.isEmpty())
        return;
    out += m_lineAnswers;
    out += protocol::isGs232(m_dialect) ? "\r\n" : "\n"; // Yaesu ends its answers with CR LF
    m_lineAnswers.clear();
}

void SimulatorFirmware::answer(const QByteArray &token)
{
    if (!answersAtAll() || token.isEmpty())
        return;
    if (!m_lineAnswers.isEmpty())
        m_lineAnswers += reportSeparator();
    m_lineAnswers += token;
}

void SimulatorFirmware::alarm(const char *kind, QByteArrayView what, QByteArray &out)
{
    if (protocol::isGs232(m_dialect)) {
        // A Yaesu controller's whole vocabulary for "no": its prompt (K3NG's too).
        if (++m_alarmsThisChunk <= kMaxAlarmsPerChunk)
            out += "?>\r\n";
        return;
    }
    if (!sendsAlarms())
        return;
    // A barrage of garbage must not turn into a barrage of alarms that
    // fills the line (and buries the answer to the next good query).
    if (++m_alarmsThisChunk > kMaxAlarmsPerChunk) {
        ++m_suppressedAlarms;
        return;
    }
    out += "AL";
    out += kind;
    out += ':';
    out += printable(what);
    out += '\n';
}

void SimulatorFirmware::refuse(const Message &m, QByteArray &out)
{
    ++m_counters.outOfLimits;
    QByteArray token = protocol::encodeToken(m, Dialect::Easycomm3);
    if (token.isEmpty())
        token = protocol::mnemonic(m.op).toByteArray();
    // The alarm names the value refused: `AZ-0.004` is not to read as
    // `AZ0.00`, which would have been accepted.
    const bool angle = m.op == Op::Azimuth || m.op == Op::Elevation;
    if (angle && m.hasValue && std::isfinite(m.value) && std::round(m.value * 100) / 100 != m.value) {
        char digits[32];
        const auto end = std::to_chars(digits, digits + sizeof digits, m.value).ptr;
        token = protocol::mnemonic(m.op).toByteArray() + QByteArray(digits, end - digits);
    }
    alarm("limit", token, out);
}

QByteArray SimulatorFirmware::angle(Op op, double degrees) const
{
    return protocol::encodeReport(Message::number(op, degrees), m_dialect);
}

QByteArray SimulatorFirmware::inputReply(int index, double value) const
{
    // Switches and loads are whole numbers; the rest carry two decimals.
    const bool whole = index == 1 || index == 2 || index == 5 || index == 6;
    return "IP" + QByteArray::number(index) + ',' + formatNumber(value, whole ? 0 : 2);
}

QByteArray SimulatorFirmware::registerReply(int index, double value) const
{
    const QByteArray text = QByteArray::number(index) + ',' + formatNumber(value, index <= 6 ? 3 : 2);
    // SatNOGS answers `CR 1` with `1,value`, no prefix.
    return m_dialect == Dialect::SatNogs ? text : "CR" + text;
}

QByteArray SimulatorFirmware::velocityReply(Op op) const
{
    const double az = m_rotator.readRegister(12).value_or(0.0);
    const double el = m_rotator.readRegister(13).value_or(0.0);
    double v = 0.0;
    switch (op) {
    case Op::VelocityLeft: v = -az; break;
    case Op::VelocityRight: v = az; break;
    case Op::VelocityUp: v = el; break;
    case Op::VelocityDown: v = -el; break;
    default: break;
    }
    return protocol::encodeToken(Message::number(op, std::max(0.0, v)), m_dialect);
}

void SimulatorFirmware::manualMove(Op op)
{
    // At the share of the manual speed GS-232's X1..X4 chose: all of it
    // unless told otherwise, as on every Easycomm board.
    const double az = 1000.0 * m_manualSpeedShare * m_rotator.axis(Axis::Azimuth).plant().manualSpeed;
    const double el = 1000.0 * m_manualSpeedShare * m_rotator.axis(Axis::Elevation).plant().manualSpeed;
    switch (op) {
    case Op::MoveLeft: m_rotator.driveAzimuth(-az); break;
    case Op::MoveRight: m_rotator.driveAzimuth(az); break;
    case Op::MoveUp: m_rotator.driveElevation(el); break;
    case Op::MoveDown: m_rotator.driveElevation(-el); break;
    case Op::StopAzimuth: stopAxis(Axis::Azimuth); break;
    case Op::StopElevation: stopAxis(Axis::Elevation); break;
    default: break;
    }
}

void SimulatorFirmware::handle(const Message &m, QByteArray &out)
{
    if (speaksK3ngEasycom())
        return handleK3ngEasycom(m, out);
    if (!m.isValid()) {
        if (m.refusal == protocol::Refusal::Overlong) {
            ++m_counters.overlong;
            alarm("overlong", m.text.view(), out);
        } else if (m.refusal == protocol::Refusal::Unknown) {
            ++m_counters.unknown;
            alarm("unknown", m.text.view(), out);
        } else {
            ++m_counters.malformed;
            alarm("malformed", m.text.view(), out);
        }
        return;
    }
    if (!protocol::dialectSupports(m_dialect, m.op)) {
        ++m_counters.unknown;
        alarm("unknown", protocol::mnemonic(m.op), out);
        return;
    }

    // Replies a device sends (GS5, IP1,1, \?ENC1,2,3,4) are not commands.
    auto readOnly = [&] {
        ++m_counters.malformed;
        QByteArray token = protocol::encodeToken(m, Dialect::Easycomm3);
        alarm("malformed", token.isEmpty() ? protocol::mnemonic(m.op) : QByteArrayView(token), out);
    };
    const double az = m_rotator.axis(Axis::Azimuth).position();
    const double el = m_rotator.axis(Axis::Elevation).position();

    switch (m.op) {
    case Op::Azimuth:
        if (!m.hasValue)
            answer(angle(m.op, az));
        else if (!pointAzimuth(m.value))
            return refuse(m, out);
        break;
    case Op::Elevation:
        if (!m.hasValue)
            answer(angle(m.op, el));
        else if (!m_rotator.pointElevation(m.value))
            return refuse(m, out);
        break;
    case Op::VelocityLeft:
    case Op::VelocityRight:
    case Op::VelocityUp:
    case Op::VelocityDown:
        if (!m.hasValue) {
            answer(velocityReply(m.op));
        } else if (m.op == Op::VelocityLeft || m.op == Op::VelocityRight) {
            m_rotator.driveAzimuth(m.op == Op::VelocityLeft ? -m.value : m.value);
        } else {
            m_rotator.driveElevation(m.op == Op::VelocityDown ? -m.value : m.value);
        }
        break;
    case Op::MoveLeft:
    case Op::MoveRight:
    case Op::MoveUp:
    case Op::MoveDown:
    case Op::StopAzimuth:
    case Op::StopElevation: manualMove(m.op); break;
    case Op::Reset: m_rotator.reset(); break;
    case Op::Park: m_rotator.park(); break;
    case Op::Aos:
    case Op::Los:
        break; // pass markers: nothing for a rotator to do
    case Op::KeepAlive:
        if (!m.text.isEmpty())
            return readOnly(); // `OK` is the controller's word, not a command
        answer("OK");
        break;
    case Op::Offset:
        // GS-232's relative move: from where the axis is now.
        if (m.index == 0 ? !m_rotator.pointAzimuth(az + m.value) : !m_rotator.pointElevation(el + m.value))
            return refuse(m, out);
        break;
    case Op::Speed:
        m_manualSpeedShare = std::clamp(m.value, 1.0, 4.0) / 4.0;
        break;
    case Op::ReadInput:
        if (m.hasValue || !m.text.isEmpty())
            return readOnly();
        if (const auto v = m_rotator.readInput(m.index))
            answer(inputReply(m.index, *v));
        else
            return refuse(m, out);
        break;
    case Op::ReadAnalog:
        if (m.hasValue || !m.text.isEmpty())
            return readOnly();
        answer("AN" + QByteArray::number(m.index) + ",0"); // no analogue sensors fitted
        break;
    case Op::SetOutput:
        m_outputs.insert(m.index, int(m.value));
        break;
    case Op::ConfigRead:
        if (m.hasValue || !m.text.isEmpty())
            return readOnly();
        if (const auto v = m_rotator.readRegister(registerRead(m.index)))
            answer(registerReply(registerRead(m.index), *v));
        else
            return refuse(m, out);
        break;
    case Op::ConfigWrite:
        if (!m.hasValue) {
            ++m_counters.malformed;
            alarm("malformed", "CW" + QByteArray::number(m.index) + ',' + m.text.view().toByteArray(), out);
            return;
        }
        if (!m_rotator.writeRegister(m.index, m.value))
            return refuse(m, out);
        break;
    case Op::Status:
        if (m.hasValue)
            return readOnly();
        if (protocol::isGs232(m_dialect)) // `ST=n`, one status for both axes (docs/protocol.md)
            answer(protocol::encodeReport(Message::number(Op::Status, m_rotator.combinedStatus()), m_dialect));
        else
            answer("GS" + QByteArray::number(m_dialect == Dialect::Easycomm3 ? m_rotator.status() : combinedStatus()));
        break;
    case Op::ErrorFlags:
        if (m.hasValue)
            return readOnly();
        answer("GE" + QByteArray::number(m_rotator.errorRegister()));
        break;
    case Op::Version:
        if (!m.text.isEmpty())
            return readOnly();
        answer("VE" + version());
        break;
    case Op::Encoders: {
        if (m.hasValue)
            return readOnly();
        const auto e = m_rotator.encoders();
        answer("\\?ENC" + QByteArray::number(qint64(e[0])) + ',' + QByteArray::number(qint64(e[1])) + ','
               + QByteArray::number(qint64(e[2])) + ',' + QByteArray::number(qint64(e[3])));
        break;
    }
    case Op::Time:
        if (!m.text.isEmpty())
            m_time = m.text.view().toByteArray();
        else
            answer("ST" + (m_time.isEmpty() ? QDateTime::currentDateTimeUtc().toString("yy:MM:dd:HH:mm:ss").toLatin1()
                                             : m_time));
        break;
    case Op::UplinkFreq:
    case Op::DownlinkFreq:
    case Op::UplinkMode:
    case Op::DownlinkMode:
    case Op::UplinkRadio:
    case Op::DownlinkRadio:
        if (m.isQuery()) {
            const QByteArray stored = m_radio.value(int(m.op));
            answer(stored.isEmpty() ? protocol::mnemonic(m.op).toByteArray() + '0' : stored);
        } else {
            m_radio.insert(int(m.op), protocol::encodeToken(m, m_dialect));
        }
        break;
    case Op::Invalid:
    case Op::Alarm:
    case Op::ConfigValue:
    case Op::Report: // rotctld's answer; no controller is sent one
    case Op::Refused: // a controller's answer, not a command
    case Op::SelectRotor: // the Micro-2g's own commands: served by its controller program
    case Op::Preset:
    case Op::StorePreset:
    case Op::Tolerance:
    case Op::Calibration:
    case Op::AdcReadings:
    case Op::RelayBits:
        ++m_counters.unknown;
        alarm("unknown", protocol::mnemonic(m.op), out);
        return;
    }
    ++m_counters.commands;
    if (m_lineAnswers.size() > kMaxLineAnswers)
        finishLine(out);
}

QByteArray SimulatorFirmware::unsolicitedChanges()
{
    if (m_dialect != Dialect::Easycomm3)
        return {};
    QByteArray out;
    auto push = [&](const QByteArray &field, const QByteArray &text) {
        auto it = m_pushed.find(field);
        if (it != m_pushed.end() && it.value() == text)
            return;
        m_pushed.insert(field, text);
        out += text;
        out += '\n';
    };
    const SimulatedRotator &r = m_rotator;
    push("AZ", "AZ" + formatNumber(r.axis(Axis::Azimuth).position(), 2));
    push("EL", "EL" + formatNumber(r.axis(Axis::Elevation).position(), 2));
    for (int input : {0, 1, 2, 7, 8})
        push("IP" + QByteArray::number(input), inputReply(input, r.readInput(input).value_or(0.0)));
    for (int reg = 10; reg <= 13; ++reg)
        push("CR" + QByteArray::number(reg), "CR" + QByteArray::number(reg) + ',' + formatNumber(r.readRegister(reg).value_or(0.0), 2));
    push("GS", "GS" + QByteArray::number(r.status()));
    push("GE", "GE" + QByteArray::number(r.errorRegister()));
    push("VE", "VE" + version());
    return out;
}

} // namespace slew::sim
