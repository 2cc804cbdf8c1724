// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --passes` and `slew --where`: argument parsing and printing; the
// astronomy is in core/sky. The options are described in cli/.

#include "slew_sky.h"

#include "cli/argvoptions.h"
#include "cli/elementsetoption.h"
#include "cli/optionnames.h"
#include "cli/sharedoptions.h"
#include "cli/slewcommandline.h"
#include "slew_identity.h"

#include "sky/observation.h"
#include "sky/passes.h"
#include "sky/utctime.h"
#include "sky/sgp4.h"
#include "sky/site.h"
#include "sky/sunmoon.h"
#include "sky/elementsetformat.h"

#include "input/finitenumber.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSettings>
#include <QTimeZone>

#include <cstdio>
#include <optional>

using namespace slew::sky;
namespace opt = slew::cli::opt;

namespace {

int fail(const QString &message)
{
    std::fprintf(stderr, "slew: %s\n", qPrintable(message));
    return 2;
}

void say(const QString &line)
{
    std::fprintf(stdout, "%s\n", qPrintable(line));
}

QDateTime fromJulian(double julian)
{
    return utcFromJulian(julian);
}

QString isoTime(double julian)
{
    return isoUtc(julian);
}

QString tableTime(double julian)
{
    return fromJulian(julian).toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
}

std::optional<double> parseTime(const QString &text)
{
    return julianFromIso(text);
}

double nowJulian()
{
    return julianNow();
}

struct Common {
    Site station;
    double julian = 0;
    QList<ElementSet> sets;
    QString origin; // where the sets came from: --tle's file, or the cache
};

} // namespace

QString readSkyStation(const QCommandLineParser &parser, bool withHorizon, Site *out)
{
    // The station from --qth, else the one the window saved (Sky → Station…).
    QString error;
    bool saved = false;
    if (parser.isSet(opt::qth)) {
        if (!parseSite(parser.value(opt::qth), out, &error))
            return QStringLiteral("--qth: %1").arg(error);
    } else {
        const QString text = QSettings().value(QLatin1String(kSiteSettingsKey)).toString();
        if (text.isEmpty())
            return QStringLiteral("--qth is needed: LAT,LON[,HEIGHT_M] or a Maidenhead locator "
                                  "(or set the station in the window: Sky → Station…)");
        if (!parseSite(text, out, &error))
            return QStringLiteral("the saved station \"%1\": %2 (give --qth)").arg(text, error);
        saved = true;
    }
    if (!withHorizon)
        return {};
    // Its horizon: --horizon, else the one the window keeps with the saved
    // station (not with another named by --qth).
    QString path = parser.value(opt::horizon);
    QString from = slew::cli::commandLineLabel(opt::horizon);
    if (!parser.isSet(opt::horizon) && saved) {
        path = QSettings().value(QLatin1String(kHorizonSettingsKey)).toString();
        from = QStringLiteral("the saved station's horizon mask");
    }
    if (path.isEmpty())
        return {};
    const HorizonFile read = readHorizonFile(path);
    if (!read.mask)
        return QStringLiteral("%1: %2").arg(from, read.error);
    out->horizon = read.mask;
    return {};
}

