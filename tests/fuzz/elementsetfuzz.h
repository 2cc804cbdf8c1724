// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the element-set fuzz targets check, whatever the form (fuzz_tle,
// fuzz_gpcsv, fuzz_ommxml, fuzz_gpjson, fuzz_ommkvn): besides crashes and
// sanitizer reports, every accepted set carries finite numbers inside the
// ranges the readers promise (a NaN once hung the pass search), every
// refusal names a line of the file (or an entry) and a reason, merging by
// catalogue number leaves each number once, SGP4 either refuses a set or
// propagates it to finite positions, and a set written back out in its
// form reads back to the same set.

#include "sky/elementsetformat.h"
#include "sky/gpcsv.h"
#include "sky/gpjson.h"
#include "sky/ommkvn.h"
#include "sky/ommxml.h"
#include "sky/sgp4.h"
#include "sky/tleformat.h"

#include <QSet>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace slew::fuzz {

[[noreturn]] inline void fail(const char *what)
{
    std::fprintf(stderr, "element-set fuzz target: %s\n", what);
    std::abort();
}

inline bool within(double x, double low, double high)
{
    return std::isfinite(x) && x >= low && x <= high;
}

inline void checkSet(const sky::ElementSet &t)
{
    if (!within(t.inclinationDeg, 0, 180) || !within(t.raanDeg, 0, 360) || !within(t.argPerigeeDeg, 0, 360)
        || !within(t.meanAnomalyDeg, 0, 360))
        fail("an angle that is not finite or out of range");
    if (!within(t.meanMotionRevPerDay, 0, sky::kMostRevolutionsPerDay) || t.meanMotionRevPerDay <= 0)
        fail("a mean motion that is not finite or out of range");
    if (!within(t.eccentricity, 0, 1) || t.eccentricity >= 1)
        fail("an eccentricity outside 0..1");
    if (t.catalogueNumber < 1 || t.catalogueNumber > sky::kLargestCatalogueNumber)
        fail("a catalogue number outside 1..999999999");
    if (!within(t.epochDayFraction, 0, 1) || t.epochDayFraction >= 1 || t.epochJulianDay != std::floor(t.epochJulianDay) + 0.5
        || !within(t.epochJulianDay, 2435839.5, 2816787.5)) // 1957 .. 2999
        fail("an epoch that is not finite or out of range");
    if (!std::isfinite(t.meanMotionDot) || !std::isfinite(t.meanMotionDdot) || !std::isfinite(t.bstar))
        fail("a drag term that is not finite");

    // SGP4 on what the reader let through: refused at set-up, or finite.
    const sky::Sgp4 satellite(t);
    if (satellite.initialError() != sky::Sgp4Error::None)
        return;
    for (const double minutes : {0.0, 90.0, -1440.0, 1440.0 * 7}) {
        const sky::Sgp4State s = satellite.propagate(minutes);
        if (s.ok() && (!std::isfinite(s.positionKm.x) || !std::isfinite(s.positionKm.y) || !std::isfinite(s.positionKm.z)
                       || !std::isfinite(s.velocityKmS.x)))
            fail("SGP4 answered a position that is not finite without an error");
    }
}

inline bool sameSet(const sky::ElementSet &a, const sky::ElementSet &b)
{
    return a.catalogueNumber == b.catalogueNumber && a.name == b.name && a.designator == b.designator
           && a.epochJulianDay == b.epochJulianDay && a.epochDayFraction == b.epochDayFraction
           && a.meanMotionRevPerDay == b.meanMotionRevPerDay && a.eccentricity == b.eccentricity
           && a.inclinationDeg == b.inclinationDeg && a.raanDeg == b.raanDeg && a.argPerigeeDeg == b.argPerigeeDeg
           && a.meanAnomalyDeg == b.meanAnomalyDeg && a.bstar == b.bstar && a.meanMotionDot == b.meanMotionDot
           && a.meanMotionDdot == b.meanMotionDdot && a.revolutionNumber == b.revolutionNumber
           && a.elementSetNumber == b.elementSetNumber;
}

// The checks of one reading: `lines` is the number of lines the text has
// (0 for a form without lines, JSON, whose refusals name an entry).
inline void checkRead(const sky::ElementSetRead &read, qsizetype lines)
{
    for (const sky::ElementSetRefusal &r : read.refusals) {
        if (r.line > 0 ? r.line > lines : r.entry < 1)
            fail("a refusal that names no line or entry of the file");
        if (r.reason.isEmpty())
            fail("a refusal without a reason");
    }
    for (const sky::ElementSet &t : read.sets)
        checkSet(t);
    const QList<sky::ElementSet> merged = sky::mergeByCatalogueNumber(read.sets);
    QSet<int> numbers;
    for (const sky::ElementSet &t : merged) {
        if (numbers.contains(t.catalogueNumber))
            fail("a catalogue number twice after merging");
        numbers.insert(t.catalogueNumber);
    }
    if (merged.size() > read.sets.size())
        fail("merging added sets");
}

// One of the GP readers on the input, then its sets written in the same
// form and read again: the same sets must come back, bit for bit.
inline int fuzzGpReader(const std::uint8_t *data, std::size_t size, sky::ElementSetForm form)
{
    if (size > 64 * 1024)
        return 0; // a few dozen sets say all a larger input would
    const QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    const auto read = [form](const QByteArray &b) {
        switch (form) {
        case sky::ElementSetForm::Csv: return sky::readGpCsv(QString::fromUtf8(b));
        case sky::ElementSetForm::OmmXml: return sky::readOmmXml(b);
        case sky::ElementSetForm::Json: return sky::readGpJson(b);
        case sky::ElementSetForm::OmmKvn: return sky::readOmmKvn(QString::fromUtf8(b));
        case sky::ElementSetForm::Tle: return sky::readTleText(QString::fromUtf8(b));
        }
        return sky::ElementSetRead();
    };
    const sky::ElementSetRead first = read(bytes);
    checkRead(first, bytes.count('\n') + bytes.count('\r') + 1); // a bound: XML counts a bare CR as a line end
    if (form == sky::ElementSetForm::Tle || first.sets.isEmpty())
        return 0;
    const sky::ElementSetRead again = read(sky::writeElementSets(first.sets, form).bytes);
    if (!again.refusals.isEmpty() || again.sets.size() != first.sets.size())
        fail("a set written out does not read back");
    for (qsizetype i = 0; i < first.sets.size(); ++i)
        if (!sameSet(first.sets[i], again.sets[i]))
            fail("a set written out reads back different");
    return 0;
}

} // namespace slew::fuzz
