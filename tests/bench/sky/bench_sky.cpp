// SPDX-License-Identifier: GPL-3.0-or-later
// Sky benchmarks on one core: SGP4 states per second (near-earth and
// deep-space sets from the real snapshot in tests/data) and pass prediction
// for 200 satellites over 7 days. Prints the figures README records.

#include "sky/passes.h"
#include "sky/sgp4.h"
#include "sky/tle.h"

#include <QElapsedTimer>
#include <QFile>

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

// States per CPU second over the given sets, each propagated across ±1 day.
double statesPerSecond(const QList<Sgp4> &sats, double *checksum)
{
    if (sats.isEmpty())
        return 0;
    QElapsedTimer timer;
    timer.start();
    const double cpuStart = threadCpuSeconds();
    long states = 0;
    double sum = 0;
    while (timer.elapsed() < 1500) {
        for (const Sgp4 &s : sats) {
            for (int i = 0; i < 200; ++i) {
                const Sgp4State st = s.propagate(-1440.0 + i * 14.4);
                sum += st.positionKm.x;
            }
            states += 200;
        }
    }
    *checksum += sum;
    return states / (threadCpuSeconds() - cpuStart);
}

} // namespace

int main()
{
    QFile file(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    if (!file.open(QIODevice::ReadOnly)) {
        std::fprintf(stderr, "bench_sky: cannot read %s\n", qPrintable(file.fileName()));
        return 1;
    }
    const QList<Tle> sets = readTleText(QString::fromLatin1(file.readAll())).sets;
    QList<Sgp4> nearEarth, deepSpace;
    for (const Tle &t : sets) {
        Sgp4 s(t);
        if (s.initialError() != Sgp4Error::None)
            continue;
        (s.isDeepSpace() ? deepSpace : nearEarth).append(s);
    }
    double checksum = 0;
    const double near = statesPerSecond(nearEarth, &checksum);
    const double deep = statesPerSecond(deepSpace, &checksum);
    std::printf("SGP4 near-earth: %.3g states/s (%d sets)\n", near, int(nearEarth.size()));
    std::printf("SDP4 deep-space: %.3g states/s (%d sets, within a day of epoch)\n", deep, int(deepSpace.size()));

    // 200 satellites as they come in the file (a mix of LEO, MEO, GEO and
    // Molniya orbits), over a week from the snapshot's newest epoch.
    const QList<Tle> two_hundred = sets.mid(0, 200);
    double start = 0;
    for (const Tle &t : sets)
        start = std::max(start, t.epochJulian());
    const Station station{55.6875, 12.625, 20, {}};
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
