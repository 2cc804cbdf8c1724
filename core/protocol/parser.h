// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Incremental Easycomm reader: bytes in, messages out.
//
// Tokens are separated by space, CR, LF (any mix, so CRLF works) and by ';',
// which Hamlib's get_conf leaves on the wire (`GS\n;`). The parser keeps only a
// fixed buffer: a token longer than InlineText::Capacity is dropped up to the
// next separator and reported once as an Invalid message, after which the
// parser is in sync again. Nothing here throws or allocates.
//
// Feeding the same bytes one at a time, all at once or in random chunks gives
// the same messages, because the state moves one byte at a time.
//
// A token ended by a space is handed out when the next non-space byte arrives
// (then Message::lineEnd tells whether its line ended). Every real peer ends
// its lines with CR or LF, so nothing waits for long; flush() ends a line by hand.
//
// rotctld is read a whole line at a time instead (parser_rotctld.cpp): its
// answers are lines (`RPRT 0`, `180.00`, a model name with spaces), and the
// two lines of a `p` answer are handed out together once both have arrived.
// Micro-2g is read a whole line at a time too (parser_micro2g.cpp): its
// answers are lines with spaces in them.
// The SPID dialects are binary frames: spid::Parser (spidparser.h) reads
// them, and this parser hands its frames out as messages
// (parser_spid.cpp), so that code that reads messages needs no second path.

#include "dialect.h"
#include "message.h"
#include "spidparser.h"

#include <QByteArrayView>

#include <array>
#include <concepts>
#include <new>

namespace slew::protocol {

class Parser {
public:
    explicit Parser(Dialect dialect = Dialect::Easycomm3) : m_dialect(dialect), m_spid(dialect) {}

    Dialect dialect() const { return m_dialect; }
    void setDialect(Dialect d)
    {
        m_dialect = d;
        m_spid.setDialect(d);
    }

    // Calls sink(const Message &) for every message the bytes complete.
    template <typename Sink>
    void feed(QByteArrayView bytes, Sink &&sink)
    {
        if (!readsTokens()) { // rotctld and Micro-2g lines, SPID frames
            for (char c : bytes)
                handOut(push(c), sink);
            return;
        }
        for (qsizetype at = 0; at < bytes.size();) {
            // A token goes in as a run: one call, not one a byte.
            at += appendTokenRun(bytes.sliced(at));
            if (at == bytes.size())
                break;
            handOut(push(bytes[at++]), sink);
        }
    }

    // Ends the current token as if a line end had arrived (for a link that
    // closes without a final newline).
    template <typename Sink>
    void flush(Sink &&sink)
    {
        handOut(isSpid(m_dialect) ? flushSpid() : push('\n'), sink);
    }

    void reset();
    // SPID: the resolution (pulses per degree) of the last reply, 0 before
    // any. A set must be written in the same pulses the controller counts.
    int spidAzimuthPulses() const { return m_spid.azimuthPulses(); }
    int spidElevationPulses() const { return m_spid.elevationPulses(); }

    // Bytes of a line are held that no line end has completed yet.
    bool hasUnfinishedLine() const
    {
        return m_length > 0 || m_overflow || m_hasPending || m_holdingAzimuth || m_spid.hasUnfinishedFrame();
    }

    // Parses one token on its own, with no line context (tests, the console).
    static Message parseToken(QByteArrayView token, Dialect d);

private:
    // What one token reads as: usually one message, two for GS-232's
    // `C2`, `S` and `+0aaa+0eee` (and for rotctld's lines `P 10 20`, `p`, `S`).
    struct Classified {
        Classified() = default;
        Classified(const Message &one) : first(one) {}
        Classified(const Message &one, const Message &two) : first(one), second(two), count(2) {}
        Message first;
        Message second;
        int count = 1;
    };

    // Whether the dialect is read a token at a time (Easycomm, GS-232),
    // rather than a line (rotctld, Micro-2g) or a frame (SPID).
    bool readsTokens() const
    {
        return m_dialect != Dialect::Rotctld && m_dialect != Dialect::Micro2g && !isSpid(m_dialect);
    }
    int push(char c); // returns how many messages are ready
    // In a dialect read in tokens: appends the bytes up to the next
    // separator (or the token's capacity), which push() would take one by
    // one with nothing to deliver; returns how many it took.
    qsizetype appendTokenRun(QByteArrayView bytes);
    void finishToken(bool lineEnd);
    int readToken(QByteArrayView token);
    void emitPending(bool lineEnd);
    bool pendingWaitsForArgument() const;
    Classified classify(QByteArrayView token) const;
    Message classifyEasycomm(QByteArrayView token) const;
    Classified classifyGs232(QByteArrayView token) const;
    int pushRotctld(char c);
    void finishRotctldLine();
    Classified classifyRotctld(QByteArrayView line) const;
    int pushMicro2g(char c);
    Classified classifyMicro2g(QByteArrayView line) const;
    int pushSpid(char c);
    int flushSpid();
    void deliverSpid(const spid::Frame &f);

