// SPDX-License-Identifier: GPL-3.0-or-later
// Doppler figures: Slew's steering against Gpredict-style radio control on
// the same pass and the same radio, in simulated time.
//
// The first pass within 3° of the zenith over JO65hq in the two days after
// the element sets' epoch (tests/data), by a LEO satellite, with a 435 MHz
// downlink and a 145.9 MHz uplink (a U/V transponder). Near TCA the
// downlink's Doppler moves fastest, up to some 175 Hz a second.
//
// The radio takes a frequency 30 ms after it is sent (a CAT bus and the
// radio's firmware) and holds it; the error is the frequency it holds
// against the true Doppler-corrected one, sampled every 10 ms from AOS to
// LOS, on both the downlink and the uplink.
//
//  - Slew: DopplerSteering run every 20 ms with its defaults (a lead of the
//    radio's latency, 19 commands a second at most, the dial followed).
//  - Gpredict-style: every cycle the frequencies due at that moment, with no
//    lead, as Gpredict's radio control does; its default cycle is 1000 ms,
//    and a careful user may shorten it (200 ms here).

#include "radio/doppler.h"
#include "radio/dopplersteering.h"
#include "radio/fakeradiolink.h"
#include "sky/tleformat.h"
#include "sky/observation.h"
#include "sky/passes.h"
#include "sky/sgp4.h"
#include "sky/elementsetformat.h"

#include <QCoreApplication>
#include <QFile>

#include <cmath>
#include <cstdio>
#include <deque>

using namespace slew;

