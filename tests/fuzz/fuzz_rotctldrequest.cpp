// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: the rotctld request parser and its answers.
//
// Input: what a client sends. It is cut into lines the way RotctldServer
// cuts it (CR or LF ends a line, longer than kMaxLine is refused unread),
// each line is parsed, and each request is answered in every form the
// server uses. Checked besides crashes and sanitizer reports: a refused line
// always says why, a set_pos carries finite angles, and every answer ends
// with a line break (a tracker reads answers line by line).
//
// Built with libFuzzer when SLEW_FUZZ is on (packaging/dev.sh fuzz); the
// normal build replays the seed corpus through it (corpusreplay.cpp).

#include "bridge/rotctldrequest.h"
#include "bridge/rotctldserver.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

using namespace slew::bridge;
using Kind = RotctldRequest::Kind;

namespace {

[[noreturn]] void fail(const char *what)
{
    std::fprintf(stderr, "fuzz_rotctldrequest: %s\n", what);
    std::abort();
}

void endsWithNewline(const QByteArray &answer)
{
    if (!answer.endsWith('\n'))
        fail("an answer that does not end its line");
}

void parseAndAnswer(QByteArrayView line)
{
    const RotctldRequest r = parseRotctldLine(line);
    switch (r.kind) {
    case Kind::Unknown:
    case Kind::Malformed:
        if (r.error.isEmpty())
            fail("a refused line without a reason");
        break;
    case Kind::SetPosition:
        if (!std::isfinite(r.az) || !std::isfinite(r.el))
            fail("set_pos with an angle that is not finite");
        break;
    default:
        break;
    }
    if (r.extended && r.separator != '\n' && r.separator != ';' && r.separator != '|' && r.separator != ',')
        fail("an extended answer separator rotctld does not use");
    endsWithNewline(formatStatus(r, 0));
    endsWithNewline(formatStatus(r, int(HamlibError::Rejected)));
    endsWithNewline(formatPosition(r, r.az, r.el));
    endsWithNewline(formatInfo(r, QStringLiteral("Slew")));
    // RotctldLink names the code in a peer's `RPRT n`, which can be any int;
    // the reset type is an int the client chose, so it stands in for one.
    (void)describeHamlibError(r.resetType);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArrayView bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    qsizetype start = 0;
    for (qsizetype i = 0; i <= bytes.size(); ++i) {
        if (i < bytes.size() && bytes[i] != '\n' && bytes[i] != '\r')
            continue;
        const QByteArrayView line = bytes.sliced(start, i - start);
        if (!line.isEmpty() && line.size() <= RotctldServer::kMaxLine)
            parseAndAnswer(line);
        start = i + 1;
    }
    return 0;
}
