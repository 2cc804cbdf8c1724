// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The optional XOR checksum of the easycom library's feature list. That
// documentation names the checksum but gives no frame, so Slew defines one
// (docs/protocol.md, "Checksum"): `*HH` right before the line terminator,
// HH the XOR of every byte of the line before the `*`, two upper-case hex
// digits (lower case is read too). `AZ EL*0C\n`.
//
// Both ends of a checksummed link frame every line they send and check every
// line they get; a line that does not check is refused whole, never parsed.
// Pure functions and a fixed-buffer line reader: no I/O, no allocation on
// the read path beyond the line handed to the sink.

#include <QByteArray>
#include <QByteArrayView>

#include <array>
#include <cstdint>

namespace slew::protocol {

std::uint8_t xorChecksum(QByteArrayView bytes);

// Adds `*HH` before the terminator of every line in `bytes` (a line ends at
// CR or LF). Empty lines (the LF of a CR LF) stay empty: they carry nothing
// to check. A last line without a terminator is framed too.
QByteArray withChecksums(QByteArrayView bytes);

enum class FrameCheck : std::uint8_t {
    Good,     // `*HH` present and right
    Missing,  // no `*HH` where it belongs
    Bad,      // `*HH` present but wrong, or not hex
    Overlong, // longer than ChecksumReader::Capacity: dropped unread
};

// Checks one line without its terminator; on Good, *payload is the line
// without `*HH`.
FrameCheck checkLine(QByteArrayView line, QByteArrayView *payload);

const char *describe(FrameCheck check);

// Splits a byte stream into lines and checks each. The sink gets
// (FrameCheck, QByteArrayView line): on Good the line without its `*HH` and
// with its terminator, ready for the Parser; otherwise the raw line as
// received (for messages). Empty lines are skipped.
class ChecksumReader {
public:
    static constexpr int Capacity = 256;

    template <typename Sink>
    void feed(QByteArrayView bytes, Sink &&sink)
    {
        for (char c : bytes) {
            if (c != '\r' && c != '\n') {
                if (m_length < Capacity)
                    m_line[size_t(m_length++)] = c;
                else
                    m_overflow = true;
                continue;
            }
            if (m_overflow) {
                m_overflow = false;
                m_length = 0;
                sink(FrameCheck::Overlong, QByteArrayView(m_line.data(), Capacity));
                continue;
            }
            if (m_length == 0)
                continue;
            const QByteArrayView line(m_line.data(), m_length);
            QByteArrayView payload;
            const FrameCheck check = checkLine(line, &payload);
            m_length = 0;
            if (check != FrameCheck::Good) {
                sink(check, line);
                continue;
            }
            // The terminator stays: the Parser ends its tokens on it. The
            // payload is shorter than the line, so it fits in place.
            m_line[size_t(payload.size())] = c;
            sink(FrameCheck::Good, QByteArrayView(m_line.data(), payload.size() + 1));
        }
    }

    bool hasUnfinishedLine() const { return m_length > 0 || m_overflow; }
    void reset()
    {
        m_length = 0;
        m_overflow = false;
    }

private:
    std::array<char, Capacity + 1> m_line{};
    int m_length = 0;
    bool m_overflow = false;
};

} // namespace slew::protocol
