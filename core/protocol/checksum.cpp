// SPDX-License-Identifier: GPL-3.0-or-later
#include "checksum.h"

namespace slew::protocol {

namespace {

constexpr char kHex[] = "0123456789ABCDEF";

int hexValue(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    return -1;
}

bool isLineEnd(char c)
{
    return c == '\r' || c == '\n';
}

} // namespace

std::uint8_t xorChecksum(QByteArrayView bytes)
{
    std::uint8_t sum = 0;
    for (char c : bytes)
        sum ^= std::uint8_t(c);
    return sum;
}

QByteArray withChecksums(QByteArrayView bytes)
{
    QByteArray out;
    out.reserve(bytes.size() + bytes.size() / 4 + 4);
    qsizetype lineStart = 0;
    auto frame = [&](qsizetype end) {
        const QByteArrayView line = bytes.sliced(lineStart, end - lineStart);
        out += line;
        if (line.isEmpty())
            return;
        const std::uint8_t sum = xorChecksum(line);
        out += '*';
        out += kHex[sum >> 4];
        out += kHex[sum & 0x0f];
    };
    for (qsizetype i = 0; i < bytes.size(); ++i) {
        if (!isLineEnd(bytes[i]))
            continue;
        frame(i);
        out += bytes[i];
        lineStart = i + 1;
    }
    if (lineStart < bytes.size())
        frame(bytes.size());
    return out;
}

FrameCheck checkLine(QByteArrayView line, QByteArrayView *payload)
{
    if (line.size() < 3 || line[line.size() - 3] != '*')
        return FrameCheck::Missing;
    const int high = hexValue(line[line.size() - 2]);
    const int low = hexValue(line[line.size() - 1]);
    const QByteArrayView body = line.first(line.size() - 3);
    if (high < 0 || low < 0 || xorChecksum(body) != std::uint8_t(high << 4 | low))
        return FrameCheck::Bad;
    if (payload)
        *payload = body;
    return FrameCheck::Good;
}

const char *describe(FrameCheck check)
{
    switch (check) {
    case FrameCheck::Good: return "checksum good";
    case FrameCheck::Missing: return "no checksum";
    case FrameCheck::Bad: return "wrong checksum";
    case FrameCheck::Overlong: return "line too long to check";
    }
    return "";
}

} // namespace slew::protocol
