// SPDX-License-Identifier: GPL-3.0-or-later
// What a radio held through a pass, from a rigctld traffic log, against the
// true Doppler-corrected frequencies: how a real radio controller (Gpredict,
// or Slew's station service) tuned a real rigctld.
//
//   doppler_from_log LOG --offset SECONDS [--tle FILE] [--sat NAME]
//                    [--qth STATION] [--downlink HZ] [--uplink HZ]
//
// LOG is what rigctld_log_proxy.py wrote: "<UTC ms> <connection> <dir>
// <line>", `>` the controller's command, `<` rigctld's answer. --offset is
// the controller's clock against the log's: the satellite's time is the
// log's UTC plus OFFSET seconds (a run of a 2018 pass in 2026 has its clock
// shifted by a whole number of seconds).
//
// A frequency (`F`, `I`, or `+F`, `+I`) is taken as held from the moment
// rigctld answered it `RPRT 0` until the next one of its kind. From AOS to
// LOS of the first whole pass in the log (elevation 0°), every 10 ms of the
// satellite's time, the held receive and transmit frequencies are compared
// with the truth from this element set: ground receive = f(1 − ṙ/c), uplink
// sent = f/(1 − ṙ/c) (core/radio/doppler.h), ṙ from SGP4 and the station
// (core/sky). Sampling starts once both paths are on the Doppler curve
// (within 100 kHz: a controller that begins at AOS has not yet tuned), and ends
// early where the controller turns split off (`S 0`: Slew's own LOS).
//
// Printed: RMS, worst and mean error of each path and of both together (as
// Slew's LOS log line counts them); frequency commands a second (mean, and
// the most in any sliding second) and all commands (reads included); the
// reads that disagreed with what was held; and the age of the Doppler each
// receive frequency carried when the radio took it (the satellite time whose
// truth it equals, found where the downlink moves over 50 Hz a second:
// positive is late, negative is a lead).

#include "radio/doppler.h"
#include "sky/tleformat.h"
#include "sky/observation.h"
#include "sky/passes.h"
#include "sky/sgp4.h"
#include "sky/site.h"
#include "sky/elementsetformat.h"
#include "sky/utctime.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <map>
#include <optional>
#include <vector>

using namespace slew;

namespace {

constexpr double kUnixEpochJulian = 2440587.5;
constexpr double kSecondsPerDay = 86400.0;
constexpr double kTrackingHz = 100e3;

struct Held {
    double atMs; // the log's UTC, when rigctld answered
    double hz;
};

struct Reading {
    double atMs;
    char kind; // 'f' or 'i'
    double hz;
};

struct Log {
    std::vector<Held> receive, transmit; // in order of time
    std::vector<double> frequencySends;  // F and I, when sent
    std::vector<double> allSends;        // every command
    std::vector<Reading> readings;
    std::vector<double> splitOff; // `S 0`: the controller's end of a pass
    int refused = 0, unanswered = 0;
    double firstMs = 0, lastMs = 0;
};

// The command's letter after an optional '+' (rigctld's extended form).
QString commandWord(const QString &line, QString *argument)
{
    QString text = line.trimmed();
    if (text.startsWith(QLatin1Char('+')))
        text = text.mid(1);
    const qsizetype space = text.indexOf(QLatin1Char(' '));
    *argument = space < 0 ? QString() : text.mid(space + 1).trimmed();
    return space < 0 ? text : text.left(space);
}

std::optional<Log> readLog(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        *error = file.errorString();
        return std::nullopt;
    }
    Log log;
    struct PendingSet {
        char kind;
        double hz;
    };
    std::map<int, std::optional<PendingSet>> pendingSet; // per connection
    std::map<int, char> pendingRead;
    bool first = true;
    QTextStream in(&file);
    while (!in.atEnd()) {
        const QString line = in.readLine();
        if (line.startsWith(QLatin1Char('#')) || line.isEmpty())
            continue;
        const QStringList parts = line.split(QLatin1Char(' '));
        if (parts.size() < 3)
            continue;
        bool ok = false;
        const double t = parts[0].toDouble(&ok);
        if (!ok)
            continue;
        const int conn = parts[1].toInt();
        const QString direction = parts[2];
        const QString rest = line.section(QLatin1Char(' '), 3);
        if (first)
            log.firstMs = t;
        first = false;
        log.lastMs = t;
        if (direction == QLatin1String(">")) {
            if (rest.startsWith(QLatin1Char('[')))
                continue; // [closed]
            if (pendingSet[conn]) {
                ++log.unanswered; // one command at a time: the last had no RPRT
                pendingSet[conn].reset();
            }
            log.allSends.push_back(t);
            QString argument;
            const QString word = commandWord(rest, &argument);
            if (word == QLatin1String("F") || word == QLatin1String("I")) {
                const double hz = argument.toDouble(&ok);
                if (ok) {
                    pendingSet[conn] = PendingSet{word == QLatin1String("F") ? 'F' : 'I', hz};
                    log.frequencySends.push_back(t);
                }
            } else if (word == QLatin1String("f") || word == QLatin1String("i")) {
                pendingRead[conn] = word == QLatin1String("f") ? 'f' : 'i';
            } else if (word == QLatin1String("S") && argument.startsWith(QLatin1Char('0'))) {
                log.splitOff.push_back(t);
            }
        } else if (direction == QLatin1String("<")) {
            const QString text = rest.trimmed();
            if (text.startsWith(QLatin1String("RPRT"))) {
                if (pendingSet[conn]) {
                    const PendingSet set = *pendingSet[conn];
                    if (text == QLatin1String("RPRT 0"))
                        (set.kind == 'F' ? log.receive : log.transmit).push_back({t, set.hz});
                    else
                        ++log.refused;
                    pendingSet[conn].reset();
                }
                pendingRead.erase(conn);
                continue;
            }
            const auto read = pendingRead.find(conn);
            if (read == pendingRead.end())
                continue;
            // Default form: the bare value; extended: "Frequency: N" or
            // "TX Frequency: N" after the echo.
            QString value = text;
            if (const qsizetype colon = text.lastIndexOf(QLatin1Char(':')); colon >= 0)
                value = text.mid(colon + 1).trimmed();
            const double hz = value.toDouble(&ok);
            if (ok && !value.isEmpty()) {
                log.readings.push_back({t, read->second, hz});
                pendingRead.erase(read);
            }
        }
    }
    return log;
}

