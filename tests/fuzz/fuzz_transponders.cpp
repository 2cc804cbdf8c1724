// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: both transponder importers (a SatNOGS DB transmitter list
// and a Gpredict .trsp file) on the same bytes, and the set they merge into.
//
// Input: a file's bytes (any bytes: a download, a file a user named).
// Checked besides crashes and sanitizer reports: every transponder let
// through has a catalogue number in range and frequencies that are finite,
// above 0, at most 300 GHz, low <= high, and at least one of them; a
// refused source keeps nothing and says why; the skip messages are capped
// and counted, each naming the source; the uplink that pairs with a
// downlink is finite and inside the uplink's reach; merging keeps each
// transponder once and the default is an alive one of its satellite.
//
// Built with libFuzzer when SLEW_FUZZ is on (packaging/dev.sh fuzz); the
// normal build replays the seed corpus through it (corpusreplay.cpp).

#include "radio/transponderimport.h"
#include "radio/transponderset.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

using namespace slew::radio;

namespace {

[[noreturn]] void fail(const char *what)
{
    std::fprintf(stderr, "fuzz_transponders: %s\n", what);
    std::abort();
}

void checkEdges(const std::optional<double> &low, const std::optional<double> &high)
{
    for (const std::optional<double> &f : {low, high})
        if (f && (!std::isfinite(*f) || *f <= 0 || *f > kHighestFrequencyHz))
            fail("a frequency that is not finite, not above 0 or above 300 GHz");
    if (high && !low)
        fail("a high edge without a low one");
    if (low && high && *low > *high)
        fail("a low edge above its high edge");
}

void checkTransponder(const Transponder &t)
{
    if (t.noradId < 1 || t.noradId > kLargestNoradId)
        fail("a catalogue number out of range");
    checkEdges(t.uplinkLowHz, t.uplinkHighHz);
    checkEdges(t.downlinkLowHz, t.downlinkHighHz);
    if (!t.uplinkLowHz && !t.downlinkLowHz)
        fail("a transponder with no frequency");
    if (!t.isLinear())
        return;
    const double width = *t.downlinkHighHz - *t.downlinkLowHz;
    for (const double f : {*t.downlinkLowHz, *t.downlinkLowHz + width / 3, *t.downlinkHighHz}) {
        const std::optional<double> up = t.uplinkForDownlink(f);
        if (t.hasUplink() != up.has_value())
            fail("a linear transponder with an uplink and no pairing inside its passband");
        if (up && (!std::isfinite(*up) || *up < *t.uplinkLowHz || *up > *t.uplinkLowHz + width))
            fail("a paired uplink outside the uplink's reach");
    }
    if (t.uplinkForDownlink(*t.downlinkHighHz + width + 1) || t.uplinkForDownlink(std::nan("")))
        fail("a pairing outside the passband");
}

void checkImport(const TransponderImport &read)
{
    if (!read.ok() && !read.transponders.isEmpty())
        fail("a refused source that kept transponders");
    if (read.ok() && read.transponders.isEmpty())
        fail("a source with nothing usable that was not refused");
    if (read.skipped.size() > kMostSkipMessages || read.skippedCount < read.skipped.size())
        fail("skip messages past the cap, or miscounted");
    for (const QString &message : read.skipped)
        if (!message.startsWith(QStringLiteral("fuzz: ")))
            fail("a skip message that does not name the source");
    for (const Transponder &t : read.transponders)
        checkTransponder(t);
}

void checkSet(const QList<Transponder> &transponders)
{
    TransponderSet set;
    const int dropped = set.merge(transponders);
    if (set.size() + dropped != transponders.size())
        fail("merging lost or invented transponders");
    if (set.merge(transponders) != transponders.size())
        fail("merging the same transponders twice kept some twice");
    for (const int norad : set.satellites()) {
        // Pairs among the first few: all pairs of thousands would spend the
        // fuzzer's time here.
        const QList<Transponder> held = set.forSatellite(norad).mid(0, 64);
        for (qsizetype i = 0; i < held.size(); ++i)
            for (qsizetype j = i + 1; j < held.size(); ++j)
                if (sameTransponder(held[i], held[j]))
                    fail("a satellite holding the same transponder twice");
        const std::optional<Transponder> chosen = set.defaultFor(norad);
        if (chosen && (!chosen->alive || chosen->noradId != norad))
            fail("a default that is dead or of another satellite");
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size > 64 * 1024)
        return 0; // a few hundred entries say all a larger input would
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    const TransponderImport satnogs = readSatnogsTransmitters(bytes, QStringLiteral("fuzz"));
    checkImport(satnogs);
    const TransponderImport gpredict = readGpredictTrsp(bytes, QStringLiteral("fuzz"), 25544);
    checkImport(gpredict);
    checkSet(satnogs.transponders + gpredict.transponders);
    return 0;
}