namespace {

// The options both modes share: the station, a time, the element file.
QString readCommon(const QCommandLineParser &parser, const QString &timeOption, bool needTle, Common *out,
                   bool withHorizon)
{
    if (const QString problem = readSkyStation(parser, withHorizon, &out->station); !problem.isEmpty())
        return problem;
    QString error;
    out->julian = nowJulian();
    if (parser.isSet(timeOption)) {
        const auto t = parseTime(parser.value(timeOption));
        if (!t)
            return QStringLiteral("--%1 wants an ISO 8601 time such as 2024-06-20T12:00:00Z, not '%2'")
                .arg(timeOption, parser.value(timeOption));
        out->julian = *t;
    }
    // The sun and the moon need no element sets: the cache is not read for them.
    if (!needTle && !parser.isSet(opt::tle))
        return {};
    const auto sets = slew::cli::readElementSetOption(parser, slew::cli::commandLineLabel, &error);
    if (!sets)
        return error;
    for (const QString &skipped : sets->skipped)
        std::fprintf(stderr, "slew: %s\n", qPrintable(skipped));
    std::fprintf(stderr, "slew: element sets from %s\n", qPrintable(sets->origin));
    out->sets = sets->sets;
    out->origin = sets->origin;
    return {};
}

std::optional<SkyBody> bodyNamed(const QString &name)
{
    if (name.compare(QStringLiteral("sun"), Qt::CaseInsensitive) == 0)
        return SkyBody::Sun;
    if (name.compare(QStringLiteral("moon"), Qt::CaseInsensitive) == 0)
        return SkyBody::Moon;
    return std::nullopt;
}

// One satellite by number or name; the message says why not.
const ElementSet *pickSatellite(const QList<ElementSet> &sets, const QString &query, QString *error)
{
    const ElementSet *tle = findOneSatellite(sets, query, error);
    if (!tle && error->startsWith(QStringLiteral("no satellite")))
        *error += QStringLiteral(" in the element sets");
    return tle;
}

QJsonObject pointJson(const PassPoint &p, bool withElevation)
{
    QJsonObject o{{QStringLiteral("time"), isoTime(p.julian)},
                  {QStringLiteral("azimuth"), std::round(p.azimuthDeg * 10) / 10}};
    if (withElevation)
        o.insert(QStringLiteral("elevation"), std::round(p.elevationDeg * 10) / 10);
    return o;
}

void printPasses(const QList<Pass> &passes, bool json, bool bodies)
{
    if (json) {
        QJsonArray array;
        for (const Pass &p : passes) {
            QJsonObject o{{QStringLiteral("name"), p.name},
                          {QStringLiteral("aos"), pointJson(p.aos, false)},
                          {QStringLiteral("tca"), pointJson(p.tca, true)},
                          {QStringLiteral("los"), pointJson(p.los, false)},
                          {QStringLiteral("max_elevation"), std::round(p.maxElevationDeg() * 10) / 10},
                          {QStringLiteral("duration_s"), std::round(p.durationSeconds())},
                          {QStringLiteral("aos_clipped"), p.aosClipped},
                          {QStringLiteral("los_clipped"), p.losClipped}};
            if (!bodies) {
                o.insert(QStringLiteral("catalogue_number"), p.catalogueNumber);
                o.insert(QStringLiteral("sunlit"), p.sunlit);
            }
            array.append(o);
        }
        std::fputs(QJsonDocument(array).toJson(QJsonDocument::Indented).constData(), stdout);
        return;
    }
    const QString header = bodies ? QStringLiteral("%1  %2  %3  %4  %5  %6  %7  %8")
                                        .arg(QStringLiteral("Body"), -6)
                                        .arg(QStringLiteral("Rise (UTC)"), -19)
                                        .arg(QStringLiteral("Az"), 5)
                                        .arg(QStringLiteral("Culmination"), -19)
                                        .arg(QStringLiteral("El"), 5)
                                        .arg(QStringLiteral("Set (UTC)"), -19)
                                        .arg(QStringLiteral("Az"), 5)
                                        .arg(QStringLiteral("Hours"))
                                  : QStringLiteral("%1  %2  %3  %4  %5  %6  %7  %8  %9")
                                        .arg(QStringLiteral("Satellite"), -20)
                                        .arg(QStringLiteral("AOS (UTC)"), -19)
                                        .arg(QStringLiteral("Az"), 5)
                                        .arg(QStringLiteral("TCA (UTC)"), -19)
                                        .arg(QStringLiteral("Max el"), 6)
                                        .arg(QStringLiteral("LOS (UTC)"), -19)
                                        .arg(QStringLiteral("Az"), 5)
                                        .arg(QStringLiteral("Min"), 5)
                                        .arg(QStringLiteral("Sunlit"));
    say(header);
    for (const Pass &p : passes) {
        if (bodies) {
            say(QStringLiteral("%1  %2  %3  %4  %5  %6  %7  %8")
                    .arg(p.name, -6)
                    .arg(tableTime(p.aos.julian) + (p.aosClipped ? QStringLiteral("*") : QString()), -19)
                    .arg(p.aos.azimuthDeg, 5, 'f', 0)
                    .arg(tableTime(p.tca.julian), -19)
                    .arg(p.tca.elevationDeg, 5, 'f', 1)
                    .arg(tableTime(p.los.julian) + (p.losClipped ? QStringLiteral("*") : QString()), -19)
                    .arg(p.los.azimuthDeg, 5, 'f', 0)
                    .arg(p.durationSeconds() / 3600.0, 5, 'f', 2));
            continue;
        }
        say(QStringLiteral("%1  %2  %3  %4  %5  %6  %7  %8  %9")
                .arg(p.name.left(20), -20)
                .arg(tableTime(p.aos.julian) + (p.aosClipped ? QStringLiteral("*") : QString()), -19)
                .arg(p.aos.azimuthDeg, 5, 'f', 0)
                .arg(tableTime(p.tca.julian), -19)
                .arg(p.tca.elevationDeg, 6, 'f', 1)
                .arg(tableTime(p.los.julian) + (p.losClipped ? QStringLiteral("*") : QString()), -19)
                .arg(p.los.azimuthDeg, 5, 'f', 0)
                .arg(p.durationSeconds() / 60.0, 5, 'f', 1)
                .arg(p.sunlit ? QStringLiteral("yes") : QStringLiteral("no")));
    }
    if (passes.isEmpty())
        say(QStringLiteral("(no passes)"));
}

int runPasses(QCoreApplication &app)
{
    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewPassesMode());
    parser.process(app);
    const QString target = parser.value(opt::passes).trimmed();
    if (target.isEmpty())
        return fail(QStringLiteral("--passes needs a satellite, \"all\", \"sun\" or \"moon\""));
    const std::optional<SkyBody> body = bodyNamed(target);

