// SPDX-License-Identifier: GPL-3.0-or-later
#include "sharedoptions.h"

#include "optionnames.h"

#include "station/serviceconfig.h"
#include "input/finitenumber.h"
#include "input/logtext.h"
#include "records/passrecordstore.h"
#include "sky/utctime.h"
#include "tracking/stationclock.h"

#include <QCommandLineParser>

namespace slew::cli {

QString commandLineLabel(const QString &longName)
{
    return QStringLiteral("--") + longName;
}

QString shownValue(const QString &text)
{
    return input::loggableText(text, 80);
}

bool readProfileOptions(const QCommandLineParser &parser, const OptionLabel &label, model::RotatorProfile *profile,
                        QString *error)
{
    if (parser.isSet(opt::profile)) {
        QString why;
        auto loaded = model::RotatorProfile::load(parser.value(opt::profile), &why);
        if (!loaded) {
            *error = QStringLiteral("%1: %2").arg(label(opt::profile), why);
            return false;
        }
        *profile = *loaded;
    }
    if (parser.isSet(opt::limits)) {
        const QString text = parser.value(opt::limits);
        QString why;
        const auto limits = station::parseLimits(text, &why);
        if (!limits) {
            *error = QStringLiteral("%1 %2: %3").arg(label(opt::limits), shownValue(text), why);
            return false;
        }
        profile->limits = *limits;
    }
    return true;
}

std::optional<StationClockOptions> readStationClockOptions(const QCommandLineParser &parser,
                                                           const OptionLabel &label, QString *error)
{
    StationClockOptions clock;
    if (parser.isSet(opt::clockStart)) {
        clock.startJulian = sky::julianFromIso(parser.value(opt::clockStart));
        if (!clock.startJulian) {
            *error = QStringLiteral("%1 %2: expected an ISO 8601 time, as 2024-06-20T12:00:00Z")
                         .arg(label(opt::clockStart), shownValue(parser.value(opt::clockStart)));
            return std::nullopt;
        }
    }
    if (parser.isSet(opt::clockRate)) {
        QString why;
        const auto value = input::numberIn(parser.value(opt::clockRate), {1, tracking::StationClock::kMaxRate, ""}, &why);
        if (!value || !clock.startJulian) {
            *error = QStringLiteral("%1: %2").arg(label(opt::clockRate), value ? QStringLiteral("needs --clock-start")
                                                                               : why + QStringLiteral(" (1 to %1)").arg(tracking::StationClock::kMaxRate));
            return std::nullopt;
        }
        clock.rate = *value;
    }
    return clock;
}

std::optional<PassRecordOptions> readPassRecordOptions(const QCommandLineParser &parser, const OptionLabel &label,
                                                       QString *error)
{
    PassRecordOptions options;
    options.keepDays = records::PassRecordStore::kDefaultKeepDays;
    if (parser.isSet(opt::passDb)) {
        options.path = parser.value(opt::passDb).trimmed();
        if (options.path.isEmpty()) {
            *error = QStringLiteral("%1: name a file").arg(label(opt::passDb));
            return std::nullopt;
        }
    }
    if (parser.isSet(opt::passKeepDays)) {
        QString why;
        const auto days = input::wholeNumberIn(parser.value(opt::passKeepDays), 1, records::PassRecordStore::kMaxKeepDays, &why);
        if (!days) {
            *error = QStringLiteral("%1: %2 (days, 1 to %3)").arg(label(opt::passKeepDays), why).arg(records::PassRecordStore::kMaxKeepDays);
            return std::nullopt;
        }
        options.keepDays = *days;
    }
    return options;
}

} // namespace slew::cli
