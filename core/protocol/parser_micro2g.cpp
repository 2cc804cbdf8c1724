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
//   T, Z, V, R     the listings                     -> Tolerance, Calibration, AdcReadings, RelayBits queries
//   Tn x           rotor n's tolerance, A/D counts  -> Tolerance, index n, value x
//   ZnL mmm, ZnR mmm, ZnD mmm, ZnL xxxx=yyy, ZnR xxxx=yyy
//                  calibrate rotor n                -> Calibration, index n, text `L mmm` (after Zn)
// Answers:
//   +0123          a heading (also +123, 123, 123.5, C1=123, +0123 with spaces around)
//                  -> Azimuth 123 and Elevation 0: a Micro-2g rotor has no
//                     elevation axis, and a position needs both
//   ?> text        the controller refused a command -> Alarm with the text
//   other text     the answer to `?`                -> Version with the line
//   T1=20 T2=20 .. the listings of T, V and R       -> Tolerance, AdcReadings, RelayBits with the
//                  (any case, blanks or commas between, any number of rotors), text as Slew writes it
//   Z1L 3990=000 Z1R 2440=090 Z1D 450
//                  a rotor's calibration            -> Calibration, index 1, text the line

#include "parser.h"

#include "tokentext.h"

#include <algorithm>
#include <array>
#include <cstdio>

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

// `T1=20 T2=20 T3=20 T4=20`, `V1=3990 ...`, `R1=- R2=L ...`: one item per
// rotor, each the listing's letter, the rotor, `=` and a value. Written
// back into out in Slew's form (upper case, one space between).
bool listing(QByteArrayView line, char letter, InlineText *out)
{
    char buffer[InlineText::Capacity];
    int length = 0;
    int items = 0;
    qsizetype i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == ','))
            ++i;
        if (i == line.size())
            break;
        const qsizetype start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != ',')
            ++i;
        const QByteArrayView item = line.sliced(start, i - start);
        if (item.size() < 4 || upper(item[0]) != letter || !isRotor(item[1]) || item[2] != '=')
            return false;
        const QByteArrayView value = item.sliced(3);
        const bool ok = letter == 'R' ? value.size() == 1 && (upper(value[0]) == 'L' || upper(value[0]) == 'R' || value[0] == '-')
                                      : allDigits(value) && value.size() <= 4;
        if (!ok || length + item.size() + 1 > int(sizeof buffer))
            return false;
        if (length > 0)
            buffer[length++] = ' ';
        for (char c : item)
            buffer[length++] = upper(c);
        ++items;
    }
    out->assign(QByteArrayView(buffer, length));
    return items > 0;
}

// What follows `ZnL ` / `ZnR `: a bearing `mmm`, or `xxxx=yyy` (a reading
// and its bearing); after `ZnD `, a degree range.
bool calibrationValue(char which, QByteArrayView v)
{
    const qsizetype equals = v.indexOf('=');
    if (which == 'D' || equals < 0)
        return allDigits(v) && v.size() <= 3;
    return allDigits(v.first(equals)) && equals <= 4 && allDigits(v.sliced(equals + 1)) && v.size() - equals - 1 <= 3;
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

namespace {

// `ZnL mmm` and the like (one group) is a calibration command; `ZnL ..
// ZnR .. ZnD ..` of one rotor is the answer to Z.
Message calibration(QByteArrayView line)
{
    std::array<QByteArrayView, 6> words{};
    int n = 0;
    for (qsizetype i = 0; i < line.size();) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
            ++i;
        const qsizetype start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t')
            ++i;
        if (i == start)
            continue;
        if (n == int(words.size()))
            return Message::invalid(line, "too many words for a Micro-2g calibration");
        words[size_t(n++)] = line.sliced(start, i - start);
    }
    const char rotor = line[1];
    if (!isRotor(rotor))
        return Message::invalid(line, "rotors are 1 to 4");
    auto group = [&](int w, char expected) {
        const QByteArrayView head = words[size_t(w)];
        const char which = head.size() == 3 ? upper(head[2]) : '?';
        return head.size() == 3 && upper(head[0]) == 'Z' && head[1] == rotor
            && (expected ? which == expected : (which == 'L' || which == 'R' || which == 'D'))
            && calibrationValue(which, words[size_t(w + 1)]);
    };
    if (n == 2 && group(0, 0)) {
        char text[16];
        const int len = std::snprintf(text, sizeof text, "%c %.*s", upper(words[0][2]), int(words[1].size()),
                                      words[1].data());
        return Message::word(Op::Calibration, QByteArrayView(text, std::clamp(len, 0, int(sizeof text) - 1)),
                             rotor - '0');
    }
    if (n == 6 && group(0, 'L') && group(2, 'R') && group(4, 'D'))
        return Message::word(Op::Calibration, line, rotor - '0');
    return Message::invalid(line, "ZnL mmm, ZnR mmm, ZnD mmm or ZnL/ZnR xxxx=yyy, rotor n 1 to 4");
}

} // namespace

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
    // The listings, the tolerance and the calibration.
    if (line.size() == 1 && (first == 'T' || first == 'Z' || first == 'V' || first == 'R')) {
        const Op op = first == 'T' ? Op::Tolerance : first == 'Z' ? Op::Calibration
            : first == 'V' ? Op::AdcReadings : Op::RelayBits;
        return one(Message::query(op));
    }
    if ((first == 'T' || first == 'V' || first == 'R') && line.size() > 3 && isRotor(line[1]) && line[2] == '=') {
        const Op op = first == 'T' ? Op::Tolerance : first == 'V' ? Op::AdcReadings : Op::RelayBits;
        Message m = Message::word(op, {});
        if (!listing(line, first, &m.text))
            return one(Message::invalid(line, "malformed Micro-2g listing (T1=20 T2=20 ...)"));
        return one(m);
    }
    // `T` or `Z` and a digit is a tolerance or calibration command, good or not.
    if (first == 'T' && line.size() > 3 && isDigit(line[1]) && (line[2] == ' ' || line[2] == '\t')) {
        const QByteArrayView counts = trimmedLine(line.sliced(3));
        if (!isRotor(line[1]) || !parseUnsigned(counts, 3, &v) || v < 1 || v > 500)
            return one(Message::invalid(line, "Tn x: rotor n 1 to 4, tolerance x 1 to 500"));
        return one(Message::number(Op::Tolerance, v, line[1] - '0'));
    }
    if (first == 'Z' && line.size() > 1 && isDigit(line[1]))
        return one(calibration(line));
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