    Common common;
    const QString error = readCommon(parser, opt::start, !body, &common, true);
    if (!error.isEmpty())
        return fail(error);
    QString why;
    double hours = 24.0;
    if (parser.isSet(opt::hours)) {
        const auto value = slew::input::numberIn(parser.value(opt::hours), {0.1, 720, " hours"}, &why);
        if (!value)
            return fail(QStringLiteral("--hours: %1").arg(why));
        hours = *value;
    }
    // AOS and LOS where the elevation crosses --aos-el (the horizon, as the
    // window's pass table has them, or the almanac's rise and set); a pass
    // is listed when its highest point climbs to --min-el.
    double aosEl = body ? kRiseSetElevationDeg : 0.0;
    double minEl = body ? kRiseSetElevationDeg : 10.0;
    for (const auto &[option, out] : {std::pair{opt::aosEl, &aosEl}, std::pair{opt::minEl, &minEl}}) {
        if (!parser.isSet(option))
            continue;
        const auto value = slew::input::numberIn(parser.value(option), {-5, 90, "°"}, &why);
        if (!value)
            return fail(QStringLiteral("%1: %2").arg(slew::cli::commandLineLabel(option), why));
        *out = *value;
    }
    const PassWindow window{common.julian, common.julian + hours / 24.0, aosEl, nullptr, minEl};
    const bool json = parser.isSet(opt::json);

