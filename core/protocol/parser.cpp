#include "parser.h"

#include <charconv>
#include <cmath>

namespace slew::protocol {

namespace {

bool isLineEnd(char c)
{
    return c == '\r' || c == '\n';
}

// ';' is here because Hamlib's get_conf writes `GS\n;` and the `;` then
// prefixes the next command.
bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == ';';
}

bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}

bool allDigits(QByteArrayView s)
{
    if (s.isEmpty())
        return false;
    for (char c : s) {
        if (!isDigit(c))
            return false;
    }
    return true;
}

char upper(char c)
{
    return (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : c;
}

bool startsWithMnemonic(QByteArrayView token, QByteArrayView mnemonic)
{
    if (token.size() < mnemonic.size())
        return false;
    for (qsizetype i = 0; i < mnemonic.size(); ++i) {
        if (upper(token[i]) != mnemonic[i])
            return false;
    }
    return true;
}

// A decimal number the way devices write them: optional sign, leading zeros
// (`AZ000.1`, `EL00099`), '.' or ',' as the decimal mark. Returns the count of
// decimals in *decimals. No exponent, no spaces, no trailing bytes.
bool parseDecimal(QByteArrayView s, double *out, int *decimals = nullptr)
{
    if (s.isEmpty() || s.size() > 24)
        return false;
    qsizetype i = 0;
    bool negative = false;
    if (s[0] == '+' || s[0] == '-') {
        negative = s[0] == '-';
        ++i;
    }
    double value = 0.0;
    int digits = 0;
    for (; i < s.size() && isDigit(s[i]); ++i, ++digits)
        value = value * 10.0 + (s[i] - '0');
    int fraction = 0;
    if (i < s.size() && (s[i] == '.' || s[i] == ',')) {
        ++i;
        double scale = 0.1;
        for (; i < s.size() && isDigit(s[i]); ++i, ++fraction, scale /= 10.0)
            value += (s[i] - '0') * scale;
    }
    if (i != s.size() || digits + fraction == 0)
        return false;
    // Round away the binary noise of the digit-by-digit sum.
    if (fraction > 0) {
        const double p = std::pow(10.0, fraction);
        value = std::round(value * p) / p;
    }
    *out = negative ? -value : value;
    if (decimals)
        *decimals = fraction;
    return true;
}

bool parseUnsigned(QByteArrayView s, int maxDigits, double *out)
{
    if (!allDigits(s) || s.size() > maxDigits)
        return false;
    double v = 0;
    for (char c : s)
        v = v * 10.0 + (c - '0');
    *out = v;
    return true;
}

bool parseSigned64(QByteArrayView s, double *out)
{
    long long v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || s.isEmpty())
        return false;
    *out = double(v);
    return true;
}

// `n,value` as in IP0,23.5 / CR1,0.8 / AN0,65535 / SatNOGS' bare `1,0.8`.
bool splitIndexed(QByteArrayView rest, int *index, QByteArrayView *value)
{
    const qsizetype comma = rest.indexOf(',');
    const QByteArrayView number = comma < 0 ? rest : rest.first(comma);
    if (!allDigits(number) || number.size() > 5)
        return false;
    *index = number.toInt();
    *value = comma < 0 ? QByteArrayView() : rest.sliced(comma + 1);
    return true;
}

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

bool looksLikeTime(QByteArrayView s)
{
    // YY:MM:DD:HH:mm:SS
    if (s.size() != 17)
        return false;
    for (qsizetype i = 0; i < s.size(); ++i) {
        const bool colon = (i % 3) == 2;
        if (colon ? s[i] != ':' : !isDigit(s[i]))
            return false;
    }
    return true;
}

bool isPrintable(QByteArrayView s)
{
    for (char c : s) {
        if (static_cast<unsigned char>(c) < 0x21 || static_cast<unsigned char>(c) > 0x7e)
            return false;
    }
    return true;
}

bool isBareConfigRead(const Message &m)
{
    return m.op == Op::ConfigRead && m.index < 0 && !m.hasValue;
}

struct Simple {
    const char *mnemonic;
    Op op;
};

// Two-letter commands that take no argument.
constexpr Simple kBare[] = {
    {"ML", Op::MoveLeft},       {"MR", Op::MoveRight},     {"MU", Op::MoveUp}, {"MD", Op::MoveDown},
    {"SA", Op::StopAzimuth},    {"SE", Op::StopElevation}, {"AO", Op::Aos},    {"LO", Op::Los},
};

} // namespace

void Parser::reset()
{
    m_length = 0;
    m_overflow = false;
    m_hasPending = false;
    m_previousOnLine = Op::Invalid;
    m_previousHadValue = false;
    m_readyCount = 0;
}

