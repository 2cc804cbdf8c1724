// SPDX-License-Identifier: GPL-3.0-or-later
#include "parser.h"

#include "tokentext.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

namespace slew::protocol {

using namespace text;

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
    m_holdingAzimuth = false;
    m_spid.reset();
    m_readyCount = 0;
}

int Parser::push(char c)
{
    m_readyCount = 0;
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
    if (m_length == 0 || m_overflow || m_dialect == Dialect::Rotctld || m_dialect == Dialect::Micro2g
        || isSpid(m_dialect))
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
    // Built in place (a message is some 200 bytes; copies showed in profiles).
    const Classified c = [&]() -> Classified {
        if (m_overflow) {
            if (m_hasPending) // a bare CR or W waiting for its argument: said, not lost
                emitPending(false);
            return {Message::invalid(token, "token longer than 128 bytes, dropped up to the next separator",
                                     Refusal::Overlong)};
        }
        if (m_hasPending && isBareConfigRead(m_pending) && allDigits(token) && token.size() <= 5) {
            // SatNOGS: `CR 1` is one command.
            m_hasPending = false;
            return {Message::query(Op::ConfigRead, token.toInt())};
        }
        if (m_hasPending && m_pendingWantsElevation && allDigits(token) && token.size() <= 3) {
            // GS-232: `W010 020` sets both axes.
            m_hasPending = false;
            m_pendingWantsElevation = false;
            return {m_pending, Message::number(Op::Elevation, token.toInt())};
        }
        if (m_hasPending)
            emitPending(false);
        return classify(token, m_tokenUnprintable ? TokenBytes::Unprintable : TokenBytes::Printable);
    }();
    m_tokenUnprintable = false;
    m_length = 0;
    m_overflow = false;
    if (c.count == 2)
        deliver(c.first, false);
    const Message &m = c.count == 2 ? c.second : c.first;
    m_previousOnLine = m.op;
    m_previousHadValue = m.hasValue;

    const bool wantsElevation = isGs232(m_dialect) && m.op == Op::Azimuth && m.hasValue && token.size() > 0
                                && upper(token[0]) == 'W' && c.count == 1;
    // The common case, a token that ends its line and waits for nothing,
    // goes out at once rather than through m_pending (one copy, not two).
    if (lineEnd && !wantsElevation && !isBareConfigRead(m)) {
        m_pendingWantsElevation = false;
        deliver(m, true);
        return;
    }
    m_pending = m;
    m_pendingWantsElevation = wantsElevation;
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

Parser::Classified Parser::classify(QByteArrayView t, TokenBytes bytes) const
{
    // The byte loop never hands over an empty token, but parseToken() can;
    // both readers look at the first byte.
    if (t.isEmpty())
        return {Message::invalid(t, "empty token", Refusal::Unknown)};
    if (m_dialect == Dialect::Rotctld)
        return classifyRotctld(t); // a whole line, spaces and all
    if (m_dialect == Dialect::Micro2g)
        return classifyMicro2g(t);
    if (isSpid(m_dialect))
        return {Message::invalid(t, "SPID is read as binary frames, not tokens")};
    // The byte loop has looked at every byte already; a token on its own
    // (parseToken) is looked at here.
    if (bytes == TokenBytes::Unprintable || (bytes == TokenBytes::Unchecked && !isPrintable(t)))
        return {Message::invalid(t, "unprintable byte in token")};
    if (isGs232(m_dialect))
        return classifyGs232(t);
    return {classifyEasycomm(t)};
}

} // namespace slew::protocol
