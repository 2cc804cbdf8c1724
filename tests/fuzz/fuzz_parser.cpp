// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: the device-side parser, every dialect.
//
// Input: the first byte picks the dialect (counted from '0', modulo the
// number of dialects, so the seed files start with '0'..':': easycomm1,
// easycomm2, easycomm3, satnogs, gs232a, gs232b, rotctld, micro2g, and the
// binary rot2prog '8', rot1prog '9', md01 ':'), the rest is what arrives on
// the wire. Besides "no crash, no sanitizer
// report", it checks what parser.h promises: the same bytes fed all at once
// or one at a time give the same messages, every refusal says why, and no
// message carries more text than InlineText holds. Every message read is
// then encoded again, so the encoder sees what the parser lets through.
//
// Built with libFuzzer when SLEW_FUZZ is on (packaging/dev.sh fuzz); the
// normal build replays the seed corpus through it (corpusreplay.cpp).

#include "protocol/dialect.h"
#include "protocol/encoder.h"
#include "protocol/parser.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace slew::protocol;

namespace {

[[noreturn]] void fail(const char *what)
{
    std::fprintf(stderr, "fuzz_parser: %s\n", what);
    std::abort();
}

void check(const Message &m)
{
    if (m.text.size() < 0 || m.text.size() > InlineText::Capacity)
        fail("message text outside InlineText's capacity");
    if (m.op == Op::Invalid) {
        if (!m.reason || !*m.reason)
            fail("a refused token without a reason");
        if (m.refusal == Refusal::None)
            fail("a refused token without a refusal kind");
        return;
    }
    if (m.hasValue && !std::isfinite(m.value))
        fail("a valid message with a value that is not finite");
    if (m.op == Op::Encoders && m.hasValue) {
        for (double e : m.encoders) {
            if (!std::isfinite(e))
                fail("encoder ticks that are not finite");
        }
    }
}

bool sameMessages(const std::vector<Message> &a, const std::vector<Message> &b)
{
    if (a.size() != b.size())
        return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (!(a[i] == b[i]) || a[i].lineEnd != b[i].lineEnd || a[i].refusal != b[i].refusal)
            return false;
    }
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size < 1)
        return 0;
    const QList<Dialect> &dialects = allDialects();
    const Dialect dialect = dialects.at(std::uint8_t(data[0] - '0') % dialects.size());
    const QByteArrayView bytes(reinterpret_cast<const char *>(data) + 1, qsizetype(size - 1));

    std::vector<Message> whole;
    Parser all(dialect);
    auto keepWhole = [&](const Message &m) { whole.push_back(m); };
    all.feed(bytes, keepWhole);
    all.flush(keepWhole);

    std::vector<Message> bytewise;
    Parser single(dialect);
    auto keepBytewise = [&](const Message &m) { bytewise.push_back(m); };
    for (qsizetype i = 0; i < bytes.size(); ++i)
        single.feed(bytes.sliced(i, 1), keepBytewise);
    single.flush(keepBytewise);

    if (!sameMessages(whole, bytewise))
        fail("feeding all at once and one byte at a time gave different messages");

    for (const Message &m : whole) {
        check(m);
        if (m.isValid()) {
            (void)encodeToken(m, dialect);
            (void)encodeReport(m, dialect);
        }
    }

    // A token on its own, as the traffic console reads it.
    check(Parser::parseToken(bytes.first(std::min<qsizetype>(bytes.size(), 2 * InlineText::Capacity)), dialect));

    // After reset() the parser reads as if new.
    all.reset();
    std::vector<Message> again;
    all.feed(bytes, [&](const Message &m) { again.push_back(m); });
    all.flush([&](const Message &m) { again.push_back(m); });
    if (!sameMessages(whole, again))
        fail("a reset parser read the same bytes differently");
    return 0;
}
