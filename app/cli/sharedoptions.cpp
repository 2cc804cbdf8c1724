// SPDX-License-Identifier: GPL-3.0-or-later
#include "sharedoptions.h"

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
    const QString profileOption = QStringLiteral("profile"), limitsOption = QStringLiteral("limits");
    if (parser.isSet(profileOption)) {
        QString why;
        auto loaded = model::RotatorProfile::load(parser.value(profileOption), &why);
        if (!loaded) {
            *error = QStringLiteral("%1: %2").arg(label(profileOption), why);
            return false;
        }
        *profile = *loaded;
    }
    if (parser.isSet(limitsOption)) {
        const QString text = parser.value(limitsOption);
        QString why;
        const auto limits = station::parseLimits(text, &why);
        if (!limits) {
            *error = QStringLiteral("%1 %2: %3").arg(label(limitsOption), shownValue(text), why);
            return false;
        }
        profile->limits = *limits;
    }
    return true;
}

std::optional<StationClockOptions> readStationClockOptions(const QCommandLineParser &parser,
                                                           const OptionLabel &label, QString *error)
{
    const QString clockStart = QStringLiteral("clock-start"), clockRate = QStringLiteral("clock-rate");
    StationClockOptions clock;
    if (parser.isSet(clockStart)) {
        clock.startJulian = sky::julianFromIso(parser.value(clockStart));
        if (!clock.startJulian) {
            *error = QStringLiteral("%1 %2: expected an ISO 8601 time, as 2024-06-20T12:00:00Z")
                         .arg(label(clockStart), shownValue(parser.value(clockStart)));
            return std::nullopt;
        }
    }
    if (parser.isSet(clockRate)) {
        QString why;
        const auto value = input::numberIn(parser.value(clockRate), {1, tracking::StationClock::kMaxRate, ""}, &why);
        if (!value || !clock.startJulian) {
            *error = QStringLiteral("%1: %2").arg(label(clockRate), value ? QStringLiteral("needs --clock-start")
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
    const QString db = QStringLiteral("pass-db"), keep = QStringLiteral("pass-keep-days");
    PassRecordOptions options;
    options.keepDays = records::PassRecordStore::kDefaultKeepDays;
    if (parser.isSet(db)) {
        options.path = parser.value(db).trimmed();
        if (options.path.isEmpty()) {
            *error = QStringLiteral("%1: name a file").arg(label(db));
            return std::nullopt;
        }
    }
    if (parser.isSet(keep)) {
        QString why;
        const auto days = input::wholeNumberIn(parser.value(keep), 1, records::PassRecordStore::kMaxKeepDays, &why);
        if (!days) {
            *error = QStringLiteral("%1: %2 (days, 1 to %3)").arg(label(keep), why).arg(records::PassRecordStore::kMaxKeepDays);
            return std::nullopt;
        }
        options.keepDays = *days;
    }
    return options;
}

} // namespace slew::cli
