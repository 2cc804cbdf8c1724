// SPDX-License-Identifier: GPL-3.0-or-later
#include "spidparser.h"

#include <algorithm>

namespace slew::protocol::spid {

namespace {

bool isLineEnd(char c)
{
    return c == '\r' || c == '\n';
}

bool isTextByte(unsigned char b)
{
    return (b >= 0x20 && b < 0x7f) || b == '\t';
}

bool isRawDigit(unsigned char b)
{
    return b <= 9;
}

// A command carries ASCII digits in a set, zeros elsewhere, and small bit
// values (PH, PV, the MD-01 move directions): never 0x57, which is what lets
// a reader find the next frame.
bool isCommandField(unsigned char b)
{
    return b <= 0x0F || (b >= '0' && b <= '9');
}

bool isCommandByte(unsigned char b)
{
    return b == std::uint8_t(Command::Stop) || b == std::uint8_t(Command::Status) || b == std::uint8_t(Command::Set)
           || b == std::uint8_t(Command::Move);
}

// Four digits from `at`, each less `zero`; -1 when one is not a digit.
int digits(const std::array<char, kCommandSize> &frame, int at, int count, char zero)
{
    int value = 0;
    for (int i = 0; i < count; ++i) {
        const int d = frame[size_t(at + i)] - zero;
        if (d < 0 || d > 9)
            return -1;
        value = value * 10 + d;
    }
    return value;
}

} // namespace

void Parser::reset()
{
    m_length = 0;
    m_mayBeReply = m_mayBeCommand = false;
    m_junk = 0;
    m_junkIsText = true;
    m_textLength = 0;
    m_azimuthPulses = m_elevationPulses = 0;
    m_readyCount = 0;
}

Frame &Parser::next()
{
    Frame &f = m_ready[size_t(m_readyCount++)];
    f = Frame{};
    return f;
}

void Parser::push(char c)
{
    if (m_length == 0)
        hunt(c);
    else
        extend(c);
}

void Parser::hunt(char c)
{
    if (c == kStart) {
        m_frame[0] = c;
        m_length = 1;
        m_mayBeReply = m_mayBeCommand = true;
        return;
    }
    if (isLineEnd(c)) {
        flushJunk();
        return;
    }
    ++m_junk;
    const auto b = static_cast<unsigned char>(c);
    if (!isTextByte(b))
        m_junkIsText = false;
    else if (m_textLength < kTextCap)
        m_text[size_t(m_textLength++)] = c; // past the cap only counted: the line is reported cut
}

bool Parser::replyAllows(int at, unsigned char b) const
{
    if (m_dialect == Dialect::Rot1Prog)
        return at <= 3 ? isRawDigit(b) : b == kEnd;
    if (at == 5 || at == 10)
        return isResolution(b);
    if (at == 11)
        return b == kEnd;
    return isRawDigit(b);
}

bool Parser::commandAllows(int at, unsigned char b) const
{
    if (at == 11)
        return isCommandByte(b);
    if (at == 12)
        return b == kEnd;
    return isCommandField(b);
}

void Parser::extend(char c)
{
    const auto b = static_cast<unsigned char>(c);
    const int at = m_length;
    m_mayBeReply = m_mayBeReply && replyAllows(at, b);
    m_mayBeCommand = m_mayBeCommand && commandAllows(at, b);
    if (!m_mayBeReply && !m_mayBeCommand) {
        m_frame[size_t(m_length++)] = c;
        reject();
        return;
    }
    m_frame[size_t(m_length++)] = c;
    const bool replyDone = m_mayBeReply && m_length == replySize(m_dialect);
    if (replyDone || (m_mayBeCommand && m_length == kCommandSize))
        complete();
}

// The held bytes are no frame: the start byte joins the junk and the rest is
// read again, since a real frame may begin inside them. The recursion is as
// deep as a frame is long at most.
void Parser::reject()
{
    const std::array<char, kCommandSize> held = m_frame;
    const int n = m_length;
    m_length = 0;
    ++m_junk;
    if (m_textLength < kTextCap)
        m_text[size_t(m_textLength++)] = held[0]; // 'W', printable
    for (int i = 1; i < n; ++i)
        push(held[size_t(i)]);
}

void Parser::flushJunk()
{
    if (m_junk == 0)
        return;
    Frame &f = next();
    if (m_junkIsText && m_textLength > 0) {
        f.kind = Frame::Kind::Text;
        f.text.assign(QByteArrayView(m_text.data(), m_textLength));
        if (m_junk > kTextCap)
            f.reason = "text line longer than 128 bytes, cut";
    } else {
        f.kind = Frame::Kind::Skipped;
        f.skipped = m_junk;
        f.reason = "bytes outside a frame";
    }
    m_junk = 0;
    m_junkIsText = true;
    m_textLength = 0;
}

void Parser::complete()
{
    // What came before this frame without a line end is reported first.
    if (m_junk > 0) {
        m_junkIsText = false; // a line cut short by a frame is not a whole text line
        flushJunk();
    }
    if (m_mayBeReply && m_length == replySize(m_dialect))
        decodeReply();
    else
        decodeCommand();
    m_length = 0;
}

void Parser::decodeReply()
{
    Frame &f = next();
    f.kind = Frame::Kind::Reply;
    if (m_dialect == Dialect::Rot1Prog) {
        f.azimuth = digits(m_frame, 1, 3, 0) - 360.0;
    } else {
        f.azimuth = digits(m_frame, 1, 4, 0) / 10.0 - 360.0;
        f.elevation = digits(m_frame, 6, 4, 0) / 10.0 - 360.0;
        f.azimuthPulses = m_frame[5];
        f.elevationPulses = m_frame[10];
    }
    if (const char *why = positionRefusal(f.azimuth, f.elevation, m_dialect)) {
        f.kind = Frame::Kind::Refused;
        f.reason = why;
        f.outOfRange = true;
        return;
    }
    if (m_dialect != Dialect::Rot1Prog) {
        m_azimuthPulses = f.azimuthPulses;
        m_elevationPulses = f.elevationPulses;
    }
}

void Parser::decodeCommand()
{
    Frame &f = next();
    f.kind = Frame::Kind::Command;
    f.command = Command(std::uint8_t(m_frame[11]));
    f.azimuthPulses = m_frame[5];
    f.elevationPulses = m_frame[10];
    auto refuse = [&f](const char *why) {
        f.kind = Frame::Kind::Refused;
        f.reason = why;
    };
    if (f.command == Command::Move) {
        f.moveDirections = m_frame[1];
        if (m_dialect != Dialect::Md01)
            refuse("a move command, which only the MD-01/02 have");
        else if (!encodeMove(f.moveDirections, m_dialect).ok())
            refuse("a move naming no direction, or both of one axis");
        return;
    }
    if (f.command != Command::Set)
        return;
    if (m_dialect == Dialect::Rot1Prog) {
        // Whole degrees in H1..H3, tenths in H4 (Hamlib writes '0' there).
        const int h = digits(m_frame, 1, 4, '0');
        if (h < 0)
            return refuse("a set whose azimuth digits are not ASCII digits");
        f.azimuth = h / 10.0 - 360.0;
    } else {
        const int h = digits(m_frame, 1, 4, '0');
        const int v = digits(m_frame, 6, 4, '0');
        if (h < 0 || v < 0)
            return refuse("a set whose digits are not ASCII digits");
        if (!isResolution(f.azimuthPulses) || !isResolution(f.elevationPulses))
            return refuse("a set whose PH or PV is not 1, 2, 4 or 10 pulses per degree");
        f.azimuth = double(h) / f.azimuthPulses - 360.0;
        f.elevation = double(v) / f.elevationPulses - 360.0;
    }
    if (const char *why = positionRefusal(f.azimuth, f.elevation, m_dialect)) {
        refuse(why);
        f.outOfRange = true;
    }
}

void Parser::finish()
{
    if (m_length > 0) {
        m_junk += m_length;
        m_junkIsText = false;
        m_length = 0;
    }
    flushJunk();
}

} // namespace slew::protocol::spid
