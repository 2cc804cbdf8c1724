// SPDX-License-Identifier: GPL-3.0-or-later
// The Micro-2g reader (the Micro-2g program's header comment; the answers
// are Slew's choice, docs/protocol.md "Micro-2g"): one whole line at a time,
// because the controller's answers are lines with spaces in them.
//
// Commands (what a host sends), with the rotor in Message::index (-1: the
// controller's default rotor):
//   n              select rotor n as the default    -> SelectRotor, value n
//   C, Cn          heading query                    -> Azimuth query
//   Mqqq, X4rMqqq  turn the default rotor to qqq    -> Azimuth, value qqq
//   Pm, Pnm        turn to preset m                 -> Preset, value m
//   Lm, Lnm        store the heading as preset m    -> StorePreset, value m
//   S, Sn          stop                             -> StopAzimuth
//   ?              some information                 -> Version query
// Answers:
//   +0123          a heading (also +123, 123, 123.5, C1=123, +0123 with spaces around)
//                  -> Azimuth 123 and Elevation 0: a Micro-2g rotor has no
//                     elevation axis, and a position needs both
//   ?> text        the controller refused a command -> Alarm with the text
//   other text     the answer to `?`                -> Version with the line
// T, Z, V, R and the calibration commands are not read yet: they arrive as
// Invalid ("not read by Slew") and change nothing.

#include "parser.h"

#include "tokentext.h"

namespace slew::protocol {

using namespace text;

namespace {

QByteArrayView trimmedLine(QByteArrayView s)
{
    while (!s.isEmpty() && (s.front() == ' ' || s.front() == '\t'))
        s = s.sliced(1);
    while (!s.isEmpty() && (s.back() == ' ' || s.back() == '\t'))
        s.chop(1);
    return s;
}

bool printableWithSpaces(QByteArrayView s)
{
    for (char c : s) {
        if (c < ' ' || c > '~')
            return false;
    }
    return true;
}

bool isRotor(char c)
{
    return c >= '1' && c <= '4';
}

// A heading as the controller prints it: a sign or none, then up to three
// whole digits with a leading zero allowed (`+0123`), a decimal tolerated.
bool heading(QByteArrayView s, double *out)
{
    if (!s.isEmpty() && s[0] == '+')
        s = s.sliced(1);
    return !s.isEmpty() && isDigit(s[0]) && s.size() <= 6 && parseDecimal(s, out) && *out >= 0 && *out <= 360;
}

} // namespace

int Parser::pushMicro2g(char c)
{
    if (c != '\n' && c != '\r') {
        if (m_length < int(m_token.size()))
            m_token[size_t(m_length++)] = c;
        else
            m_overflow = true;
        return m_readyCount;
    }
    const QByteArrayView line = trimmedLine(QByteArrayView(m_token.data(), m_length));
    const bool overflow = m_overflow;
    m_length = 0;
    m_overflow = false;
    if (overflow) {
        deliver(Message::invalid(line, "line longer than 128 bytes, dropped", Refusal::Overlong), true);
    } else if (!line.isEmpty()) { // the LF of a CR LF carries nothing
        const Classified c = classifyMicro2g(line);
        if (c.count == 2)
            deliver(c.first, false);
        deliver(c.count == 2 ? c.second : c.first, true);
    }
    return m_readyCount;
}

Parser::Classified Parser::classifyMicro2g(QByteArrayView line) const
{
    Classified c;
    auto one = [&](const Message &m) {
        c.first = m;
        c.count = 1;
        return c;
    };
    if (!printableWithSpaces(line))
        return one(Message::invalid(line, "unprintable byte in line"));
    // The controller's refusal: `?>` and why.
    if (line.startsWith("?>")) {
        const QByteArrayView why = trimmedLine(line.sliced(2));
        return one(Message::word(Op::Alarm, why.isEmpty() ? QByteArrayView("?>") : why));
    }
    if (line == "?")
        return one(Message::query(Op::Version));
    double v = 0;
    // A heading, or `C1=123` / `C=123` naming the rotor.
    QByteArrayView number = line;
    int rotor = -1;
    if (upper(line[0]) == 'C' && line.size() > 2) {
        const bool named = line.size() > 3 && isRotor(line[1]) && line[2] == '=';
        if (named || line[1] == '=') {
            rotor = named ? line[1] - '0' : -1;
            number = trimmedLine(line.sliced(named ? 3 : 2));
        }
    }
    if (!number.isEmpty() && (number[0] == '+' || isDigit(number[0])) && number.size() > 1) {
        if (!heading(number, &v))
            return one(Message::invalid(line, "malformed Micro-2g heading (+0123)"));
        c.first = Message::number(Op::Azimuth, v, rotor);
        c.second = Message::number(Op::Elevation, 0);
        c.count = 2;
        return c;
    }
    const char first = upper(line[0]);
    const QByteArrayView rest = line.sliced(1);
    // A single digit selects the default rotor.
    if (line.size() == 1 && isDigit(first)) {
        if (!isRotor(first))
            return one(Message::invalid(line, "rotors are 1 to 4"));
        return one(Message::number(Op::SelectRotor, first - '0'));
    }
    // Commands with an optional rotor digit: C, S; P and L with a preset.
    auto rotorOnly = [&](Op op) {
        if (rest.isEmpty())
            return one(Message::query(op));
        if (rest.size() == 1 && isRotor(rest[0]))
            return one(Message::query(op, rest[0] - '0'));
        return one(Message::invalid(line, "the rotor is 1 to 4"));
    };
    auto preset = [&](Op op) {
        const bool withRotor = rest.size() == 2 && isRotor(rest[0]);
        const char m = withRotor ? rest[1] : rest.size() == 1 ? rest[0] : '0';
        if (m < '1' || m > '3')
            return one(Message::invalid(line, "a preset is 1 to 3 (Pm, Pnm, Lm, Lnm)"));
        return one(Message::number(op, m - '0', withRotor ? rest[0] - '0' : -1));
    };
    // Logging programs put `X4` and one more byte before M.
    if (first == 'X' && line.size() >= 4 && line[1] == '4') {
        const QByteArrayView m = upper(line[2]) == 'M' ? line.sliced(2) : line.sliced(3);
        if (!m.isEmpty() && upper(m[0]) == 'M')
            return classifyMicro2g(m);
    }
    // A line of words is the answer to `?` (its text is free); the
    // listings of T, Z, V and R hold `=` and are not read yet.
    if (line.contains(' ') && !line.contains('=') && first >= 'A' && first <= 'Z')
        return one(Message::word(Op::Version, line));
    switch (first) {
    case 'C': return rotorOnly(Op::Azimuth);
    case 'S': return rotorOnly(Op::StopAzimuth);
    case 'P': return preset(Op::Preset);
    case 'L': return preset(Op::StorePreset);
    case 'M':
        if (rest.size() != 3 || !allDigits(rest) || !heading(rest, &v))
            return one(Message::invalid(line, "M wants a bearing of 000 to 360 (M035)"));
        return one(Message::number(Op::Azimuth, v));
    default:
        break;
    }
    return one(Message::invalid(line, "not a Micro-2g command or answer Slew reads", Refusal::Unknown));
}

} // namespace slew::protocol