    if (body) {
        printPasses(predictBodyPasses(*body, common.station, window), json, true);
        return 0;
    }
    if (target.compare(QStringLiteral("all"), Qt::CaseInsensitive) == 0) {
        if (common.sets.isEmpty())
            return fail(QStringLiteral("no element sets could be read from %1").arg(common.origin));
        // A set that reads but cannot be propagated (decayed, absurd drag)
        // has no passes: say so, rather than let "(no passes)" stand for it.
        QList<ElementSet> usable;
        for (const ElementSet &t : common.sets) {
            const Sgp4Error initial = Sgp4(t).initialError();
            if (initial == Sgp4Error::None)
                usable.append(t);
            else
                std::fprintf(stderr, "slew: %s (%d) cannot be propagated: %s; skipped\n", qPrintable(t.displayName()),
                             t.catalogueNumber, qPrintable(sgp4ErrorText(initial)));
        }
        if (usable.isEmpty())
            return fail(QStringLiteral("none of the element sets from %1 can be propagated").arg(common.origin));
        printPasses(predictPasses(usable, common.station, window), json, false);
        return 0;
    }
    const ElementSet *tle = pickSatellite(common.sets, target, &why);
    if (!tle) {
        std::fprintf(stderr, "slew: %s\n", qPrintable(why));
        return 1;
    }
    const Sgp4 sat(*tle);
    if (sat.initialError() != Sgp4Error::None) {
        std::fprintf(stderr, "slew: %s cannot be propagated: %s\n", qPrintable(tle->displayName()),
                     qPrintable(sgp4ErrorText(sat.initialError())));
        return 1;
    }
    printPasses(predictPasses(sat, common.station, window), json, false);
    return 0;
}

