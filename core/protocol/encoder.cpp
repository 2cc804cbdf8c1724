// SPDX-License-Identifier: GPL-3.0-or-later
#include "encoder.h"

#include "spidcodec.h"

#include "operations.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace slew::protocol {

QByteArray formatNumber(double value, int decimals)
{
    // A value that rounds to zero is written as zero: "-0.0" reads as a
    // negative angle to some device parsers.
    if (!std::isfinite(value) || std::fabs(value) < 0.5 * std::pow(10.0, -decimals))
        value = 0.0;
    // snprintf with "C" numbers: the wire always uses '.', never a locale comma.
    // It returns the length the whole number needs, which for a large value
    // is more than it wrote: the buffer holds any finite double at the
    // decimals Slew uses, and the length is clamped to what was written.
    char buffer[400]; // DBL_MAX is 309 digits before the point
    const int n = std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return QByteArray(buffer, std::clamp(n, 0, int(sizeof buffer) - 1));
}

namespace {

// Rounded to a whole number for the wire, defined for every double: a NaN
// is 0 and magnitudes are capped at 10^15, where llround (and llabs of what
// it returns) would otherwise be undefined. Callers check ranges first; this
// keeps the encoder total when one does not.
long long wholeNumber(double v)
{
    constexpr double kCap = 1e15;
    if (std::isnan(v))
        return 0;
    return std::llround(std::clamp(v, -kCap, kCap));
}

QByteArray integer(double v)
{
    return QByteArray::number(qint64(wholeNumber(v)));
}

// Velocity in mdeg/s. The Easycomm III derivative controller pads to 3 digits, Hamlib's
// model 204 (the SatNOGS path) to 4; devices read either.
QByteArray velocity(double mdegPerSecond, Dialect d)
{
    char buffer[32];
    const long long v = std::llabs(wholeNumber(mdegPerSecond));
    const int n = std::snprintf(buffer, sizeof buffer, d == Dialect::SatNogs ? "%04lld" : "%03lld", v);
    return QByteArray(buffer, n);
}

QByteArray threeDigits(double degrees)
{
    char buffer[32];
    const int n = std::snprintf(buffer, sizeof buffer, "%03lld", wholeNumber(std::max(0.0, degrees)));
    return QByteArray(buffer, n);
}

// GS-232 commands: single letters, angles as three whole digits.
QByteArray encodeGs232Token(const Message &m)
{
    switch (m.op) {
    case Op::Azimuth: return m.hasValue ? "M" + threeDigits(m.value) : QByteArray("C");
    case Op::Elevation: return m.hasValue ? QByteArray() : QByteArray("B");
    case Op::MoveLeft: return "L";
    case Op::MoveRight: return "R";
    case Op::MoveUp: return "U";
    case Op::MoveDown: return "D";
    case Op::StopAzimuth: return "A";
    case Op::StopElevation: return "E";
    case Op::Speed: return "X" + QByteArray::number(std::clamp(int(m.value), 1, 4));
    case Op::KeepAlive: return "?";
    case Op::Status: return m.hasValue ? QByteArray() : QByteArray("GS");
    default: return {};
    }
}

// rotctld's `M` takes a speed from 1 to 100 (or -1, "no change"): a share of
// what the rotator can do, not a rate Slew could work out from degrees per
// second. Half is what Slew asks; -1 would leave it to whatever the backend
// last had, which after connecting nobody knows.
constexpr int kRotctldMoveSpeed = 50;

QByteArray rotctldMove(int direction)
{
    return "M " + QByteArray::number(direction) + ' ' + QByteArray::number(kRotctldMoveSpeed);
}

// rotctld's commands (Hamlib's rotctld(1) manual page): a letter and its
// arguments after spaces. Its set position always names both axes, so a
// lone angle has no form here: encodeSetPosition writes `P az el`.
QByteArray encodeRotctldToken(const Message &m)
{
    switch (m.op) {
    case Op::Azimuth:
    case Op::Elevation: return m.hasValue ? QByteArray() : QByteArray("p"); // p answers both axes
    case Op::MoveUp: return rotctldMove(2); // Hamlib's ROT_MOVE_UP
    case Op::MoveDown: return rotctldMove(4);
    case Op::MoveLeft: return rotctldMove(8);
    case Op::MoveRight: return rotctldMove(16);
    case Op::StopAzimuth:
    case Op::StopElevation: return "S"; // rotctld stops both axes: more than asked, never less
    case Op::Park: return "K";
    case Op::Reset: return "R 1"; // ROT_RESET_ALL, the one reset type Hamlib defines
    case Op::Version: return m.isQuery() ? QByteArray("_") : QByteArray();
    default: return {};
    }
}

// The Micro-2g program's commands (its header comment): a letter, the
// rotor's digit when one is named (index 1..4), then the argument. Mqqq has
// no rotor digit, as it turns the default rotor: a named rotor is made the
// default first (`2\rM035`). A bearing goes out as 0..359: the program
// picks the shorter way inside its overlap itself.
QByteArray encodeMicro2gToken(const Message &m)
{
    const bool named = m.index >= 1 && m.index <= 4;
    const QByteArray rotor = named ? QByteArray::number(m.index) : QByteArray();
    switch (m.op) {
    case Op::Azimuth: {
        if (!m.hasValue)
            return "C" + rotor;
        const long long bearing = ((wholeNumber(m.value) % 360) + 360) % 360;
        return (named ? rotor + '\r' : QByteArray()) + "M" + threeDigits(double(bearing));
    }
    case Op::StopAzimuth: return "S" + rotor;
    case Op::Preset:
    case Op::StorePreset:
        if (!m.hasValue || m.value < 1 || m.value > 3)
            return {};
        return (m.op == Op::Preset ? "P" : "L") + rotor + integer(m.value);
    case Op::SelectRotor:
        if (!m.hasValue || m.value < 1 || m.value > 4)
            return {};
        return integer(m.value);
    case Op::Version: return m.isQuery() ? QByteArray("?") : QByteArray();
    case Op::Tolerance:
        if (m.isQuery() && !named)
            return "T";
        if (!named || !m.hasValue || m.value < 1 || m.value > 500)
            return {};
        return "T" + rotor + ' ' + integer(m.value); // Tn x
    case Op::Calibration:
        if (m.isQuery() && !named)
            return "Z";
        // ZnL mmm, ZnR xxxx=yyy, ZnD mmm: the text is what follows the rotor.
        if (!named || m.text.isEmpty())
            return {};
        return "Z" + rotor + m.text.view().toByteArray();
    case Op::AdcReadings: return m.isQuery() && !named ? QByteArray("V") : QByteArray();
    case Op::RelayBits: return m.isQuery() && !named ? QByteArray("R") : QByteArray();
    default: return {};
    }
}

// Whether a line holds one command (GS-232, rotctld, Micro-2g) rather than
// several tokens (Easycomm).
bool oneCommandALine(Dialect d)
{
    return isGs232(d) || d == Dialect::Rotctld || d == Dialect::Micro2g;
}

} // namespace

