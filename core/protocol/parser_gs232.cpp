// The GS-232 reader: one token of GS-232A/B (the Micro-2g program, the easycom library) to one
// or two messages (Parser::classifyGs232): `C2` asks for both axes, `S` stops
// both, `+0aaa+0eee` reports both.

#include "parser.h"

#include "tokentext.h"

#include <optional>

namespace slew::protocol {

using namespace text;

namespace {

// One signed offset: a sign or none, up to three digits (a decimal is
// tolerated), at most 450 either way since no rotator turns further.
bool offset(QByteArrayView s, double *out)
{
    const QByteArrayView digits = (!s.isEmpty() && (s[0] == '+' || s[0] == '-')) ? s.sliced(1) : s;
    return !digits.isEmpty() && digits.size() <= 6 && isDigit(digits[0]) && parseDecimal(s, out)
        && *out >= -450 && *out <= 450;
}

// `+010-005`, `010+005`, `-5+0`: the second offset starts at the first sign
// after the first byte, so it must carry one.
bool offsetPair(QByteArrayView s, double *az, double *el)
{
    qsizetype split = -1;
    for (qsizetype i = 1; i < s.size(); ++i) {
        if (s[i] == '+' || s[i] == '-') {
            split = i;
            break;
        }
    }
    return split > 0 && offset(s.first(split), az) && offset(s.sliced(split), el);
}

// The status after `ST=`: a number of at most 16 bits (decimal, or hex
// after 0x) or a word for one state, in the bits of Easycomm's GS.
std::optional<int> statusBits(QByteArrayView s)
{
    struct Word {
        QByteArrayView name; // its length known at compile time
        int bits;
    };
    static constexpr Word kWords[] = {{"IDLE", 1}, {"MOVING", 2}, {"POINTING", 4}, {"ERROR", 8}};
    for (const Word &w : kWords) {
        if (s.size() == w.name.size() && startsWithMnemonic(s, w.name))
            return w.bits;
    }
    if (s.size() > 2 && s[0] == '0' && upper(s[1]) == 'X') {
        bool ok = false;
        const int v = s.sliced(2).toInt(&ok, 16);
        return ok && s.size() <= 6 && v >= 0 ? std::optional<int>(v) : std::nullopt;
    }
    double v = 0;
    if (!parseUnsigned(s, 5, &v) || v > 0xFFFF)
        return std::nullopt;
    return int(v);
}

} // namespace

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

    // Reports: `+0aaa`, `+0aaa+0eee` (GS-232A), `AZ=aaa`, `EL=eee` (GS-232B),
    // `AZ=aaaEL=eee` (K3NG's GS-232B).
    if (first == '+') {
        const qsizetype second = t.indexOf('+', 1);
        if (second < 0 && degrees(rest, &a))
            return one(Message::number(Op::Azimuth, a)); // the answer to C (or B: read as azimuth)
        if (second > 0 && degrees(t.sliced(1, second - 1), &a) && degrees(t.sliced(second + 1), &b))
            return two(Message::number(Op::Azimuth, a), Message::number(Op::Elevation, b));
        return one(Message::invalid(t, "malformed GS-232 position report"));
    }
    // K3NG's GS-232B firmware answers C2 with the two joined, `AZ=059EL=025`
    // (Hamlib's 603 reads it too); the elevation's part starts at `EL=`.
    if (t.size() > 3 && startsWithMnemonic(t, "AZ=")) {
        qsizetype el = 3;
        while (el < t.size() && !startsWithMnemonic(t.sliced(el), "EL="))
            ++el;
        if (el < t.size()) {
            if (!degrees(t.sliced(3, el - 3), &a) || !degrees(t.sliced(el + 3), &b))
                return one(Message::invalid(t, "malformed GS-232 position report"));
            return two(Message::number(Op::Azimuth, a), Message::number(Op::Elevation, b));
        }
    }
    if (t.size() > 3 && (startsWithMnemonic(t, "AZ=") || startsWithMnemonic(t, "EL="))) {
        if (!degrees(t.sliced(3), &a))
            return one(Message::invalid(t, "malformed GS-232 position report"));
        return one(Message::number(first == 'A' ? Op::Azimuth : Op::Elevation, a));
    }
    // The Yaesu prompt after a command it did not take (K3NG's too).
    if (t == "?>")
        return one(Message::word(Op::Refused, t));
    if (t.size() == 2 && upper(t[0]) == 'G' && upper(t[1]) == 'S')
        return one(Message::query(Op::Status));
    // The answer to GS: `ST=6` (Slew's choice); `ST6`, `ST=006`, `ST=0x06`
    // and the words IDLE, MOVING, POINTING, ERROR are read too.
    if (t.size() > 2 && startsWithMnemonic(t, "ST")) {
        if (const std::optional<int> bits = statusBits(t.sliced(t[2] == '=' ? 3 : 2)))
            return one(Message::number(Op::Status, *bits));
        return one(Message::invalid(t, "malformed GS-232 status (ST=n)"));
    }
    if (t == "C2" || t == "c2")
        return two(Message::query(Op::Azimuth), Message::query(Op::Elevation));
    if (t == "?")
        return one(Message::query(Op::KeepAlive));
    // The answer to `?`: the easycom library gives none, Slew chose `OK`.
    // It carries text so that it is never taken for an echo of the `?`.
    if (t == "OK" || t == "ok")
        return one(Message::word(Op::KeepAlive, "OK"));
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
    case 'A': // Aaaa (the easycom library's variant): azimuth
    case 'M': // Maaa: azimuth
    case 'W': // Waaa eee: the elevation is the next token
        if (!degrees(rest, &a))
            return one(Message::invalid(t, "malformed GS-232 angle"));
        return one(Message::number(Op::Azimuth, a));
    case 'E': // Eeee (the easycom library's variant): elevation
        if (!degrees(rest, &a))
            return one(Message::invalid(t, "malformed GS-232 angle"));
        return one(Message::number(Op::Elevation, a));
    case 'O': { // O+aaa-eee: a relative move (the easycom library's table)
        double da = 0, de = 0;
        if (!offsetPair(rest, &da, &de))
            return one(Message::invalid(t, "malformed GS-232 relative move (O+010-005)"));
        return two(Message::number(Op::Offset, da, 0), Message::number(Op::Offset, de, 1));
    }
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

} // namespace slew::protocol
