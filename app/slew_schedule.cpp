// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --schedule`: argument parsing and printing; the planning is in
// core/schedule. The options are described in cli/.

#include "slew_schedule.h"

#include "cli/argvoptions.h"
#include "cli/optionnames.h"
#include "cli/sharedoptions.h"
#include "cli/slewcommandline.h"
#include "cli/trackoptions.h"
#include "slew_identity.h"
#include "slew_sky.h"

#include "input/finitenumber.h"
#include "model/rotatorprofile.h"
#include "schedule/schedule.h"
#include "schedule/scheduletext.h"
#include "sky/elementage.h"
#include "sky/site.h"
#include "sky/utctime.h"
#include "tracking/rotatorreach.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QJsonDocument>

#include <cstdio>

namespace opt = slew::cli::opt;

namespace {

int fail(const QString &message)
{
    std::fprintf(stderr, "slew: %s\n", qPrintable(message));
    return 2;
}

} // namespace

bool wantsSchedule(int argc, char **argv)
{
    return slew::cli::argvHasSwitch(argc, argv, opt::schedule);
}

int runSchedule(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    setUpSlewApplication();
    checkSettingsFile(); // the saved station is read from them
    checkSatelliteNames();
    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewScheduleMode());
    parser.process(app.arguments());
    const slew::cli::OptionLabel label = slew::cli::commandLineLabel;
    QString error;

    if (!parser.isSet(opt::track))
        return fail(QStringLiteral("--schedule needs --track, once for each target, the first the highest priority"));
    const auto targets = slew::cli::readTrackTargets(parser, label, &error);
    if (!targets)
        return fail(error);
    slew::sky::Site station;
    if (const QString problem = readSkyStation(parser, true, &station); !problem.isEmpty())
        return fail(problem);

    slew::model::RotatorProfile profile;
    if (!slew::cli::readProfileOptions(parser, label, &profile, &error))
        return fail(error);

    slew::schedule::ScheduleSettings settings;
    settings.startJulian = slew::sky::julianNow();
    if (parser.isSet(opt::start)) {
        const auto start = slew::sky::julianFromIso(parser.value(opt::start));
        if (!start)
            return fail(QStringLiteral("--start wants an ISO 8601 time such as 2024-06-20T12:00:00Z, not '%1'")
                            .arg(slew::cli::shownValue(parser.value(opt::start))));
        settings.startJulian = *start;
    }
    auto number = [&](const QString &option, slew::input::NumberRange range, double *out) {
        if (!parser.isSet(option))
            return true;
        QString why;
        const auto value = slew::input::numberIn(parser.value(option), range, &why);
        if (!value) {
            error = QStringLiteral("%1: %2").arg(label(option), why);
            return false;
        }
        *out = *value;
        return true;
    };
    if (!number(opt::hours, {0.1, 168, " hours"}, &settings.hours)
        || !number(opt::minEl, {-5, 90, "°"}, &settings.minElevationDeg)
        || !number(opt::guard, {0, 3600, " s"}, &settings.guardSeconds)
        || !number(opt::maxElementAge,
                   {slew::sky::kLeastElementAgeLimitDays, slew::sky::kMostElementAgeLimitDays, " days"},
                   &settings.maxElementAgeDays))
        return fail(error);

    const slew::schedule::Schedule plan =
        slew::schedule::planSchedule(*targets, station, slew::tracking::reachOf(profile.limits, profile.motion), settings);
    if (parser.isSet(opt::json)) {
        QJsonObject json = slew::schedule::scheduleToJson(plan);
        json.insert(QStringLiteral("station"), slew::sky::describeSite(station));
        if (station.horizon)
            json.insert(QStringLiteral("horizon"), station.horizon->describe());
        std::fputs(QJsonDocument(json).toJson(QJsonDocument::Indented).constData(), stdout);
        return 0;
    }
    std::printf("%s\n", qPrintable(slew::sky::describeSite(station)));
    if (station.horizon)
        std::printf("horizon mask: %s\n", qPrintable(station.horizon->describe()));
    for (int i = 0; i < plan.targets.size(); ++i)
        std::printf("priority %d: %s\n", i + 1, qPrintable(plan.targets[i]));
    for (const slew::schedule::ScheduledPass &p : plan.passes)
        std::printf("%s\n", qPrintable(slew::schedule::describeScheduledPass(p)));
    for (const QString &note : plan.notes)
        std::printf("%s\n", qPrintable(note));
    std::printf("%s\n", qPrintable(slew::schedule::describeScheduleSummary(plan)));
    return 0;
}