QByteArray encodeToken(const Message &m, Dialect d)
{
    // SPID has no tokens: its frames come from spidcodec.h, never text.
    if (isSpid(d) || !dialectSupports(d, m.op))
        return {};
    if (isGs232(d))
        return encodeGs232Token(m);
    if (d == Dialect::Rotctld)
        return encodeRotctldToken(m);
    if (d == Dialect::Micro2g)
        return encodeMicro2gToken(m);
    QByteArray out = mnemonic(m.op).toByteArray();
    switch (operationInfo(m.op).argument) {
    case Argument::Angle:
        if (m.hasValue)
            out += formatNumber(m.value, angleDecimals(d));
        break;
    case Argument::Integer:
        if (m.hasValue)
            out += integer(m.value);
        break;
    case Argument::Word:
        out += m.text.view();
        break;
    case Argument::Velocity:
        if (m.hasValue)
            out += velocity(m.value, d);
        break;
    case Argument::OutputValue:
        out += QByteArray::number(m.index) + ',' + integer(m.value);
        break;
    case Argument::Index:
        out += QByteArray::number(m.index);
        break;
    case Argument::Register:
        // SatNOGS firmware reads the register after a space: `CR 1`.
        if (d == Dialect::SatNogs)
            out += ' ';
        out += QByteArray::number(m.index);
        break;
    case Argument::RegisterValue:
        out += QByteArray::number(m.index) + ',';
        out += m.text.isEmpty() ? formatNumber(m.value, 3) : m.text.view().toByteArray();
        break;
    case Argument::None:
        break;
    case Argument::NeverSent:
        return {};
    }
    return out;
}

QByteArray encodeReport(const Message &m, Dialect d)
{
    if (d == Dialect::Rotctld) {
        // The lines of a `p` answer: bare numbers, azimuth first.
        if (!m.hasValue || (m.op != Op::Azimuth && m.op != Op::Elevation))
            return {};
        return formatNumber(m.value, angleDecimals(d));
    }
    if (!isGs232(d))
        return encodeToken(m, d);
    // GS-232's status answer (Slew's choice, docs/protocol.md): `ST=` and
    // the status bits in decimal, as Easycomm's GS carries them.
    if (m.op == Op::Status)
        return m.hasValue ? "ST=" + integer(m.value) : QByteArray();
    // GS-232 reports differ from its commands: `+0aaa` (A) or `AZ=aaa` (B).
    if (!m.hasValue || (m.op != Op::Azimuth && m.op != Op::Elevation))
        return {};
    if (d == Dialect::Gs232A)
        return "+0" + threeDigits(m.value);
    return (m.op == Op::Azimuth ? "AZ=" : "EL=") + threeDigits(m.value);
}

QByteArray reportSeparator(Dialect d)
{
    // GS-232A runs its two numbers together (`+0010+0020`), GS-232B puts two
    // spaces between (`AZ=010  EL=020`), Easycomm one.
    switch (d) {
    case Dialect::Gs232A: return {};
    case Dialect::Gs232B: return "  ";
    case Dialect::Rotctld: return "\n"; // a `p` answer is two lines
    default: return " ";
    }
}

