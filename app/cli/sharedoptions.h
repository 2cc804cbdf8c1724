// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The options the window and the station service both take, read once, so
// both accept the same values and refuse the others with the same words:
// --profile and --limits (the rotator for this run), --clock-start and
// --clock-rate (a rehearsal).

#include "model/rotatorprofile.h"

#include <QString>

#include <functional>
#include <optional>

class QCommandLineParser;

namespace slew::cli {

// How a message names an option: "--limits", or the config file and line
// that gave it ("station.conf:4: limits").
using OptionLabel = std::function<QString(const QString &longName)>;

// The label of an option given on the command line: "--name".
QString commandLineLabel(const QString &longName);

// Text from an option or a config file, safe for the terminal and the
// journal.
QString shownValue(const QString &text);

// --profile FILE read into *profile, then --limits over its travel; each
// only when given. False, and why in *error, when either cannot be used.
bool readProfileOptions(const QCommandLineParser &parser, const OptionLabel &label, model::RotatorProfile *profile,
                        QString *error);

// The station clock the command line asks for: a start (a rehearsal) and a
// rate, or no start (the system's UTC, at rate 1).
struct StationClockOptions {
    std::optional<double> startJulian; // --clock-start
    double rate = 1.0;                  // --clock-rate, 1 to tracking::StationClock::kMaxRate
};

// --clock-start ISO8601 and --clock-rate N, which needs --clock-start.
std::optional<StationClockOptions> readStationClockOptions(const QCommandLineParser &parser,
                                                           const OptionLabel &label, QString *error);

// Where passes are recorded (--pass-db FILE; empty: the default file) and
// how long their samples are kept (--pass-keep-days N).
struct PassRecordOptions {
    QString path;
    int keepDays = 90; // records::PassRecordStore::kDefaultKeepDays
};

// --pass-db and --pass-keep-days, each only when given.
std::optional<PassRecordOptions> readPassRecordOptions(const QCommandLineParser &parser, const OptionLabel &label,
                                                       QString *error);

} // namespace slew::cli
