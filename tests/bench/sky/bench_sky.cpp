// SPDX-License-Identifier: GPL-3.0-or-later
// Sky benchmarks on one core: SGP4 states per second (near-earth and
// deep-space sets from the real snapshot in tests/data) and pass prediction
// for 200 satellites over 7 days. Prints the figures README records, and
// beside them Vallado's C++ SGP4 timed the same way (vallado_reference.py,
// through python3-sgp4 when it has its C++ extension).

#include "sky/tleformat.h"
#include "sky/passes.h"
#include "sky/sgp4.h"
#include "sky/sgp4propagator.h"
#include "sky/elementsetformat.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>

#include <algorithm>
#include <cstdio>
#include <ctime>

using namespace slew::sky;

namespace {

// CPU time of this thread: the development machine is shared, and wall
// time there measures the neighbours' builds as much as this code.
double threadCpuSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + t.tv_nsec / 1e9;
}

// The times each set is propagated at, in order: `count` of them evenly
// from -halfSpan to just short of +halfSpan minutes about its epoch. A day
// either side is where element sets are mostly used; ten days either side
// is where a deep-space set's resonance integration, stepping half a day
// at a time from epoch, costs the most. vallado_reference.py takes the same
// two numbers.
//
// Each set goes over its grid as many rounds in a row as make 2000 states
// (ten of the short grid, one of the long), then the next set: one set
// asked for a run of times, as a pass scan asks, and the order the
// reference calls Vallado's code in, 2000 states a call to keep Python's
// share small. (Going round all the sets one grid at a time instead costs
// Slew's figures 10-15 % in cache misses.)
struct TimeGrid {
    int count;
    double halfSpanMinutes;
    double at(int i) const { return -halfSpanMinutes + i * (2.0 * halfSpanMinutes / count); }
    int roundsPerSet() const { return std::max(1, 2000 / count); }
    QString label() const
    {
        const double days = halfSpanMinutes / 1440.0;
        return QStringLiteral("%1 times over +-%2 %3").arg(count).arg(days).arg(days == 1.0 ? "day" : "days");
    }
};
constexpr TimeGrid kGrids[] = {{200, 1440.0}, {10000, 14400.0}};

// How each set is propagated across the grid: as a caller with a run of
// times does (Sgp4Propagator: the resonance integration carried from one
// time to the next), or one-off calls that each integrate from epoch.
enum class Calls { Carried, OneOff };

// States per CPU-second over the given sets, each at every time of the grid,
// for about a second and a half.
double statesPerSecond(const QList<Sgp4> &sats, const TimeGrid &grid, Calls calls, double *checksum)
{
    if (sats.isEmpty())
        return 0;
    QElapsedTimer timer;
    timer.start();
    const double cpuStart = threadCpuSeconds();
    long states = 0;
    double sum = 0;
    while (timer.elapsed() < 1500) {
        for (qsizetype k = 0; k < sats.size() && timer.elapsed() < 1500; ++k) {
            const Sgp4 &s = sats[k];
            Sgp4Propagator propagator(s);
            for (int round = 0; round < grid.roundsPerSet(); ++round) {
                for (int i = 0; i < grid.count; ++i) {
                    const double t = grid.at(i);
                    const Sgp4State st = calls == Calls::Carried ? propagator.propagate(t) : s.propagate(t);
                    sum += st.positionKm.x;
                }
                states += grid.count;
            }
        }
    }
    *checksum += sum;
    return states / (threadCpuSeconds() - cpuStart);
}

// Vallado's C++ over the same sets and grids, in the same run, so the two
// see the same load. Debian's python3 is the one python3-sgp4 installs into;
// a build of it with the C++ extension is found through PYTHONPATH.
void printValladoReference(const QString &tleFile)
{
    QStringList arguments{QStringLiteral(SLEW_BENCH_SKY_DIR "/vallado_reference.py"), tleFile};
    for (const TimeGrid &grid : kGrids)
        arguments << QStringLiteral("%1:%2").arg(grid.count).arg(grid.halfSpanMinutes);
    QProcess python;
    python.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    python.start(QStringLiteral("/usr/bin/python3"), arguments);
    if (!python.waitForFinished(300000)) {
        std::printf("Vallado reference: not measured (%s)\n", qPrintable(python.errorString()));
        return;
    }
    std::fputs(python.readAllStandardOutput().constData(), stdout);
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv); // for QProcess
    QFile file(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    if (!file.open(QIODevice::ReadOnly)) {
        std::fprintf(stderr, "bench_sky: cannot read %s\n", qPrintable(file.fileName()));
        return 1;
    }
    const QList<ElementSet> sets = readTleText(QString::fromLatin1(file.readAll())).sets;
    QList<Sgp4> nearEarth, deepSpace;
    for (const ElementSet &t : sets) {
        Sgp4 s(t);
        if (s.initialError() != Sgp4Error::None)
            continue;
        (s.isDeepSpace() ? deepSpace : nearEarth).append(s);
    }
    double checksum = 0;
    for (const TimeGrid &grid : kGrids) {
        const double near = statesPerSecond(nearEarth, grid, Calls::Carried, &checksum);
        const double deep = statesPerSecond(deepSpace, grid, Calls::Carried, &checksum);
        const double deepOneOff = statesPerSecond(deepSpace, grid, Calls::OneOff, &checksum);
        const QByteArray label = grid.label().toUtf8();
        std::printf("SGP4 near-earth, %s: %.3g states/s (%d sets)\n", label.constData(), near, int(nearEarth.size()));
        std::printf("SDP4 deep-space, %s: %.3g states/s (%d sets); one-off calls, each from epoch: %.3g\n",
                    label.constData(), deep, int(deepSpace.size()), deepOneOff);
    }
    std::fflush(stdout);
    printValladoReference(file.fileName());

    // 200 satellites as they come in the file (a mix of LEO, MEO, GEO and
    // Molniya orbits), over a week from the snapshot's newest epoch.
    const QList<ElementSet> two_hundred = sets.mid(0, 200);
    double start = 0;
    for (const ElementSet &t : sets)
        start = std::max(start, t.epochJulian());
    const Site station{55.6875, 12.625, 20, {}, {}};
    QElapsedTimer timer;
    timer.start();
    const double cpuStart = threadCpuSeconds();
    const QList<Pass> passes = predictPasses(two_hundred, station, {start, start + 7.0, 0.0});
    const double cpu = threadCpuSeconds() - cpuStart;
    const double wall = timer.nsecsElapsed() / 1e9;
    std::printf("Pass prediction: %d satellites, 7 days, %d passes in %.3f s of CPU (%.3f s wall)\n",
                int(two_hundred.size()), int(passes.size()), cpu, wall);
    std::fprintf(stderr, "(checksum %g)\n", checksum);
    return 0;
}
