// SPDX-License-Identifier: GPL-3.0-or-later
// The Easycomm reader: one token of Easycomm I, II, III or SatNOGS to a
// message (Parser::classifyEasycomm). The line context (Easycomm I's mode
// words) comes from the parser's state.

#include "parser.h"

#include "tokentext.h"

namespace slew::protocol {

using namespace text;

namespace {

constexpr double kMaxVelocity = 99999.0; // mdeg/s

Message indexedReply(Op op, int index, QByteArrayView value)
{
    Message m = Message::word(op, value, index);
    double number = 0;
    if (parseDecimal(value, &number)) {
        m.hasValue = true;
        m.value = number;
    }
    return m;
}

} // namespace

Message Parser::classifyEasycomm(QByteArrayView t) const
{
    // The mode word of an Easycomm I line: `UP145800000 FM`. Checked first
    // because a mode may look like a command (`CW`).
    if ((m_previousOnLine == Op::UplinkFreq || m_previousOnLine == Op::DownlinkFreq) && m_previousHadValue
        && t.size() <= 3) {
        bool hasDigit = false;
        for (char c : t)
            hasDigit = hasDigit || isDigit(c);
        if (!hasDigit)
            return Message::word(m_previousOnLine == Op::UplinkFreq ? Op::UplinkMode : Op::DownlinkMode, t);
    }

    if (startsWithMnemonic(t, "\\?ENC")) {
        const QByteArrayView rest = t.sliced(5);
        if (rest.isEmpty())
            return Message::query(Op::Encoders);
        Message m = Message::query(Op::Encoders);
        int field = 0;
        qsizetype start = 0;
        for (qsizetype i = 0; i <= rest.size(); ++i) {
            if (i == rest.size() || rest[i] == ',') {
                if (field >= 4 || !parseSigned64(rest.sliced(start, i - start), &m.encoders[size_t(field)]))
                    return Message::invalid(t, "encoder report needs four whole numbers");
                ++field;
                start = i + 1;
            }
        }
        if (field != 4)
            return Message::invalid(t, "encoder report needs four whole numbers");
        m.hasValue = true;
        m.value = m.encoders[0];
        return m;
    }
    if (t.size() == 5 && startsWithMnemonic(t, "RESET"))
        return Message::query(Op::Reset);
    if (t.size() == 4 && startsWithMnemonic(t, "PARK"))
        return Message::query(Op::Park);

    // A controller's "no": K3NG's Easycom answers `?` to a command it does
    // not know (PARK, GS, CR1), and `?>` is the Yaesu prompt some Easycomm
    // boards copied.
    if (t == "?" || t == "?>")
        return Message::word(Op::Refused, t);
    // K3NG's Easycom answers `AZ EL` with the bare numbers, `+59.1 +24.8`
    // (each query's answer ended by the byte that ended the query): the
    // first signed number on a line is the azimuth, the one after it the
    // elevation, which is signed only when negative (`-0.5`) in the
    // firmware's AZ-less `EL` answer but always in its pair.
    if (t[0] == '+' || t[0] == '-') {
        double v = 0;
        if (t.size() < 2 || !isDigit(t[1]) || !parseDecimal(t, &v))
            return Message::invalid(t, "malformed bare position (+aaa.a)");
        return Message::number(m_previousBareAzimuth ? Op::Elevation : Op::Azimuth, v);
    }

    // SatNOGS' answer to `CR n` has no prefix: `1,0.80`.
    if (isDigit(t[0])) {
        int index = -1;
        std::optional<QByteArrayView> value;
        if (splitIndexed(t, &index, &value) && value && !value->isEmpty())
            return indexedReply(Op::ConfigValue, index, *value);
        return Message::invalid(t, "number without a command", Refusal::Unknown);
    }

    if (t.size() < 2)
        return Message::invalid(t, "unknown command", Refusal::Unknown);
    const QByteArrayView rest = t.sliced(2);

    // The two-letter commands that take no argument (ML MR MU MD SA SE AO
    // LO) are found in the switch below, by their two letters, as the rest.
    auto bare = [&](Op op) {
        if (!rest.isEmpty())
            return Message::invalid(t, "command takes no argument");
        return Message::query(op);
    };

    auto angle = [&](Op op) {
        if (rest.isEmpty())
            return Message::query(op);
        double v = 0;
        int decimals = 0;
        if (!parseDecimal(rest, &v, &decimals))
            return Message::invalid(t, "malformed angle");
        if (m_dialect == Dialect::Easycomm1 && decimals > 1)
            return Message::invalid(t, "Easycomm I angles have one decimal");
        return Message::number(op, v);
    };
    auto unsignedValue = [&](Op op, int maxDigits, const char *why) {
        if (rest.isEmpty())
            return Message::query(op);
        double v = 0;
        if (!parseUnsigned(rest, maxDigits, &v))
            return Message::invalid(t, why);
        return Message::number(op, v);
    };
    auto word = [&](Op op) {
        if (rest.isEmpty())
            return Message::query(op);
        return Message::word(op, rest);
    };
    auto velocity = [&](Op op) {
        if (rest.isEmpty())
            return Message::query(op);
        double v = 0;
        if (!parseDecimal(rest, &v) || v < 0)
            return Message::invalid(t, "malformed velocity (mdeg/s, not negative)");
        // Hamlib sends at most 9900 and the Easycomm III derivative controller caps its
        // drive at 30000; five digits leave room, and keep a value that
        // would wrap a controller's integer out.
        if (v > kMaxVelocity)
            return Message::invalid(t, "velocity out of range (0 to 99999 mdeg/s)");
        return Message::number(op, v);
    };
    auto indexed = [&](Op op, bool valueRequired) {
        int index = -1;
        std::optional<QByteArrayView> value;
        if (!splitIndexed(rest, &index, &value))
            return Message::invalid(t, "register or input number missing or malformed");
        if (value && value->isEmpty())
            return Message::invalid(t, "value missing after the comma");
        if (!value && valueRequired)
            return Message::invalid(t, "value missing");
        if (!value)
            return Message::query(op, index);
        return indexedReply(op, index, *value);
    };

    const char a = upper(t[0]);
    const char b = upper(t[1]);
    switch (a) {
    case 'M':
        switch (b) {
        case 'L': return bare(Op::MoveLeft);
        case 'R': return bare(Op::MoveRight);
        case 'U': return bare(Op::MoveUp);
        case 'D': return bare(Op::MoveDown);
        default: break;
        }
        break;
    case 'L':
        if (b == 'O')
            return bare(Op::Los);
        break;
    case 'A':
        if (b == 'O')
            return bare(Op::Aos);
        if (b == 'Z')
            return angle(Op::Azimuth);
        if (b == 'N')
            return indexed(Op::ReadAnalog, false);
        if (b == 'L') {
            Message m = Message::word(Op::Alarm, rest);
            return m;
        }
        break;
    case 'E':
        if (b == 'L')
            return angle(Op::Elevation);
        break;
    case 'U':
        if (b == 'P')
            return unsignedValue(Op::UplinkFreq, 10, "malformed uplink frequency (Hz)");
        if (b == 'M')
            return word(Op::UplinkMode);
        if (b == 'R')
            return unsignedValue(Op::UplinkRadio, 3, "malformed uplink radio number");
        break;
    case 'D':
        if (b == 'N')
            return unsignedValue(Op::DownlinkFreq, 10, "malformed downlink frequency (Hz)");
        if (b == 'M')
            return word(Op::DownlinkMode);
        if (b == 'R')
            return unsignedValue(Op::DownlinkRadio, 3, "malformed downlink radio number");
        break;
    case 'O':
        if (b == 'P') {
            Message m = indexed(Op::SetOutput, true);
            if (m.op == Op::SetOutput && !(m.text.view() == "0" || m.text.view() == "1"))
                return Message::invalid(t, "output value must be 0 or 1");
            return m;
        }
        break;
    case 'I':
        if (b == 'P')
            return indexed(Op::ReadInput, false);
        break;
    case 'S':
        if (b == 'A')
            return bare(Op::StopAzimuth);
        if (b == 'E')
            return bare(Op::StopElevation);
        if (b == 'T') {
            if (rest.isEmpty())
                return Message::query(Op::Time);
            if (!isValidTime(rest))
                return Message::invalid(t, "time must be a real YY:MM:DD:HH:mm:SS");
            return Message::word(Op::Time, rest);
        }
        break;
    case 'V':
        switch (b) {
        case 'E': return word(Op::Version);
        case 'L': return velocity(Op::VelocityLeft);
        case 'R': return velocity(Op::VelocityRight);
        case 'U': return velocity(Op::VelocityUp);
        case 'D': return velocity(Op::VelocityDown);
        default: break;
        }
        break;
    case 'C':
        if (b == 'R') {
            if (rest.isEmpty())
                return Message::query(Op::ConfigRead); // register follows: `CR 1`
            return indexed(Op::ConfigRead, false);
        }
        if (b == 'W')
            return indexed(Op::ConfigWrite, true);
        break;
    case 'G':
        if (b == 'S')
            return unsignedValue(Op::Status, 5, "malformed status register");
        if (b == 'E')
            return unsignedValue(Op::ErrorFlags, 5, "malformed error register");
        break;
    default:
        break;
    }
    return Message::invalid(t, "unknown command", Refusal::Unknown);
}

} // namespace slew::protocol