int runWhere(QCoreApplication &app)
{
    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewWhereMode());
    parser.process(app);
    const QString target = parser.value(opt::where).trimmed();
    if (target.isEmpty())
        return fail(QStringLiteral("--where needs a satellite, \"sun\" or \"moon\""));
    const std::optional<SkyBody> body = bodyNamed(target);
    Common common;
    const QString error = readCommon(parser, opt::time, !body, &common, false);
    if (!error.isEmpty())
        return fail(error);
    const bool refraction = parser.isSet(opt::refraction);

    QJsonObject out{{QStringLiteral("time"), isoTime(common.julian)}};
    LookAngles look;
    if (body) {
        const BodyPosition p = bodyPosition(*body, common.station, common.julian);
        look.azimuthDeg = p.azimuthDeg;
        look.elevationDeg = p.elevationDeg;
        // Range from the station, rate by a one-second difference.
        const Vec3 station = siteEarthFixed(common.station);
        auto rangeAt = [&](double julian) {
            const BodyPosition q = bodyPosition(*body, common.station, julian);
            const double ra = radians(q.rightAscensionDeg), dec = radians(q.declinationDeg);
            const Vec3 geocentric = Vec3{std::cos(dec) * std::cos(ra), std::cos(dec) * std::sin(ra), std::sin(dec)}
                                    * q.distanceKm;
            const double g = gmstIau82(julian);
            const Vec3 stationInertial{station.x * std::cos(g) - station.y * std::sin(g),
                                       station.x * std::sin(g) + station.y * std::cos(g), station.z};
            return (geocentric - stationInertial).norm();
        };
        look.rangeKm = rangeAt(common.julian);
        look.rangeRateKmS = rangeAt(common.julian + 0.5 / kSecondsPerDay) - rangeAt(common.julian - 0.5 / kSecondsPerDay);
        out.insert(QStringLiteral("name"), *body == SkyBody::Sun ? QStringLiteral("Sun") : QStringLiteral("Moon"));
    } else {
        QString why;
        const ElementSet *tle = pickSatellite(common.sets, target, &why);
        if (!tle) {
            std::fprintf(stderr, "slew: %s\n", qPrintable(why));
            return 1;
        }
        const Sgp4 sat(*tle);
        const Sgp4State s = sat.propagateToJulian(common.julian);
        if (!s.ok()) {
            std::fprintf(stderr, "slew: %s cannot be propagated to %s: %s\n", qPrintable(tle->displayName()),
                         qPrintable(isoTime(common.julian)), qPrintable(sgp4ErrorText(s.error)));
            return 1;
        }
        look = lookAngles(common.station, s.positionKm, s.velocityKmS, common.julian);
        const Geodetic under = subSatellitePoint(s.positionKm, common.julian);
        out.insert(QStringLiteral("name"), tle->displayName());
        out.insert(QStringLiteral("catalogue_number"), tle->catalogueNumber);
        out.insert(QStringLiteral("sub_latitude"), under.latitudeDeg);
        out.insert(QStringLiteral("sub_longitude"), under.longitudeDeg);
        out.insert(QStringLiteral("altitude_km"), under.heightKm);
        out.insert(QStringLiteral("sunlit"), isSunlit(s.positionKm, sunVectorEquatorial(common.julian)));
        out.insert(QStringLiteral("element_age_days"), common.julian - sat.epochJulian());
    }
    if (refraction)
        look.elevationDeg += refractionDeg(look.elevationDeg);
    // Never a NaN printed as an answer: a position that is not a number is a
    // failure, said as one.
    bool allNumbers = slew::input::allFinite(look.azimuthDeg, look.elevationDeg, look.rangeKm, look.rangeRateKmS);
    for (const QJsonValue &v : out)
        allNumbers = allNumbers && (!v.isDouble() || std::isfinite(v.toDouble()));
    if (!allNumbers) {
        std::fprintf(stderr, "slew: %s at %s: the position computed is not a number; no answer\n",
                     qPrintable(out.value(QStringLiteral("name")).toString()), qPrintable(isoTime(common.julian)));
        return 1;
    }
    out.insert(QStringLiteral("azimuth"), look.azimuthDeg);
    out.insert(QStringLiteral("elevation"), look.elevationDeg);
    out.insert(QStringLiteral("range_km"), look.rangeKm);
    out.insert(QStringLiteral("range_rate_km_s"), look.rangeRateKmS);
    out.insert(QStringLiteral("refraction"), refraction);

    if (parser.isSet(opt::json)) {
        std::fputs(QJsonDocument(out).toJson(QJsonDocument::Indented).constData(), stdout);
        return 0;
    }
    say(QStringLiteral("%1 at %2").arg(out.value(QStringLiteral("name")).toString(), isoTime(common.julian)));
    say(QStringLiteral("azimuth    %1°").arg(look.azimuthDeg, 0, 'f', 3));
    say(QStringLiteral("elevation  %1°%2").arg(look.elevationDeg, 0, 'f', 3)
            .arg(refraction ? QStringLiteral(" (refracted)") : QString()));
    say(QStringLiteral("range      %1 km").arg(look.rangeKm, 0, 'f', 3));
    say(QStringLiteral("range-rate %1 km/s").arg(look.rangeRateKmS, 0, 'f', 4));
    if (!body) {
        say(QStringLiteral("beneath    %1°, %2°, %3 km up")
                .arg(out.value(QStringLiteral("sub_latitude")).toDouble(), 0, 'f', 3)
                .arg(out.value(QStringLiteral("sub_longitude")).toDouble(), 0, 'f', 3)
                .arg(out.value(QStringLiteral("altitude_km")).toDouble(), 0, 'f', 1));
        say(QStringLiteral("sunlit     %1").arg(out.value(QStringLiteral("sunlit")).toBool() ? QStringLiteral("yes")
                                                                                          : QStringLiteral("no")));
    }
    return 0;
}

} // namespace

bool wantsSky(int argc, char **argv)
{
    return slew::cli::argvHasOption(argc, argv, opt::passes) || slew::cli::argvHasOption(argc, argv, opt::where);
}

int runSky(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    setUpSlewApplication();
    checkSettingsFile(); // the saved station is read from them
    checkSatelliteNames();
    return slew::cli::argvHasOption(argc, argv, opt::passes) ? runPasses(app) : runWhere(app);
}
