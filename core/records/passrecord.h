// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One pass as the station keeps it after the pass: what was tracked, when
// it was up, how well the antenna followed it, and how it ended; and the
// antenna's path beside the target's, a few samples a second. Values only:
// the store (passrecordstore.h) writes and reads them.

#include <QDateTime>
#include <QList>
#include <QString>

#include <optional>

namespace slew::records {

// How a pass ended. InProgress while it is written; a record still in
// progress when a store opens was left by a Slew that stopped mid-pass and
// becomes Interrupted.
enum class Outcome { InProgress, Tracked, Interrupted, Dropped };

// The words stored in the `outcome` column: "in progress", "tracked",
// "interrupted", "dropped".
QString outcomeName(Outcome outcome);
std::optional<Outcome> outcomeFromName(const QString &name);

// What is known of a pass before it is tracked (or dropped).
struct PassPlanned {
    QString target;              // "FLOCK 2P-1", "sun", "azel:200,30"
    std::optional<int> norad;    // a satellite's catalogue number; none for anything else
    QDateTime aos, tca, los;     // UTC, by the station clock (a rehearsal's own time)
    std::optional<double> maxElevationDeg;
    std::optional<double> plannedWorstDeg; // the planner's predicted worst pointing error
    bool rehearsal = false;      // by a rehearsal clock, not the real time
};

// What was measured. Anything not measured (no radio, no reading after the
// settling time) is none, and stored as NULL, as is anything not a finite
// number.
struct PassFigures {
    std::optional<double> rmsDeg;
    std::optional<double> worstDeg;
    std::optional<int> commands;
    std::optional<double> dopplerRmsHz;
    std::optional<double> dopplerWorstHz;
};

struct PassRecord {
    qint64 id = 0;
    PassPlanned planned;
    PassFigures figures;
    Outcome outcome = Outcome::InProgress;
    QString reason;              // why it was interrupted or dropped; empty when tracked
    QDateTime recorded;          // wall-clock UTC when the record was begun: its age for pruning
    QDateTime ended;             // station-clock UTC when it was finished
    int samples = 0;             // pass_samples rows kept for it
};

// One moment of a pass: where the antenna pointed (the rotator's reading,
// in its own terms: an azimuth past 360° on an overlap rotator, an
// elevation past 90° on a flip) and where the target was, and the angle
// between them on the sky.
struct PassSample {
    qint64 unixMs = 0;           // station-clock time, ms since 1970 UTC
    double antennaAzDeg = 0;
    double antennaElDeg = 0;
    double targetAzDeg = 0;
    double targetElDeg = 0;
    double errorDeg = 0;
};

// The ranges a stored value must lie in to be believed when read back (a
// file edited by hand, or damaged): anything else is taken as not there.
bool plausibleSample(const PassSample &sample);

// Text as it is stored and read back: trimmed, and cut to `chars` with an
// ellipsis.
QString boundedText(const QString &text, int chars);

// "2018-01-22T09:17:51.250Z": how times are stored (sorts as text, reads
// in any sqlite3 shell); nothing for an invalid time.
QString storedTime(const QDateTime &utc);
// The time a column holds, or an invalid QDateTime for anything else.
QDateTime timeFromStored(const QString &text);

} // namespace slew::records