QByteArray encodeLine(std::initializer_list<Message> tokens, Dialect d)
{
    // GS-232 and rotctld take one command a line; Easycomm several, space-separated.
    const char separator = oneCommandALine(d) ? lineTerminator(d) : ' ';
    QByteArray line;
    for (const Message &m : tokens) {
        const QByteArray token = encodeToken(m, d);
        if (token.isEmpty())
            return {};
        if (!line.isEmpty())
            line += separator;
        line += token;
    }
    if (!line.isEmpty())
        line += lineTerminator(d);
    return line;
}

QByteArray encodeEasycomm1Line(double az, double el, quint64 up, QByteArrayView upMode, quint64 down,
                               QByteArrayView downMode)
{
    QByteArray line = "AZ" + formatNumber(az, 1) + " EL" + formatNumber(el, 1);
    line += " UP" + QByteArray::number(up).rightJustified(3, '0') + ' ' + upMode.toByteArray();
    line += " DN" + QByteArray::number(down).rightJustified(3, '0') + ' ' + downMode.toByteArray();
    line += '\n';
    return line;
}

QByteArray encodeSetPosition(double az, double el, Dialect d, int rotor)
{
    if (isSpid(d))
        return {}; // a frame that needs the controller's resolution: spid::encodeSet
    if (d == Dialect::Micro2g) // azimuth only: the elevation has no command
        return encodeLine({Message::number(Op::Azimuth, az, rotor > 0 ? rotor : -1)}, d);
    if (d == Dialect::Easycomm1)
        return encodeEasycomm1Line(az, el);
    if (isGs232(d))
        return "W" + threeDigits(az) + ' ' + threeDigits(el) + lineTerminator(d);
    if (d == Dialect::Rotctld)
        return "P " + formatNumber(az, angleDecimals(d)) + ' ' + formatNumber(el, angleDecimals(d)) + lineTerminator(d);
    return encodeLine({Message::number(Op::Azimuth, az), Message::number(Op::Elevation, el)}, d);
}

QByteArray encodeQueryPosition(Dialect d, int rotor)
{
    if (isSpid(d))
        return spid::encodeStatus(); // a fixed frame: the controller answers with its position
    if (d == Dialect::Micro2g)
        return encodeLine({Message::query(Op::Azimuth, rotor > 0 ? rotor : -1)}, d);
    if (d == Dialect::Easycomm1)
        return {}; // Easycomm I has no way to ask
    if (isGs232(d))
        return QByteArray("C2") + lineTerminator(d);
    if (d == Dialect::Rotctld)
        return QByteArray("p") + lineTerminator(d);
    return encodeLine({Message::query(Op::Azimuth), Message::query(Op::Elevation)}, d);
}

int positionReplyBytes(Dialect d)
{
    if (isSpid(d))
        return spid::replySize(d);
    return 20;
}

QByteArray encodeOffset(double azimuth, double elevation, Dialect d)
{
    if (!dialectSupports(d, Op::Offset))
        return {};
    auto signedThree = [](double v) {
        char buffer[32];
        const int n = std::snprintf(buffer, sizeof buffer, "%+04lld", wholeNumber(v));
        return QByteArray(buffer, n);
    };
    return "O" + signedThree(azimuth) + signedThree(elevation) + lineTerminator(d);
}

QByteArray encodeStop(bool azimuth, bool elevation, Dialect d, int rotor)
{
    if (isSpid(d)) // one frame stops every axis: stopping more than asked is the safe side
        return azimuth || elevation ? spid::encodeStop() : QByteArray();
    if (d == Dialect::Micro2g) // one axis: a stop of elevation alone has nothing to stop
        return azimuth ? encodeLine({Message::query(Op::StopAzimuth, rotor > 0 ? rotor : -1)}, d) : QByteArray();
    if (d == Dialect::Easycomm1 || (!azimuth && !elevation))
        return {};
    if (azimuth && elevation && isGs232(d))
        return QByteArray("S") + lineTerminator(d);
    if (d == Dialect::Rotctld)
        return QByteArray("S") + lineTerminator(d); // one stop for every axis
    if (azimuth && elevation)
        return encodeLine({Message::query(Op::StopAzimuth), Message::query(Op::StopElevation)}, d);
    return encodeLine({Message::query(azimuth ? Op::StopAzimuth : Op::StopElevation)}, d);
}

QByteArray encodeStopHold(bool azimuth, bool elevation, Dialect d)
{
    if (!dialectSupports(d, Op::VelocityLeft) || !dialectSupports(d, Op::VelocityUp))
        return {};
    if (azimuth && elevation)
        return encodeLine({Message::number(Op::VelocityLeft, 0), Message::number(Op::VelocityUp, 0)}, d);
    if (azimuth || elevation)
        return encodeLine({Message::number(azimuth ? Op::VelocityLeft : Op::VelocityUp, 0)}, d);
    return {};
}

} // namespace slew::protocol
