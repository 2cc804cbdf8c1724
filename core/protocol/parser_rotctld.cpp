// SPDX-License-Identifier: GPL-3.0-or-later
// The rotctld reader (Hamlib's rotctld(1) manual page): one whole line at a
// time, because rotctld's answers are lines, not tokens.
//
// What rotctld sends back:
//   RPRT 0           a command done                     -> Op::Report, value 0
//   RPRT -9          a command refused, Hamlib's code    -> Op::Alarm, naming the error
//   180.00 / 45.00   the two lines of a `p` answer       -> Op::Azimuth and Op::Elevation, together
//   Dummy rotator    the answer to `_`                   -> Op::Version
// Lines of the commands Slew sends (`P 10 20`, `p`, `S`, `K`, `R 1`,
// `M 16 50`, `_`, and their long names) read as the same messages as their
// Easycomm forms: the session's raw line passes the move gate through them.
//
// A `p` answer is two bare numbers with nothing to tell them apart but their
// order, so the first waits until the second arrives; if the second line is
// not a number, both are dropped with a message. An error code becomes an
// alarm because that is what the session already makes of a controller that
// refuses: it shows the text, forgets the target it was going to, and fails
// the query on the wire (rotctld answers a failed `p` with an RPRT line).

#include "parser.h"

#include "hamliberrors.h"
#include "tokentext.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdio>

namespace slew::protocol {

using namespace text;

namespace {

// The reason given for a line that starts like a number and is not one; the
// pairing of a `p` answer's lines knows it by this pointer.
constexpr const char *kNotANumber = "a line of a position answer that is not a number";

bool isBlank(char c)
{
    return c == ' ' || c == '\t';
}

QByteArrayView trimmed(QByteArrayView s)
{
    while (!s.isEmpty() && isBlank(s.front()))
        s = s.sliced(1);
    while (!s.isEmpty() && isBlank(s.back()))
        s.chop(1);
    return s;
}

// Printable ASCII, spaces and tabs allowed inside.
bool isPrintableLine(QByteArrayView s)
{
    for (char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if ((u < 0x20 && c != '\t') || u > 0x7e)
            return false;
    }
    return true;
}

// Up to kMaxWords words separated by blanks; returns how many there were
// (kMaxWords + 1 when there were more).
constexpr int kMaxWords = 3;
int splitWords(QByteArrayView s, std::array<QByteArrayView, kMaxWords> &words)
{
    int n = 0;
    qsizetype i = 0;
    while (i < s.size()) {
        while (i < s.size() && isBlank(s[i]))
            ++i;
        if (i == s.size())
            break;
        const qsizetype start = i;
        while (i < s.size() && !isBlank(s[i]))
            ++i;
        if (n == kMaxWords)
            return kMaxWords + 1;
        words[size_t(n++)] = s.sliced(start, i - start);
    }
    return n;
}

bool readInt(QByteArrayView s, int *out)
{
    if (s.isEmpty() || s.size() > 10)
        return false;
    const char *begin = s.data();
    if (*begin == '+' && s.size() > 1)
        ++begin; // from_chars takes no '+'
    int v = 0;
    const auto [end, ec] = std::from_chars(begin, s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size())
        return false;
    *out = v;
    return true;
}

// The commands rotctld takes that Slew reads, by short and long name.
enum class Command : std::uint8_t { SetPosition, GetPosition, Stop, Park, Reset, Move, GetInfo };
struct CommandName {
    char shortName;
    const char *longName;
    Command command;
    int arguments;
};
constexpr CommandName kCommands[] = {
    {'P', "set_pos", Command::SetPosition, 2}, {'p', "get_pos", Command::GetPosition, 0},
    {'S', "stop", Command::Stop, 0},           {'K', "park", Command::Park, 0},
    {'R', "reset", Command::Reset, 1},         {'M', "move", Command::Move, 2},
    {'_', "get_info", Command::GetInfo, 0},
};

const CommandName *findCommand(QByteArrayView word)
{
    for (const CommandName &c : kCommands) {
        if ((word.size() == 1 && word[0] == c.shortName) || (word.size() > 1 && word[0] == '\\' && word.sliced(1) == c.longName))
            return &c;
    }
    return nullptr;
}

// `RPRT n`: 0 is done, anything else an error (rotctld sends it negated).
Message readReport(QByteArrayView line, QByteArrayView codeText)
{
    int code = 0;
    if (!readInt(codeText, &code))
        return Message::invalid(line, "RPRT without a whole-number code");
    if (code == 0)
        return Message::number(Op::Report, 0);
    // The alarm text, built without allocating: "RPRT -9: command rejected (RIG_ERJCTED)".
    char text[InlineText::Capacity];
    const char *name = hamlibErrorName(code);
    const int n = name ? std::snprintf(text, sizeof text, "RPRT %d: %s (%s)", code, hamlibErrorText(code), name)
                       : std::snprintf(text, sizeof text, "RPRT %d: an error Hamlib does not name", code);
    Message m = Message::word(Op::Alarm, QByteArrayView(text, std::clamp(n, 0, int(sizeof text) - 1)));
    m.hasValue = true;
    m.value = code;
    return m;
}

} // namespace

int Parser::pushRotctld(char c)
{
    if (c == '\n' || c == '\r') {
        finishRotctldLine();
        return m_readyCount;
    }
    if (m_length < int(m_token.size()))
        m_token[size_t(m_length++)] = c;
    else
        m_overflow = true;
    return m_readyCount;
}

void Parser::finishRotctldLine()
{
    const QByteArrayView line = trimmed(QByteArrayView(m_token.data(), m_length));
    const bool overflow = m_overflow;
    m_length = 0;
    m_overflow = false;
    Classified c;
    if (overflow) {
        c.first = Message::invalid(line, "line longer than 128 bytes, dropped", Refusal::Overlong);
    } else if (line.isEmpty()) {
        return; // an empty line (a CR LF peer's second byte) carries nothing
    } else {
        c = classifyRotctld(line);
    }
    // Only the lines of a `p` answer hold numbers, so a line that is a number,
    // or starts like one, takes the next place in a pair: azimuth, elevation.
    // A bare number reads as an azimuth on its own (see classifyRotctld).
    const bool number = c.count == 1 && c.first.op == Op::Azimuth && c.first.hasValue;
    const bool brokenNumber = c.first.op == Op::Invalid && c.first.reason == kNotANumber;

    if (m_holdingAzimuth) {
        m_holdingAzimuth = false;
        if (m_azimuthBroken) {
            // Already reported with the first line; its partner goes with it.
            if (number || brokenNumber)
                return;
        } else if (number) {
            deliver(Message::number(Op::Azimuth, m_heldAzimuth), false);
            deliver(Message::number(Op::Elevation, c.first.value), true);
            return;
        } else {
            deliver(Message::invalid(line, "a position answer whose elevation line is missing or not a number: "
                                           "its azimuth is dropped too"),
                    true);
            // The line was the elevation's place, unless it is an answer of
            // its own: an RPRT line answers the next command.
            const bool answerOfItsOwn = c.first.op != Op::Invalid && c.first.op != Op::Version;
            if (!answerOfItsOwn)
                return;
        }
    } else if (number || brokenNumber) {
        m_holdingAzimuth = true;
        m_azimuthBroken = brokenNumber;
        m_heldAzimuth = c.first.value;
        if (number)
            return; // waits for its elevation
    }
    if (c.count == 2)
        deliver(c.first, false);
    deliver(c.count == 2 ? c.second : c.first, true);
}

Parser::Classified Parser::classifyRotctld(QByteArrayView line) const
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
    line = trimmed(line);
    if (line.isEmpty())
        return one(Message::invalid(line, "empty line", Refusal::Unknown));
    if (!isPrintableLine(line))
        return one(Message::invalid(line, "unprintable byte in line"));