namespace {

constexpr double kDownlinkHz = 435.0e6;
constexpr double kUplinkHz = 145.9e6;
constexpr int kLatencyMs = 30;
constexpr double kSecondsPerDay = 86400.0;

sky::Site station()
{
    sky::Site s;
    s.latitudeDeg = 55.6875; // JO65hq
    s.longitudeDeg = 12.625;
    return s;
}

struct ZenithPass {
    sky::ElementSet tle;
    sky::Pass pass;
};

std::optional<ZenithPass> findZenithPass()
{
    QFile file(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;
    const QList<sky::ElementSet> sets = sky::readTleText(QString::fromLatin1(file.readAll())).sets;
    double epoch = 0;
    for (const sky::ElementSet &t : sets)
        epoch = std::max(epoch, t.epochJulian());
    for (const sky::ElementSet &t : sets) {
        if (t.meanMotionRevPerDay < 11.0)
            continue; // LEO only
        const sky::Sgp4 sat(t);
        for (const sky::Pass &p : sky::predictPasses(sat, station(), sky::PassWindow{epoch, epoch + 2.0, 0.0})) {
            if (!p.aosClipped && !p.losClipped && p.maxElevationDeg() > 87.0)
                return ZenithPass{t, p};
        }
    }
    return std::nullopt;
}

struct Figures {
    double rxRms = 0, rxWorst = 0, txRms = 0, txWorst = 0;
    int peakPerSecond = 0;
    double meanPerSecond = 0;
};

class Run {
public:
    Run(const ZenithPass &zp) : m_sat(zp.tle), m_pass(zp.pass) { m_radio.latency = kLatencyMs; }

    std::optional<double> rangeRate(double julian) const
    {
        const sky::Sgp4State state = m_sat.propagateToJulian(julian);
        if (!state.ok())
            return std::nullopt;
        return sky::lookAngles(station(), state.positionKm, state.velocityKmS, julian).rangeRateKmS;
    }

    // Runs the pass, calling `control(julian, ms)` every `everyMs`.
    template <typename Control>
    Figures run(int everyMs, Control control)
    {
        const double aos = m_pass.aos.julian, los = m_pass.los.julian;
        const qint64 lengthMs = qint64((los - aos) * kSecondsPerDay * 1000.0);
        double rxSquares = 0, txSquares = 0;
        qint64 samples = 0;
        Figures f;
        std::deque<qint64> sends;
        qsizetype seen = 0;
        for (qint64 ms = 0; ms <= lengthMs; ms += 10) {
            const double julian = aos + ms / 1000.0 / kSecondsPerDay;
            m_radio.advanceTo(ms);
            if (ms % everyMs == 0)
                control(julian, ms);
            for (; seen < m_radio.sent.size(); ++seen)
                sends.push_back(ms);
            while (!sends.empty() && ms - sends.front() >= 1000)
                sends.pop_front();
            f.peakPerSecond = std::max(f.peakPerSecond, int(sends.size()));
            if (!m_radio.receive || !m_radio.transmit)
                continue;
            const radio::RadioTuning truth = radio::tuningFor(satellite(), *rangeRate(julian));
            const double rx = *m_radio.receive - truth.receiveHz, tx = *m_radio.transmit - *truth.transmitHz;
            rxSquares += rx * rx;
            txSquares += tx * tx;
            f.rxWorst = std::max(f.rxWorst, std::abs(rx));
            f.txWorst = std::max(f.txWorst, std::abs(tx));
            ++samples;
        }
        f.rxRms = std::sqrt(rxSquares / double(std::max<qint64>(samples, 1)));
        f.txRms = std::sqrt(txSquares / double(std::max<qint64>(samples, 1)));
        f.meanPerSecond = double(m_radio.sent.size()) / (double(lengthMs) / 1000.0);
        return f;
    }

    static radio::SatelliteFrequencies satellite()
    {
        radio::SatelliteFrequencies s;
        s.downlinkHz = kDownlinkHz;
        s.uplinkHz = kUplinkHz;
        return s;
    }

    FakeRadioLink m_radio;

private:
    sky::Sgp4 m_sat;
    sky::Pass m_pass;
};

void print(const char *who, const Figures &f)
{
    std::printf("%-34s downlink RMS %6.2f Hz, worst %6.1f Hz | uplink RMS %6.2f Hz, worst %6.1f Hz | "
                "commands %5.2f/s mean, %2d in the busiest second\n",
                who, f.rxRms, f.rxWorst, f.txRms, f.txWorst, f.meanPerSecond, f.peakPerSecond);
}

Figures gpredictStyle(const ZenithPass &zp, int cycleMs)
{
    Run run(zp);
    return run.run(cycleMs, [&](double julian, qint64) {
        const radio::RadioTuning t = radio::tuningFor(Run::satellite(), *run.rangeRate(julian));
        run.m_radio.setReceiveHz(std::round(t.receiveHz));
        run.m_radio.setTransmitHz(std::round(*t.transmitHz));
    });
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const std::optional<ZenithPass> zp = findZenithPass();
    if (!zp) {
        std::fprintf(stderr, "bench_doppler: no near-zenith pass in the test element sets\n");
        return 1;
    }
    std::printf("pass: %s, max el %.1f°, %.0f s; downlink %.1f MHz, uplink %.1f MHz; radio latency %d ms\n",
                qPrintable(zp->tle.name), zp->pass.maxElevationDeg(),
                (zp->pass.los.julian - zp->pass.aos.julian) * kSecondsPerDay, kDownlinkHz / 1e6, kUplinkHz / 1e6,
                kLatencyMs);
    {
        Run probe(*zp);
        double fastest = 0;
        for (double t = zp->pass.aos.julian; t < zp->pass.los.julian; t += 1.0 / kSecondsPerDay) {
            const double a = radio::downlinkOnGroundHz(kDownlinkHz, *probe.rangeRate(t));
            const double b = radio::downlinkOnGroundHz(kDownlinkHz, *probe.rangeRate(t + 1.0 / kSecondsPerDay));
            fastest = std::max(fastest, std::abs(b - a));
        }
        std::printf("the downlink's Doppler moves up to %.0f Hz a second\n", fastest);
    }

    Run slew(*zp);
    radio::DopplerSteering steering(&slew.m_radio);
    steering.begin(Run::satellite(), [&](double julian) { return slew.rangeRate(julian); });
    const Figures ours = slew.run(20, [&](double julian, qint64 ms) { steering.step(julian, ms); });
    print("Slew (DopplerSteering, defaults)", ours);
    const Figures byDefault = gpredictStyle(*zp, 1000);
    print("Gpredict-style, 1000 ms cycle", byDefault);
    const Figures tuned = gpredictStyle(*zp, 200);
    print("Gpredict-style, 200 ms cycle", tuned);
    std::printf("Slew against Gpredict-style 1000 ms: downlink RMS %.0f× lower, worst %.0f× lower\n",
                byDefault.rxRms / ours.rxRms, byDefault.rxWorst / ours.rxWorst);
    std::printf("Slew against Gpredict-style 200 ms: downlink RMS %.1f× lower, worst %.1f× lower\n",
                tuned.rxRms / ours.rxRms, tuned.rxWorst / ours.rxWorst);
    return 0;
}