int Parser::push(char c)
{
    m_readyCount = 0;
    if (isLineEnd(c)) {
        if (m_length > 0 || m_overflow)
            finishToken(true);
        else if (m_hasPending)
            emitPending(true);
        m_previousOnLine = Op::Invalid;
        m_previousHadValue = false;
        return m_readyCount;
    }
    if (isSpace(c)) {
        if (m_length > 0 || m_overflow)
            finishToken(false);
        return m_readyCount;
    }
    // A new token begins: the pending one did not end its line. A bare `CR`
    // keeps waiting, since its register may be this token (SatNOGS `CR 1`),
    // and so does GS-232's `W010` for its elevation.
    if (m_length == 0 && !m_overflow && m_hasPending && !pendingWaitsForArgument())
        emitPending(false);
    if (m_length < int(m_token.size()))
        m_token[size_t(m_length++)] = c;
    else
        m_overflow = true;
    return m_readyCount;
}

void Parser::deliver(const Message &m, bool lineEnd)
{
    Message &slot = m_ready[size_t(m_readyCount++)];
    slot = m;
    slot.lineEnd = lineEnd;
}

bool Parser::pendingWaitsForArgument() const
{
    return m_hasPending && (isBareConfigRead(m_pending) || m_pendingWantsElevation);
}

void Parser::emitPending(bool lineEnd)
{
    m_hasPending = false;
    if (isBareConfigRead(m_pending)) {
        deliver(Message::invalid("CR", "config read without a register number"), lineEnd);
    } else if (m_pendingWantsElevation) {
        m_pendingWantsElevation = false;
        deliver(Message::invalid("W", "W needs an azimuth and an elevation (W010 020)"), lineEnd);
    } else {
        deliver(m_pending, lineEnd);
    }
}

void Parser::finishToken(bool lineEnd)
{
    const QByteArrayView token(m_token.data(), m_length);
    Classified c;
    if (m_overflow) {
        c.first = Message::invalid(token, "token longer than 128 bytes, dropped up to the next separator",
                                   Refusal::Overlong);
    } else if (m_hasPending && isBareConfigRead(m_pending) && allDigits(token) && token.size() <= 5) {
        // SatNOGS: `CR 1` is one command.
        m_hasPending = false;
        c.first = Message::query(Op::ConfigRead, token.toInt());
    } else if (m_hasPending && m_pendingWantsElevation && allDigits(token) && token.size() <= 3) {
        // GS-232: `W010 020` sets both axes.
        m_hasPending = false;
        m_pendingWantsElevation = false;
        c.first = m_pending;
        c.second = Message::number(Op::Elevation, token.toInt());
        c.count = 2;
    } else {
        if (m_hasPending)
            emitPending(false);
        c = classify(token);
    }
    m_length = 0;
    m_overflow = false;
    if (c.count == 2)
        deliver(c.first, false);
    const Message &m = c.count == 2 ? c.second : c.first;
    m_previousOnLine = m.op;
    m_previousHadValue = m.hasValue;

    m_pending = m;
    m_pendingWantsElevation = isGs232(m_dialect) && m.op == Op::Azimuth && m.hasValue && token.size() > 0
                              && upper(token[0]) == 'W' && c.count == 1;
    if (lineEnd)
        emitPending(true);
    else
        m_hasPending = true;
}

Message Parser::parseToken(QByteArrayView token, Dialect d)
{
    Parser p(d);
    return p.classify(token).first;
}

Parser::Classified Parser::classify(QByteArrayView t) const
{
    if (!isPrintable(t)) {
        Classified c;
        c.first = Message::invalid(t, "unprintable byte in token");
        return c;
    }
    if (isGs232(m_dialect))
        return classifyGs232(t);
    Classified c;
    c.first = classifyEasycomm(t);
    return c;
}