    std::array<QByteArrayView, kMaxWords> words;
    const int count = splitWords(line, words);
    if (words[0] == "RPRT") {
        if (count != 2)
            return one(Message::invalid(line, "RPRT without a whole-number code"));
        return one(readReport(line, words[1]));
    }
    double number = 0;
    if (count == 1 && parseDecimal(line, &number))
        return one(Message::number(Op::Azimuth, number)); // one line of a `p` answer

    if (const CommandName *command = findCommand(words[0])) {
        if (count - 1 != command->arguments)
            return one(Message::invalid(line, "wrong number of arguments for a rotctld command"));
        double a = 0, b = 0;
        int direction = 0, speed = 0, resetType = 0;
        switch (command->command) {
        case Command::SetPosition:
            if (!parseDecimal(words[1], &a) || !parseDecimal(words[2], &b))
                return one(Message::invalid(line, "set_pos needs two numbers: P az el"));
            return two(Message::number(Op::Azimuth, a), Message::number(Op::Elevation, b));
        case Command::GetPosition: return two(Message::query(Op::Azimuth), Message::query(Op::Elevation));
        case Command::Stop: return two(Message::query(Op::StopAzimuth), Message::query(Op::StopElevation));
        case Command::Park: return one(Message::query(Op::Park));
        case Command::Reset:
            if (!readInt(words[1], &resetType))
                return one(Message::invalid(line, "reset needs a whole-number type: R 1"));
            return one(Message::query(Op::Reset));
        case Command::Move:
            if (!readInt(words[1], &direction) || !readInt(words[2], &speed) || !(speed == -1 || (speed >= 1 && speed <= 100)))
                return one(Message::invalid(line, "move needs a direction and a speed of 1 to 100 or -1: M 16 50"));
            switch (direction) {
            case 2: return one(Message::query(Op::MoveUp));
            case 4: return one(Message::query(Op::MoveDown));
            case 8: return one(Message::query(Op::MoveLeft));
            case 16: return one(Message::query(Op::MoveRight));
            default: return one(Message::invalid(line, "move direction must be 2, 4, 8 or 16"));
            }
        case Command::GetInfo: return one(Message::query(Op::Version));
        }
    }
    // What looks like a number or a command, and is neither, is garbage; so
    // is a command Slew does not read (`\dump_state`, the extended forms
    // `+p`, `;p`), whose answer it could not read either.
    const char first = line[0];
    const bool extendedForm = first == '+' && line.size() > 1 && !isDigit(line[1]) && line[1] != '.';
    if (!extendedForm && (isDigit(first) || first == '-' || first == '+' || first == '.'))
        return one(Message::invalid(line, kNotANumber));
    if (extendedForm || first == ',' || first == ';' || first == '|' || first == '\\')
        return one(Message::invalid(line, "not a rotctld answer Slew reads", Refusal::Unknown));
    if (count == 1 && line.size() == 1)
        return one(Message::invalid(line, "not a rotctld command Slew reads", Refusal::Unknown));
    // Anything else is text: the model's name, rotctld's answer to `_`. (A
    // line of words cannot be told from it; as a raw line to send, such
    // text is refused by the session.)
    return one(Message::word(Op::Version, line));
}

} // namespace slew::protocol
