// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Incremental SPID reader: bytes in, frames out, in either direction (host
// commands for the simulator, controller replies for the session), the way
// the Easycomm Parser reads both.
//
// A frame starts at 0x57. Every byte after it is checked as it arrives
// against what a reply or a command of the dialect may hold there (raw
// digits 0..9 in a reply, ASCII digits or zeros in a command, a resolution
// byte of 1, 2, 4 or 10, the end byte 0x20), so a start byte that was only
// garbage, or the 'W' of an MD-01 text line such as "Warning", is dropped as
// soon as the next byte disagrees and the bytes after it are read again.
// Bytes outside frames are either a text line (printable, ended by CR or
// LF: MD-01 firmware interleaves log lines) or skipped garbage, each
// reported once.
//
// Memory is fixed: one frame (13 bytes) and one text line of at most
// InlineText::Capacity bytes; a longer line is cut and reported as overlong,
// and garbage is only counted. Feeding the bytes one at a time, all at once
// or in random chunks gives the same frames. Nothing here throws or
// allocates.

#include "dialect.h"
#include "message.h"
#include "spidcodec.h"

#include <QByteArrayView>

#include <array>
#include <cstdint>

namespace slew::protocol::spid {

struct Frame {
    enum class Kind : std::uint8_t {
        Reply,   // a controller's position (az, el, PH, PV)
        Command, // a host frame: command, and for a set its position and PH/PV
        Text,    // a text line between frames, without its CR LF
        Skipped, // bytes that were neither a frame nor a text line
        Refused, // a whole frame that cannot be acted on (reason says why)
    };
    Kind kind = Kind::Skipped;
    Command command = Command::Status; // Command
    double azimuth = 0.0;              // Reply; Command Set
    double elevation = 0.0;            // Reply; Command Set; 0 for Rot1Prog
    int azimuthPulses = 0;             // PH as received (0 where the frame has none)
    int elevationPulses = 0;           // PV
    int moveDirections = 0;            // Command Move: MoveBit values
    InlineText text;                   // Text
    int skipped = 0;                   // Skipped: how many bytes
    const char *reason = nullptr;      // Skipped, Refused, a cut Text line
    bool outOfRange = false;           // Refused: readable, but outside the SPID ranges
};

class Parser {
public:
    explicit Parser(Dialect dialect = Dialect::Rot2Prog) : m_dialect(dialect) {}

    Dialect dialect() const { return m_dialect; }
    // A new dialect starts afresh; the same one again (a profile applied
    // anew mid-stream) keeps the frame under way and the resolution learnt.
    void setDialect(Dialect d)
    {
        if (d == m_dialect)
            return;
        m_dialect = d;
        reset();
    }

    // Calls sink(const Frame &) for every frame the bytes complete.
    template <typename Sink>
    void feed(QByteArrayView bytes, Sink &&sink)
    {
        for (char c : bytes) {
            push(c);
            deliver(sink);
        }
    }

    // Reports what is held (a part frame, a line without its end) as
    // skipped or text, for a link that closed.
    template <typename Sink>
    void flush(Sink &&sink)
    {
        finish();
        deliver(sink);
    }

    void reset();
    bool hasUnfinishedFrame() const { return m_length > 0 || m_junk > 0; }

    // The resolution of the last reply, 0 before any: pulses per degree.
    int azimuthPulses() const { return m_azimuthPulses; }
    int elevationPulses() const { return m_elevationPulses; }

    // The longest a text line may be before it is cut.
    static constexpr int kTextCap = InlineText::Capacity;

private:
    template <typename Sink>
    void deliver(Sink &sink)
    {
        for (int i = 0; i < m_readyCount; ++i)
            sink(static_cast<const Frame &>(m_ready[size_t(i)]));
        m_readyCount = 0;
    }

    void push(char c);
    void hunt(char c);
    void extend(char c);
    void reject();
    void complete();
    void flushJunk();
    void finish();
    Frame &next();
    bool replyAllows(int at, unsigned char b) const;
    bool commandAllows(int at, unsigned char b) const;
    void decodeReply();
    void decodeCommand();

    Dialect m_dialect;
    // The frame being read, from its 0x57.
    std::array<char, kCommandSize> m_frame{};
    int m_length = 0;
    bool m_mayBeReply = false;
    bool m_mayBeCommand = false;
    // Bytes outside frames since the last report: how many, and the text of
    // the line they may be (up to the cap).
    int m_junk = 0;
    bool m_junkIsText = true;
    std::array<char, kTextCap> m_text{};
    int m_textLength = 0;
    int m_azimuthPulses = 0;
    int m_elevationPulses = 0;
    // One byte can release a held frame's bytes: at most one report per
    // byte read again (line ends) plus the junk before a frame and the frame.
    std::array<Frame, kCommandSize + 3> m_ready;
    int m_readyCount = 0;
};

} // namespace slew::protocol::spid