Parser::Classified Parser::classifyGs232(QByteArrayView t) const
{
    Classified c;
    auto one = [&](const Message &m) {
        c.first = m;
        c.count = 1;
        return c;
    };
    auto two = [&](const Message &a, const Message &b) {
        c.first = a;
        c.second = b;
        c.count = 2;
        return c;
    };
    // Whole degrees, up to three digits (a decimal is tolerated).
    auto degrees = [](QByteArrayView s, double *out) {
        return !s.isEmpty() && s.size() <= 6 && parseDecimal(s, out) && *out >= 0;
    };
    double a = 0, b = 0;
    const char first = upper(t[0]);
    const QByteArrayView rest = t.sliced(1);

    // Reports: `+0aaa`, `+0aaa+0eee` (GS-232A), `AZ=aaa`, `EL=eee` (GS-232B).
    if (first == '+') {
        const qsizetype second = t.indexOf('+', 1);
        if (second < 0 && degrees(rest, &a))
            return one(Message::number(Op::Azimuth, a)); // the answer to C (or B: read as azimuth)
        if (second > 0 && degrees(t.sliced(1, second - 1), &a) && degrees(t.sliced(second + 1), &b))
            return two(Message::number(Op::Azimuth, a), Message::number(Op::Elevation, b));
        return one(Message::invalid(t, "malformed GS-232 position report"));
    }
    if (t.size() > 3 && (startsWithMnemonic(t, "AZ=") || startsWithMnemonic(t, "EL="))) {
        if (!degrees(t.sliced(3), &a))
            return one(Message::invalid(t, "malformed GS-232 position report"));
        return one(Message::number(first == 'A' ? Op::Azimuth : Op::Elevation, a));
    }
    if (t == "?>")
        return one(Message::invalid(t, "the controller did not understand the command (?>)", Refusal::Unknown));
    if (t == "C2" || t == "c2")
        return two(Message::query(Op::Azimuth), Message::query(Op::Elevation));
    if (t == "?")
        return one(Message::query(Op::KeepAlive));
    if (t.size() == 1) {
        switch (first) {
        case 'C': return one(Message::query(Op::Azimuth));
        case 'B': return one(Message::query(Op::Elevation));
        case 'S': return two(Message::query(Op::StopAzimuth), Message::query(Op::StopElevation));
        case 'A': return one(Message::query(Op::StopAzimuth));
        case 'E': return one(Message::query(Op::StopElevation));
        case 'R': return one(Message::query(Op::MoveRight));
        case 'L': return one(Message::query(Op::MoveLeft));
        case 'U': return one(Message::query(Op::MoveUp));
        case 'D': return one(Message::query(Op::MoveDown));
        default: break;
        }
    }
    switch (first) {
    case 'A': // Aaaa (seeds/004's variant): azimuth
    case 'M': // Maaa: azimuth
    case 'W': // Waaa eee: the elevation is the next token
        if (!degrees(rest, &a))
            return one(Message::invalid(t, "malformed GS-232 angle"));
        return one(Message::number(Op::Azimuth, a));
    case 'E': // Eeee (seeds/004's variant): elevation
        if (!degrees(rest, &a))
            return one(Message::invalid(t, "malformed GS-232 angle"));
        return one(Message::number(Op::Elevation, a));
    case 'X': {
        if (rest.size() != 1 || rest[0] < '1' || rest[0] > '4')
            return one(Message::invalid(t, "speed must be X1 to X4"));
        return one(Message::number(Op::Speed, rest[0] - '0'));
    }
    default:
        break;
    }
    return one(Message::invalid(t, "unknown command", Refusal::Unknown));
}

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

    // SatNOGS' answer to `CR n` has no prefix: `1,0.80`.
    if (isDigit(t[0])) {
        int index = -1;
        QByteArrayView value;
        if (t.contains(',') && splitIndexed(t, &index, &value) && !value.isEmpty())
            return indexedReply(Op::ConfigValue, index, value);
        return Message::invalid(t, "number without a command", Refusal::Unknown);
    }

    if (t.size() < 2)
        return Message::invalid(t, "unknown command", Refusal::Unknown);
    const QByteArrayView rest = t.sliced(2);

    for (const Simple &s : kBare) {
        if (startsWithMnemonic(t, s.mnemonic)) {
            if (!rest.isEmpty())
                return Message::invalid(t, "command takes no argument");
            return Message::query(s.op);
        }
    }

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
        return Message::number(op, v);
    };
    auto indexed = [&](Op op, bool valueRequired) {
        int index = -1;
        QByteArrayView value;
        if (!splitIndexed(rest, &index, &value))
            return Message::invalid(t, "register or input number missing or malformed");
        if (t.contains(',') && value.isEmpty())
            return Message::invalid(t, "value missing after the comma");
        if (valueRequired && value.isEmpty())
            return Message::invalid(t, "value missing");
        if (value.isEmpty())
            return Message::query(op, index);
        return indexedReply(op, index, value);
    };

    const char a = upper(t[0]);
    const char b = upper(t[1]);
    switch (a) {
    case 'A':
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
        if (b == 'T') {
            if (rest.isEmpty())
                return Message::query(Op::Time);
            if (!looksLikeTime(rest))
                return Message::invalid(t, "time must be YY:MM:DD:HH:mm:SS");
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