std::optional<double> heldAt(const std::vector<Held> &held, double ms)
{
    auto it = std::upper_bound(held.begin(), held.end(), ms, [](double t, const Held &h) { return t < h.atMs; });
    if (it == held.begin())
        return std::nullopt;
    return std::prev(it)->hz;
}

// The most events in any window of `widthMs` (sorted times).
int busiest(const std::vector<double> &times, double fromMs, double toMs, double widthMs)
{
    int best = 0;
    size_t lo = 0;
    for (size_t hi = 0; hi < times.size(); ++hi) {
        if (times[hi] < fromMs || times[hi] > toMs)
            continue;
        while (times[lo] < fromMs || times[hi] - times[lo] >= widthMs)
            ++lo;
        best = std::max(best, int(hi - lo + 1));
    }
    return best;
}

int countWithin(const std::vector<double> &times, double fromMs, double toMs)
{
    return int(std::count_if(times.begin(), times.end(), [&](double t) { return t >= fromMs && t <= toMs; }));
}

struct PathFigures {
    double sumSquares = 0, sum = 0, worst = 0, worstAtMs = 0;
    qint64 samples = 0;
    void add(double error, double atMs)
    {
        sumSquares += error * error;
        sum += error;
        if (std::abs(error) > worst) {
            worst = std::abs(error);
            worstAtMs = atMs;
        }
        ++samples;
    }
    double rms() const { return samples ? std::sqrt(sumSquares / double(samples)) : 0.0; }
    double mean() const { return samples ? sum / double(samples) : 0.0; }
};

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("The Doppler error of a radio through a pass, from a rigctld_log_proxy.py log."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("log"), QStringLiteral("The proxy's log."));
    parser.addOptions({
        {QStringLiteral("offset"), QStringLiteral("The satellite's time minus the log's UTC, in seconds."),
         QStringLiteral("seconds"), QStringLiteral("0")},
        {QStringLiteral("tle"), QStringLiteral("Element sets (default: the test data's 2018 sets)."),
         QStringLiteral("file"), QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle")},
        {QStringLiteral("sat"), QStringLiteral("The satellite's name (default BRITE-TORONTO)."), QStringLiteral("name"),
         QStringLiteral("BRITE-TORONTO")},
        {QStringLiteral("qth"), QStringLiteral("The station (default JO65hq)."), QStringLiteral("station"),
         QStringLiteral("JO65hq")},
        {QStringLiteral("downlink"), QStringLiteral("The satellite's downlink in Hz (default 435000000)."),
         QStringLiteral("hz"), QStringLiteral("435000000")},
        {QStringLiteral("uplink"), QStringLiteral("The satellite's uplink in Hz (default 145900000)."),
         QStringLiteral("hz"), QStringLiteral("145900000")},
    });
    parser.process(app);
    if (parser.positionalArguments().size() != 1)
        parser.showHelp(2);

    const double offsetS = parser.value(QStringLiteral("offset")).toDouble();
    sky::Site station;
    QString why;
    if (!sky::parseSite(parser.value(QStringLiteral("qth")), &station, &why)) {
        std::fprintf(stderr, "doppler_from_log: --qth: %s\n", qPrintable(why));
        return 2;
    }
    QFile tleFile(parser.value(QStringLiteral("tle")));
    if (!tleFile.open(QIODevice::ReadOnly)) {
        std::fprintf(stderr, "doppler_from_log: %s: %s\n", qPrintable(tleFile.fileName()),
                     qPrintable(tleFile.errorString()));
        return 2;
    }
    std::optional<sky::ElementSet> tle;
    for (const sky::ElementSet &t : sky::readTleText(QString::fromLatin1(tleFile.readAll())).sets) {
        if (t.name.trimmed().compare(parser.value(QStringLiteral("sat")), Qt::CaseInsensitive) == 0)
            tle = t;
    }
    if (!tle) {
        std::fprintf(stderr, "doppler_from_log: no %s in %s\n", qPrintable(parser.value(QStringLiteral("sat"))),
                     qPrintable(tleFile.fileName()));
        return 2;
    }
    const std::optional<Log> log = readLog(parser.positionalArguments().first(), &why);
    if (!log) {
        std::fprintf(stderr, "doppler_from_log: %s\n", qPrintable(why));
        return 2;
    }

    auto julianOf = [&](double logMs) { return kUnixEpochJulian + (logMs / 1000.0 + offsetS) / kSecondsPerDay; };
    auto logMsOf = [&](double julian) { return ((julian - kUnixEpochJulian) * kSecondsPerDay - offsetS) * 1000.0; };

    const sky::Sgp4 sat(*tle);
    const QList<sky::Pass> passes =
        sky::predictPasses(sat, station, sky::PassWindow{julianOf(log->firstMs), julianOf(log->lastMs), 0.0});
    const sky::Pass *pass = nullptr;
    for (const sky::Pass &p : passes) {
        if (!p.aosClipped && !p.losClipped && logMsOf(p.los.julian) <= log->lastMs) {
            pass = &p;
            break;
        }
    }
    if (!pass) {
        std::fprintf(stderr, "doppler_from_log: no whole pass of %s in the log's %.0f s\n", qPrintable(tle->name),
                     (log->lastMs - log->firstMs) / 1000.0);
        return 1;
    }

    radio::SatelliteFrequencies frequencies;
    frequencies.downlinkHz = parser.value(QStringLiteral("downlink")).toDouble();
    frequencies.uplinkHz = parser.value(QStringLiteral("uplink")).toDouble();
    auto rangeRate = [&](double julian) {
        const sky::Sgp4State state = sat.propagateToJulian(julian);
        return sky::lookAngles(station, state.positionKm, state.velocityKmS, julian).rangeRateKmS;
    };
    auto truthAt = [&](double julian) { return radio::tuningFor(frequencies, rangeRate(julian)); };

    const double aosMs = logMsOf(pass->aos.julian);
    double losMs = logMsOf(pass->los.julian);
    auto withMs = [](double julian) { return sky::utcFromJulian(julian).toString(Qt::ISODateWithMs); };
    std::printf("pass: %s, AOS %s, TCA %s, LOS %s, max el %.1f°, %.0f s\n", qPrintable(tle->name),
                qPrintable(withMs(pass->aos.julian)), qPrintable(withMs(pass->tca.julian)),
                qPrintable(withMs(pass->los.julian)), pass->maxElevationDeg(),
                (pass->los.julian - pass->aos.julian) * kSecondsPerDay);
    // A controller that ends its pass itself (Slew turns split off and puts
    // the radio back where it found it) ends the figures there: what it
    // tunes after its own LOS is no Doppler tracking.
    for (double t : log->splitOff) {
        if (t > aosMs && t < losMs) {
            std::printf("the controller turned split off %.0f ms before LOS: the figures end there\n", losMs - t);
            losMs = t;
            break;
        }
    }
    const double lengthS = (losMs - aosMs) / 1000.0;

    PathFigures rx, tx;
    double firstSampleMs = -1;
    for (double ms = aosMs; ms <= losMs; ms += 10.0) {
        const std::optional<double> r = heldAt(log->receive, ms), t = heldAt(log->transmit, ms);
        if (!r || !t)
            continue;
        const radio::RadioTuning truth = truthAt(julianOf(ms));
        if (firstSampleMs < 0) {
            // Tracking has begun once both paths are on the Doppler curve:
            // the shift is at most some 10 kHz at 435 MHz, so a frequency
            // 100 kHz off is what the radio was left on before (Slew begins
            // at AOS; until its first F and I it holds the operator's).
            if (std::abs(*r - truth.receiveHz) > kTrackingHz || std::abs(*t - *truth.transmitHz) > kTrackingHz)
                continue;
            firstSampleMs = ms;
        }
        rx.add(*r - truth.receiveHz, ms);
        tx.add(*t - *truth.transmitHz, ms);
    }
    if (rx.samples == 0) {
        std::fprintf(stderr, "doppler_from_log: the radio was never set on both paths during the pass\n");
        return 1;
    }
    std::printf("sampled every 10 ms from %s (%.0f ms after AOS: both paths tracking) to %s: %lld samples\n",
                qPrintable(withMs(julianOf(firstSampleMs))), firstSampleMs - aosMs, qPrintable(withMs(julianOf(losMs))),
                (long long)rx.samples);
    std::printf("downlink: RMS %6.2f Hz, worst %6.1f Hz (AOS + %.2f s), mean %+6.2f Hz\n", rx.rms(), rx.worst,
                (rx.worstAtMs - aosMs) / 1000.0, rx.mean());
    std::printf("uplink:   RMS %6.2f Hz, worst %6.1f Hz (AOS + %.2f s), mean %+6.2f Hz\n", tx.rms(), tx.worst,
                (tx.worstAtMs - aosMs) / 1000.0, tx.mean());
    std::printf("both:     RMS %6.2f Hz, worst %6.1f Hz (as Slew's LOS line counts them)\n",
                std::sqrt((rx.sumSquares + tx.sumSquares) / double(rx.samples + tx.samples)),
                std::max(rx.worst, tx.worst));

    const int frequencyCommands = countWithin(log->frequencySends, aosMs, losMs);
    const int allCommands = countWithin(log->allSends, aosMs, losMs);
    std::printf("frequency commands (F, I): %d, %.2f a second, %d in the busiest second\n", frequencyCommands,
                frequencyCommands / lengthS, busiest(log->frequencySends, aosMs, losMs, 1000.0));
    std::printf("all commands (reads too): %d, %.2f a second, %d in the busiest second\n", allCommands,
                allCommands / lengthS, busiest(log->allSends, aosMs, losMs, 1000.0));

    int disagreed = 0, readsInPass = 0;
    for (const Reading &reading : log->readings) {
        if (reading.atMs < aosMs || reading.atMs > losMs)
            continue;
        const std::optional<double> held = heldAt(reading.kind == 'f' ? log->receive : log->transmit, reading.atMs);
        ++readsInPass;
        if (held && std::abs(*held - reading.hz) >= 1.0)
            ++disagreed;
    }
    std::printf("reads in the pass: %d, %d disagreeing with the frequency held; %d sets refused, %d unanswered\n",
                readsInPass, disagreed, log->refused, log->unanswered);

    // The age of each receive frequency when it took effect: the satellite
    // time at which the truth equals it, against the time it was taken.
    std::vector<double> ages;
    for (const Held &h : log->receive) {
        if (h.atMs < aosMs || h.atMs > losMs)
            continue;
        const double j = julianOf(h.atMs);
        const double rate =
            truthAt(j + 0.5 / kSecondsPerDay).receiveHz - truthAt(j - 0.5 / kSecondsPerDay).receiveHz;
        if (std::abs(rate) < 50.0)
            continue;
        // The downlink falls through the pass (approaching: above f; receding:
        // below): bisect within ±5 s.
        double lo = j - 5.0 / kSecondsPerDay, hi = j + 5.0 / kSecondsPerDay;
        const double fLo = truthAt(lo).receiveHz - h.hz, fHi = truthAt(hi).receiveHz - h.hz;
        if (fLo * fHi > 0)
            continue;
        for (int i = 0; i < 60; ++i) {
            const double mid = (lo + hi) / 2;
            if ((truthAt(mid).receiveHz - h.hz) * fLo > 0)
                lo = mid;
            else
                hi = mid;
        }
        ages.push_back((j - (lo + hi) / 2) * kSecondsPerDay * 1000.0);
    }
    if (!ages.empty()) {
        std::sort(ages.begin(), ages.end());
        std::printf("age of the Doppler in each receive frequency when taken (where it moves > 50 Hz/s, %zu): "
                    "min %.0f ms, median %.0f ms, max %.0f ms\n",
                    ages.size(), ages.front(), ages[ages.size() / 2], ages.back());
    }
    return 0;
}
