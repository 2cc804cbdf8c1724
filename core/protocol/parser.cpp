// SPDX-License-Identifier: GPL-3.0-or-later
#include "parser.h"

#include "tokentext.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace slew::protocol {

using namespace text;

// Parser::build() makes a message over the one its slot held before,
// without destroying that one first.
static_assert(std::is_trivially_destructible_v<Message>, "a slot's old message must need no destructor");

namespace {

// What each byte is to the token reader, looked up once per byte: a token
// is scanned once for its end and for bytes it may not hold together.
enum ByteClass : std::uint8_t {
    kLineEnd = 1,     // CR, LF
    kSpace = 2,       // ' ', tab, ';' (Hamlib's get_conf writes `GS\n;` and
                      // the `;` then prefixes the next command)
    kUnprintable = 4, // outside printable ASCII
};
constexpr std::array<std::uint8_t, 256> kByteClasses = [] {
    std::array<std::uint8_t, 256> table{};
    for (int c = 0; c < 256; ++c) {
        if (c == '\r' || c == '\n')
            table[size_t(c)] |= kLineEnd;
        if (c == ' ' || c == '\t' || c == ';')
            table[size_t(c)] |= kSpace;
        if (c < 0x21 || c > 0x7e)
            table[size_t(c)] |= kUnprintable;
    }
    return table;
}();

std::uint8_t classOf(char c)
{
    return kByteClasses[static_cast<unsigned char>(c)];
}

bool isLineEnd(char c)
{
    return classOf(c) & kLineEnd;
}

bool isSpace(char c)
{
    return classOf(c) & kSpace;
}

bool isBareConfigRead(const Message &m)
{
    return m.op == Op::ConfigRead && m.index < 0 && !m.hasValue;
}

} // namespace

void Parser::reset()
{
    m_length = 0;
    m_overflow = false;
    m_tokenUnprintable = false;
    m_hasPending = false;
    m_previousOnLine = Op::Invalid;
    m_previousHadValue = false;
    m_previousBareAzimuth = false;
    m_holdingAzimuth = false;
    m_spid.reset();
    m_readyCount = 0;
}

