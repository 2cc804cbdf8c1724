// SPDX-License-Identifier: GPL-3.0-or-later
// Tracking figures: Slew's planner and tracker against Gpredict-style
// tracking on the same passes and the same simulated rotators.
//
// Five real passes over JO65hq from the element sets in tests/data (a low
// pass, a 60° pass, two within 3° of the zenith, and one over the north
// stop, where trackers go the long way round), two simulated G-5500 class
// rotators (6.2°/s azimuth, 2.7°/s elevation; 360°/90° and 450°/180° of
// travel), on the simulator's manual clock, so a pass runs in a second or
// two and the figures do not depend on how busy the machine is.
//
//  - Slew: the pass planned before AOS, pre-positioned, followed with the
//    lead and minimum step the profile's motion gives (0.51 s, 0.5°).
//  - Gpredict-style: no planner; once a second the pass's bearing and
//    elevation go through Slew's rotctld server as `P az el` when either
//    differs from the rotator's reading by more than Gpredict's default
//    tolerance (5°), as Gpredict's antenna control does; `p` reads it.
//    And the same tuned as a careful user does: every 500 ms, 0.5°.
//
// Pointing error is the angle on the sky between where the antenna points
// and where the satellite is, over every position reading from AOS + 5 s
// to LOS. End-stop hits count the times the rotator reached a limit switch;
// unwinds, whole turns of azimuth commanded beyond what the sky travels.
//
// Each pass also gets its floor: the least worst error any path can keep
// whose azimuth turns at 6.2°/s (acceleration aside; leastworstswing.h),
// and, for a path that does not turn half a turn (over the top), the miss
// of the zenith. Slew's figures are to be read against it.

#include "bridge/rotctldserver.h"
#include "common/simulatorpump.h"
#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "sim/simulator.h"
#include "sky/tleformat.h"
#include "sky/passes.h"
#include "sky/elementsetformat.h"
#include "tracking/leastworstswing.h"
#include "tracking/skytrack.h"
#include "tracking/rotatorreach.h"
#include "tracking/tracker.h"

#include <QCoreApplication>
#include <QFile>
#include <QTcpSocket>

#include <cmath>
#include <cstdio>

using namespace slew;
using session::RotatorSession;
using tracking::SkyPoint;