    // Messages are made in a ring of slots and handed out from there: the
    // ready ones first, then the slot where the next message is built (and
    // where a pending one is held). A message is some 200 bytes; copying it
    // two or three times on its way out took some 15 % of the parser's time.
    // The ready array this replaced had 16 slots for one byte's messages (a
    // SPID byte may release a rejected frame's text lines); the ring holds
    // a pending message besides, so it has 32, a power of two so that it
    // wraps with a mask.
    static constexpr unsigned kSlots = 32;
    Message &slot(int i) { return m_slots[(m_firstReady + unsigned(i)) % kSlots]; }
    const Message &slot(int i) const { return m_slots[(m_firstReady + unsigned(i)) % kSlots]; }
    Message &nextSlot() { return slot(m_readyCount); }
    const Message &nextSlot() const { return slot(m_readyCount); }
    // Builds the message make() returns right in the next slot: a returned
    // Message initializes the slot itself, with no copy on the way.
    template <typename Make>
    void build(Make &&make)
    {
        ::new (static_cast<void *>(&nextSlot())) Message(make());
    }
    // The message in the next slot is ready.
    void publish(bool lineEnd)
    {
        nextSlot().lineEnd = lineEnd;
        ++m_readyCount;
    }
    // Builds the message make() returns in the next slot, ready (SPID's
    // frames).
    template <std::invocable Make>
    void deliver(Make &&make, bool lineEnd)
    {
        moveHeldOutOfTheWay();
        build(make);
        publish(lineEnd);
    }
    // The same for a message made elsewhere, a copy (the readers that
    // classify into a Classified: GS-232, rotctld, Micro-2g).
    void deliver(const Message &m, bool lineEnd)
    {
        moveHeldOutOfTheWay();
        nextSlot() = m;
        publish(lineEnd);
    }
    // Only another dialect's reader delivers while a message is held (the
    // dialect changed in the middle of a line): the held one moves up a
    // slot, so that it is still there should the dialect change back.
    void moveHeldOutOfTheWay()
    {
        if (m_hasPending)
            slot(m_readyCount + 1) = nextSlot();
    }
    // Hands the n ready messages to sink and frees their slots; a pending
    // message stays where it is, now the first slot after the ready ones.
    template <typename Sink>
    void handOut(int n, Sink &sink)
    {
        for (int i = 0; i < n; ++i)
            sink(static_cast<const Message &>(slot(i)));
        m_firstReady = (m_firstReady + unsigned(n)) % kSlots;
        m_readyCount = 0;
    }

    Dialect m_dialect;
    std::array<char, InlineText::Capacity> m_token{};
    int m_length = 0;
    bool m_overflow = false;
    bool m_tokenUnprintable = false; // a byte outside printable ASCII was taken into m_token
    // A token ended by a space is held in nextSlot() until the next byte
    // tells whether its line ended, so that `AZ EL \n` is known to be one line.
    bool m_hasPending = false;
    // GS-232's `W010 020`: the held azimuth waits for its elevation.
    bool m_pendingWantsElevation = false;
    // Line context: the mode word after UPnnn / DNnnn (Easycomm I).
    Op m_previousOnLine = Op::Invalid;
    bool m_previousHadValue = false;
    // Line context: the token before was a bare signed azimuth (K3NG's
    // Easycom `+59.1 +24.8`), so a second one is the elevation.
    bool m_previousBareAzimuth = false;
    // rotctld: the first line of a `p` answer, waiting for its second.
    bool m_holdingAzimuth = false;
    bool m_azimuthBroken = false; // that first line was not a number (already reported)
    double m_heldAzimuth = 0.0;
    spid::Parser m_spid;
    std::array<Message, kSlots> m_slots;
    unsigned m_firstReady = 0;
    int m_readyCount = 0;
};

} // namespace slew::protocol