int Parser::push(char c)
{
    if (m_dialect == Dialect::Rotctld)
        return pushRotctld(c);
    if (m_dialect == Dialect::Micro2g)
        return pushMicro2g(c);
    if (isSpid(m_dialect))
        return pushSpid(c);
    if (isLineEnd(c)) {
        if (m_length > 0 || m_overflow)
            finishToken(true);
        else if (m_hasPending)
            emitPending(true);
        m_previousOnLine = Op::Invalid;
        m_previousHadValue = false;
        m_previousBareAzimuth = false;
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
    if (m_length < int(m_token.size())) {
        m_token[size_t(m_length++)] = c;
        m_tokenUnprintable = m_tokenUnprintable || (classOf(c) & kUnprintable);
    } else {
        m_overflow = true;
    }
    return m_readyCount;
}

qsizetype Parser::appendTokenRun(QByteArrayView bytes)
{
    // A token's first byte comes here too, unless a message is pending:
    // push() takes that byte, as it may release the message for feed() to
    // hand out. (The dialect is asked again in case a sink changed it.)
    if ((m_length == 0 && m_hasPending) || m_overflow || !readsTokens())
        return 0;
    const qsizetype room = qsizetype(m_token.size()) - m_length;
    const qsizetype limit = std::min(bytes.size(), room);
    // Copied as it is scanned: tokens are a few bytes, a memcpy call each
    // cost more than the bytes.
    char *to = m_token.data() + m_length;
    qsizetype n = 0;
    std::uint8_t seen = 0;
    for (; n < limit; ++n) {
        const char c = bytes[n];
        const std::uint8_t k = classOf(c);
        if (k & (kLineEnd | kSpace))
            break;
        seen |= k;
        to[n] = c;
    }
    m_length += int(n);
    m_tokenUnprintable = m_tokenUnprintable || (seen & kUnprintable);
    return n;
}

bool Parser::pendingWaitsForArgument() const
{
    return m_hasPending && (isBareConfigRead(nextSlot()) || m_pendingWantsElevation);
}

void Parser::emitPending(bool lineEnd)
{
    m_hasPending = false;
    if (isBareConfigRead(nextSlot())) {
        build([] { return Message::invalid("CR", "config read without a register number"); });
    } else if (m_pendingWantsElevation) {
        m_pendingWantsElevation = false;
        build([] { return Message::invalid("W", "W needs an azimuth and an elevation (W010 020)"); });
    }
    publish(lineEnd);
}

void Parser::finishToken(bool lineEnd)
{
    const QByteArrayView token(m_token.data(), m_length);
    const int count = readToken(token);
    m_tokenUnprintable = false;
    m_length = 0;
    m_overflow = false;
    // The token's (last) message is held in the next slot until its line
    // end is known; a line end hands it out at once.
    const Message &m = nextSlot();
    m_previousOnLine = m.op;
    m_previousHadValue = m.hasValue;
    m_previousBareAzimuth = !isGs232(m_dialect) && m.op == Op::Azimuth && m.hasValue && count == 1
                            && token.size() > 0 && (token[0] == '+' || token[0] == '-');
    m_pendingWantsElevation = isGs232(m_dialect) && m.op == Op::Azimuth && m.hasValue && token.size() > 0
                              && upper(token[0]) == 'W' && count == 1;
    m_hasPending = true;
    if (lineEnd)
        emitPending(true);
}

// Builds what the token reads as in the next slot, after settling the
// pending message (a bare CR or W may take this token as its argument).
// Returns how many messages the token made; of two, the first is ready.
int Parser::readToken(QByteArrayView token)
{
    if (m_overflow) {
        if (m_hasPending) // a bare CR or W waiting for its argument: said, not lost
            emitPending(false);
        build([&] {
            return Message::invalid(token, "token longer than 128 bytes, dropped up to the next separator",
                                    Refusal::Overlong);
        });
        return 1;
    }
    if (m_hasPending && isBareConfigRead(nextSlot()) && allDigits(token) && token.size() <= 5) {
        // SatNOGS: `CR 1` is one command; it takes the bare CR's place.
        m_hasPending = false;
        build([&] { return Message::query(Op::ConfigRead, digitsValue(token)); });
        return 1;
    }
    if (m_hasPending && m_pendingWantsElevation && allDigits(token) && token.size() <= 3) {
        // GS-232: `W010 020` sets both axes.
        m_hasPending = false;
        m_pendingWantsElevation = false;
        publish(false); // the held azimuth
        build([&] { return Message::number(Op::Elevation, digitsValue(token)); });
        return 2;
    }
    if (m_hasPending)
        emitPending(false);
    // The byte loop has looked at every byte already.
    if (m_tokenUnprintable) {
        build([&] { return Message::invalid(token, "unprintable byte in token"); });
        return 1;
    }
    if (isGs232(m_dialect)) {
        const Classified c = classifyGs232(token);
        if (c.count == 2)
            deliver(c.first, false);
        nextSlot() = c.count == 2 ? c.second : c.first;
        return c.count;
    }
    build([&] { return classifyEasycomm(token); });
    return 1;
}

Message Parser::parseToken(QByteArrayView token, Dialect d)
{
    Parser p(d);
    return p.classify(token).first;
}

Parser::Classified Parser::classify(QByteArrayView t) const
{
    // parseToken's way in, a token on its own (the byte loop reads its
    // tokens with readToken, which knows their bytes already). Both
    // readers look at the first byte.
    if (t.isEmpty())
        return {Message::invalid(t, "empty token", Refusal::Unknown)};
    if (m_dialect == Dialect::Rotctld)
        return classifyRotctld(t); // a whole line, spaces and all
    if (m_dialect == Dialect::Micro2g)
        return classifyMicro2g(t);
    if (isSpid(m_dialect))
        return {Message::invalid(t, "SPID is read as binary frames, not tokens")};
    if (!isPrintable(t))
        return {Message::invalid(t, "unprintable byte in token")};
    if (isGs232(m_dialect))
        return classifyGs232(t);
    return {classifyEasycomm(t)};
}

} // namespace slew::protocol