namespace {

constexpr double kSettle = tracking::Tracker::kSettleSeconds;
// Gpredict's antenna control at its defaults (a 1000 ms cycle, 5°
// tolerance), and as a careful user tunes it (500 ms, 0.5°).
struct GpredictSettings {
    double cycleS;
    double toleranceDeg;
};
constexpr GpredictSettings kGpredictDefaults{1.0, 5.0};
constexpr GpredictSettings kGpredictTuned{0.5, 0.5};

struct Figures {
    double rms = 0, worst = 0;
    int samples = 0;
    int endStopHits = 0;
    int unwinds = 0;
    int commands = 0;
    double passSeconds = 0;
};

struct PassCase {
    const char *name;
    sky::ElementSet tle;
    sky::Pass pass;
    QList<SkyPoint> points;
};

sky::Site station()
{
    sky::Site s;
    s.latitudeDeg = 55.6875; // JO65hq
    s.longitudeDeg = 12.625;
    return s;
}

bool crossesNorth(const QList<SkyPoint> &points)
{
    for (int i = 1; i < points.size(); ++i) {
        if (std::abs(points[i].azimuthDeg - points[i - 1].azimuthDeg) > 180)
            return true;
    }
    return false;
}

// The first pass of each kind in the two days after the snapshot's epoch;
// the low and the 60° one do not cross north, so a 360° rotator can follow them.
QList<PassCase> findPasses()
{
    QFile file(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QList<sky::ElementSet> sets = sky::readTleText(QString::fromLatin1(file.readAll())).sets;
    double epoch = 0;
    for (const sky::ElementSet &t : sets)
        epoch = std::max(epoch, t.epochJulian());
    struct Want {
        const char *name;
        double low, high;
        bool mayCrossNorth;
        bool mustCrossNorth = false;
    };
    const Want wants[] = {{"low (max el 8-15°)", 8, 15, false},
                          {"60° (57-63°)", 57, 63, false},
                          {"near zenith (>87°)", 87, 91, true},
                          {"over the north stop (30-70°)", 30, 70, true, true},
                          // The first near-zenith pass culminates 0.5° from
                          // the zenith; over the top, the error grows with
                          // that miss, so a second one farther from it too.
                          {"1-3° from the zenith (87-89°)", 87, 89, true}};
    QList<PassCase> found;
    for (const Want &w : wants) {
        // A pass that stays clear of north first; one over it only if there is none.
        std::optional<PassCase> overNorth;
        std::optional<PassCase> chosen;
        for (const sky::ElementSet &t : sets) {
            const sky::Sgp4 sat(t);
            for (const sky::Pass &p : sky::predictPasses(sat, station(), sky::PassWindow{epoch, epoch + 2.0, 0.0})) {
                if (p.aosClipped || p.losClipped || p.maxElevationDeg() < w.low || p.maxElevationDeg() > w.high)
                    continue;
                const QList<SkyPoint> points = tracking::sampleSatellitePass(sat, station(), p, 1.0);
                if (w.mustCrossNorth ? crossesNorth(points) : !crossesNorth(points))
                    chosen = PassCase{w.name, t, p, points};
                else if (w.mayCrossNorth && !overNorth)
                    overNorth = PassCase{w.name, t, p, points};
                if (chosen)
                    break;
            }
            if (chosen)
                break;
        }
        if (!chosen)
            chosen = overNorth;
        if (chosen)
            found.append(*chosen);
    }
    return found;
}

SkyPoint skyAt(const QList<SkyPoint> &pass, double seconds)
{
    if (seconds <= pass.front().seconds)
        return pass.front();
    if (seconds >= pass.back().seconds)
        return pass.back();
    const int i = std::min(int(pass.size()) - 2, int(seconds - pass.front().seconds)); // 1 s steps
    const SkyPoint &a = pass[i], &b = pass[i + 1];
    const double f = (seconds - a.seconds) / (b.seconds - a.seconds);
    const double turn = std::fmod(b.azimuthDeg - a.azimuthDeg + 540.0, 360.0) - 180.0;
    return SkyPoint{seconds, std::fmod(a.azimuthDeg + f * turn + 360.0, 360.0),
                    a.elevationDeg + f * (b.elevationDeg - a.elevationDeg)};
}

// One simulated G-5500 on its manual clock, and the measurements every run takes.
class Rig {
public:
    // `relay`: the simulator's relay motor control, and a profile that says so
    // (the tracker's 2° step for relays unless `relayStep` says otherwise).
    Rig(double azMax, double elMax, bool relay = false, double relayStep = 0)
    {
        model::RotatorProfile profile;
        profile.limits = model::RotatorLimits{0, azMax, 0, elMax};
        profile.parkAz = 0;
        profile.parkEl = 0;
        if (relay) {
            profile.motion.drive = model::RotatorMotion::Drive::Relay;
            profile.motion.trackStepDeg = relayStep;
        }
        session.setProfile(profile);
        session.connectTo(QStringLiteral("sim:?clock=manual&az_max=%1&el_max=%2%3")
                              .arg(azMax)
                              .arg(elMax)
                              .arg(relay ? QStringLiteral("&control=relay") : QString()));
        pump.follow(&session);
        runEventLoopUntil([&] { return session.capabilities().probed && session.hasPosition(); }, 10000);
        sim = sim::simulatorBehind(session.link());
        // The profile's motion is the g5500 model's (docs/simulator.md), as
        // the tuning step measures it.
        reach = tracking::reachOf(session);
        QObject::connect(&session, &RotatorSession::targetChanged, &session, [this](double az, double) {
            if (measuring && lastTarget)
                commandedTravel += std::abs(az - *lastTarget);
            if (measuring)
                ++figures.commands;
            lastTarget = az;
        });
        QObject::connect(&session, &RotatorSession::positionChanged, &session, [this](double az, double el, bool stale) {
            if (!measuring || stale)
                return;
            const double t = seconds();
            if (t < kSettle || t > pass.back().seconds)
                return;
            const SkyPoint target = skyAt(pass, t);
            const double e = tracking::skyAngleDeg(az, el, target.azimuthDeg, target.elevationDeg);
            ++figures.samples;
            sumSquares += e * e;
            figures.worst = std::max(figures.worst, e);
            figures.rms = std::sqrt(sumSquares / figures.samples);
        });
        // A limit switch closing during the pass is a hit.
        QObject::connect(&sim->clock(), &sim::SimClock::advanced, &session, [this] {
            const bool on = sim->rotator().axis(sim::Axis::Azimuth).limitSwitches() != 0
                            || sim->rotator().axis(sim::Axis::Elevation).limitSwitches() != 0;
            if (on && !onSwitch && measuring && seconds() >= 0)
                ++figures.endStopHits;
            onSwitch = on;
        });
    }

    // Seconds from AOS on the simulator's clock.
    double seconds() const { return sim->clock().now() - aosAtSim; }
    void runUntil(double secondsFromAos)
    {
        runEventLoopUntil([&] { return seconds() >= secondsFromAos; }, 120000);
    }

    RotatorSession session;
    SimulatorPump pump{0.02};
    sim::Simulator *sim = nullptr;
    tracking::RotatorReach reach;
    QList<SkyPoint> pass;
    double aosAtSim = 0;
    bool measuring = false;
    bool onSwitch = false;
    std::optional<double> lastTarget;
    double commandedTravel = 0; // degrees of azimuth commanded during the pass
    Figures figures;

    // Unwinds: whole turns of azimuth commanded beyond what the sky travels
    // (a jump across the stop, or a sweep spread out ahead of it).
    void countUnwinds()
    {
        double skyTravel = 0;
        for (int i = 1; i < pass.size(); ++i)
            skyTravel += std::abs(std::fmod(pass[i].azimuthDeg - pass[i - 1].azimuthDeg + 540.0, 360.0) - 180.0);
        figures.unwinds = std::max(0, int(std::floor((commandedTravel - skyTravel + 180.0) / 360.0)));
    }
    double sumSquares = 0;
};

Figures runSlew(const PassCase &c, double azMax, double elMax, tracking::PassPlan *plan, bool relay = false,
                double relayStep = 0)
{
    Rig rig(azMax, elMax, relay, relayStep);
    rig.pass = c.points;
    rig.aosAtSim = rig.sim->clock().now() + 150; // room to pre-position
    tracking::Tracker tracker(&rig.session);
    tracking::TrackerSettings settings;
    settings.afterPass = tracking::TrackerSettings::AfterPass::Stay;
    tracker.setSettings(tracking::trackerSettingsFor(rig.session.profile().motion, settings));
    const double aosJulian = c.pass.aos.julian;
    tracker.track(c.points, aosJulian, rig.reach, [&rig, aosJulian] { return aosJulian + rig.seconds() / 86400.0; });
    *plan = tracker.plan();
    rig.runUntil(0);
    rig.measuring = true;
    rig.runUntil(c.points.back().seconds + 1);
    rig.figures.passSeconds = c.points.back().seconds;
    rig.countUnwinds();
    return rig.figures;
}

// Gpredict's antenna control, through Slew's rotctld server: once a cycle,
// read the position; when either axis is more than the tolerance off the
// satellite, send the satellite's bearing and elevation.
Figures runGpredictStyle(const PassCase &c, double azMax, double elMax, GpredictSettings settings,
                         bool relay = false)
{
    Rig rig(azMax, elMax, relay);
    rig.pass = c.points;
    rig.aosAtSim = rig.sim->clock().now() + 150;
    bridge::RotctldServer server(&rig.session);
    QString error;
    server.listen(QHostAddress::LocalHost, 0, &error);
    QTcpSocket client;
    client.connectToHost(QHostAddress::LocalHost, server.port());
    runEventLoopUntil([&] { return client.state() == QAbstractSocket::ConnectedState; }, 5000);
    QByteArray replies;
    QObject::connect(&client, &QTcpSocket::readyRead, &client, [&] { replies += client.readAll(); });
    auto ask = [&](const QByteArray &line) {
        replies.clear();
        client.write(line + '\n');
        runEventLoopUntil([&] { return replies.count('\n') >= (line == "p" ? 2 : 1); }, 5000);
        return replies;
    };
    // Before AOS Gpredict points at where the satellite will rise, as Slew does.
    for (double t = -120; t <= c.points.back().seconds; t += settings.cycleS) {
        rig.runUntil(t);
        rig.measuring = t >= 0;
        const QList<QByteArray> position = ask("p").split('\n');
        const double az = position.value(0).toDouble(), el = position.value(1).toDouble();
        const SkyPoint sat = skyAt(c.points, std::max(0.0, rig.seconds()));
        // Gpredict compares the numbers as they are: 359° and 1° are 358° apart.
        if (std::abs(sat.azimuthDeg - std::fmod(az + 360.0, 360.0)) > settings.toleranceDeg
            || std::abs(sat.elevationDeg - el) > settings.toleranceDeg)
            ask(QStringLiteral("P %1 %2").arg(sat.azimuthDeg, 0, 'f', 2).arg(std::max(0.0, sat.elevationDeg), 0, 'f', 2).toLatin1());
    }
    rig.figures.passSeconds = c.points.back().seconds;
    rig.countUnwinds();
    return rig.figures;
}

void print(const char *who, const Figures &f)
{
    std::printf("    %-16s RMS %7.3f°  worst %7.2f°  end-stop hits %d  unwinds %d  commands %.2f/s\n", who, f.rms, f.worst,
                f.endStopHits, f.unwinds, f.passSeconds > 0 ? f.commands / f.passSeconds : 0.0);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    registerLinkSchemes();
    const QList<PassCase> passes = findPasses();
    if (passes.size() != 5) {
        std::fprintf(stderr, "bench_tracking: found %d of the 5 passes\n", int(passes.size()));
        return 1;
    }
    for (const PassCase &c : passes) {
        std::printf("%s: %s, max el %.1f°, %.0f s\n", c.name, qPrintable(c.tle.name), c.pass.maxElevationDeg(),
                    c.pass.durationSeconds());
        std::printf("  floor: %.2f° for any path turning the azimuth at 6.2°/s; over the top, at least %.1f°\n",
                    tracking::leastWorstFloorDeg(c.points, 6.2), 90.0 - c.pass.maxElevationDeg());
        for (const auto &[azMax, elMax] : {std::pair{360.0, 90.0}, std::pair{450.0, 180.0}}) {
            std::printf("  %g°/%g° rotator\n", azMax, elMax);
            tracking::PassPlan plan;
            const Figures slew = runSlew(c, azMax, elMax, &plan);
            std::printf("    plan: %s\n", qPrintable(plan.describe()));
            print("Slew", slew);
            print("Gpredict-style", runGpredictStyle(c, azMax, elMax, kGpredictDefaults));
            print("  tuned", runGpredictStyle(c, azMax, elMax, kGpredictTuned));
        }
    }
    // A relay drive (full speed or off) on the 60° pass: the tracker's relay
    // step (1°) and a coarser one.
    std::printf("%s, relay drive (on beyond 0.5° from the target, off within 0.1°), 450°/180°\n", passes[1].name);
    for (double step : {0.0, 2.0}) {
        tracking::PassPlan plan;
        const Figures relay = runSlew(passes[1], 450, 180, &plan, true, step);
        print(step == 0 ? "Slew, 1° step" : "Slew, 2° step", relay);
    }
    print("Gpredict-style", runGpredictStyle(passes[1], 450, 180, kGpredictDefaults, true));
    print("  tuned", runGpredictStyle(passes[1], 450, 180, kGpredictTuned, true));
    // Without an elevation axis past 90°, how fast an azimuth axis must be
    // to follow the near-zenith pass.
    const PassCase &zenith = passes[2];
    std::printf("%s: the planner's predicted worst by azimuth speed (360°/90°, half a second to full speed)\n", zenith.name);
    for (double rate : {6.2, 10.0, 15.0, 20.0, 30.0, 40.0}) {
        tracking::RotatorReach reach;
        reach.limits = model::RotatorLimits{0, 360, 0, 90};
        reach.azimuthRateDegS = rate;
        reach.elevationRateDegS = 2.7;
        reach.azimuthAccelDegS2 = rate / 0.5;
        reach.elevationAccelDegS2 = 6.0;
        const tracking::PassPlan plan = tracking::planPass(zenith.points, reach);
        std::printf("  %5.1f°/s: worst %5.2f°\n", rate, plan.predictedWorstDeg);
    }
    return 0;
}
