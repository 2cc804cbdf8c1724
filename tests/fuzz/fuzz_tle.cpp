// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: the element-set reader and what is done with each set it
// accepts.
//
// Input: a file's bytes (any bytes: a download, a cache, a --tle file).
// Checked besides crashes and sanitizer reports: every accepted set carries
// finite numbers inside the ranges the reader promises (a NaN once hung the
// pass search), every refusal names a line of the file and a reason, merging
// by catalogue number leaves each number once, and SGP4 either refuses a set
// or propagates it to finite positions.
//
// Built with libFuzzer when SLEW_FUZZ is on (packaging/dev.sh fuzz); the
// normal build replays the seed corpus through it (corpusreplay.cpp).

#include "sky/sgp4.h"
#include "sky/tle.h"

#include <QSet>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

using namespace slew::sky;

namespace {

[[noreturn]] void fail(const char *what)
{
    std::fprintf(stderr, "fuzz_tle: %s\n", what);
    std::abort();
}

bool within(double x, double low, double high)
{
    return std::isfinite(x) && x >= low && x <= high;
}

void checkSet(const Tle &t)
{
    if (!within(t.inclinationDeg, 0, 180) || !within(t.raanDeg, 0, 360) || !within(t.argPerigeeDeg, 0, 360)
        || !within(t.meanAnomalyDeg, 0, 360))
        fail("an angle that is not finite or out of range");
    if (!within(t.meanMotionRevPerDay, 0, kMostRevolutionsPerDay) || t.meanMotionRevPerDay <= 0)
        fail("a mean motion that is not finite or out of range");
    if (!within(t.eccentricity, 0, 1) || t.eccentricity >= 1)
        fail("an eccentricity outside 0..1");
    if (!within(t.epochDayOfYear, 1, 367) || !std::isfinite(t.epochJulian()))
        fail("an epoch that is not finite or out of range");
    if (!std::isfinite(t.meanMotionDot) || !std::isfinite(t.meanMotionDdot) || !std::isfinite(t.bstar))
        fail("a drag term that is not finite");

    // SGP4 on what the reader let through: refused at set-up, or finite.
    const Sgp4 satellite(t);
    if (satellite.initialError() != Sgp4Error::None)
        return;
    for (const double minutes : {0.0, 90.0, -1440.0, 1440.0 * 7}) {
        const Sgp4State s = satellite.propagate(minutes);
        if (s.ok() && (!std::isfinite(s.positionKm.x) || !std::isfinite(s.positionKm.y) || !std::isfinite(s.positionKm.z)
                       || !std::isfinite(s.velocityKmS.x)))
            fail("SGP4 answered a position that is not finite without an error");
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size > 64 * 1024)
        return 0; // a few dozen sets say all a larger input would
    const QString text = QString::fromUtf8(reinterpret_cast<const char *>(data), qsizetype(size));
    const TleReadResult read = readTleText(text);
    const qsizetype lines = text.count(u'\n') + 1;
    for (const TleRefusal &r : read.refusals) {
        if (r.line < 1 || r.line > lines)
            fail("a refusal that names no line of the file");
        if (r.reason.isEmpty())
            fail("a refusal without a reason");
    }
    for (const Tle &t : read.sets)
        checkSet(t);
    const QList<Tle> merged = mergeByCatalogueNumber(read.sets);
    QSet<int> numbers;
    for (const Tle &t : merged) {
        if (numbers.contains(t.catalogueNumber))
            fail("a catalogue number twice after merging");
        numbers.insert(t.catalogueNumber);
    }
    if (merged.size() > read.sets.size())
        fail("merging added sets");
    return 0;
}
