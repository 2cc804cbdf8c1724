// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a whole active catalogue (12,000 objects) in each form an element
// set comes in: TLE, CSV, OMM XML, JSON, OMM KVN. The catalogue is the test
// snapshot's 979 sets (tests/data) renumbered into six- and nine-digit
// catalogue numbers until there are as many as CelesTrak's active group,
// written in each form by Slew's own writers. Beside Slew's figures, in the
// same run and over the same files: Debian's python3-sgp4 reading the CSV
// and the XML with its OMM module (sgp4.omm.parse_csv / parse_xml) and
// initialising a Satrec from each, and a plain line-and-comma splitter over
// the CSV that reads no number at all, the floor any CSV reader stands on.
//
// CPU time of this thread, best of several rounds: the machine is shared,
// and wall time there measures the neighbours as much as this code.

#include "sky/elementsetformat.h"
#include "sky/sgp4.h"
#include "sky/tleformat.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>

using namespace slew::sky;

namespace {

constexpr int kCatalogueSize = 12000;
constexpr int kRounds = 7;

double threadCpuSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + t.tv_nsec / 1e9;
}

// The best of kRounds, in milliseconds.
double bestMs(const std::function<void()> &work)
{
    double best = 1e9;
    for (int i = 0; i < kRounds; ++i) {
        const double start = threadCpuSeconds();
        work();
        best = std::min(best, (threadCpuSeconds() - start) * 1000.0);
    }
    return best;
}

QList<ElementSet> catalogue()
{
    QFile file(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QList<ElementSet> snapshot = readTleText(QString::fromLatin1(file.readAll())).sets;
    QList<ElementSet> all;
    for (int i = 0; all.size() < kCatalogueSize && !snapshot.isEmpty(); ++i) {
        ElementSet s = snapshot[i % snapshot.size()];
        // Six-digit numbers (Alpha-5 can still carry them, so the TLE file
        // holds the whole catalogue too); every tenth, nine digits in the
        // CSV, JSON, XML and KVN.
        s.catalogueNumber = 100000 + i;
        s.meanAnomalyDeg = std::fmod(s.meanAnomalyDeg + 7.0 * (i / snapshot.size()), 360.0);
        all.append(s);
    }
    return all;
}

// Python's figures, from one process: the same files, its best of rounds.
const char *kPythonScript = R"(
import sys, time
from sgp4 import omm
from sgp4.api import Satrec
def run(path, parse):
    best = 1e9
    for _ in range(3):
        t = time.process_time()
        with open(path) as f:
            n = 0
            for fields in parse(f):
                s = Satrec(); omm.initialize(s, fields); n += 1
        best = min(best, time.process_time() - t)
    return best * 1000, n
from sgp4.api import accelerated
print('accelerated', 'yes' if accelerated else 'no', 0)
for name, path, parse in (('csv', sys.argv[1], omm.parse_csv), ('xml', sys.argv[2], omm.parse_xml)):
    ms, n = run(path, parse)
    print(name, '%.1f' % ms, n)
)";

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QList<ElementSet> sets = catalogue();
    if (sets.size() != kCatalogueSize) {
        std::fprintf(stderr, "bench_elementsets: tests/data/gpredict-satellites-2018.tle is missing\n");
        return 1;
    }
    QTemporaryDir dir;
    struct Form {
        ElementSetForm form;
        const char *file;
        QByteArray bytes;
    };
    QList<Form> forms = {{ElementSetForm::Tle, "catalogue.tle", {}},
                         {ElementSetForm::Csv, "catalogue.csv", {}},
                         {ElementSetForm::OmmXml, "catalogue.xml", {}},
                         {ElementSetForm::Json, "catalogue.json", {}},
                         {ElementSetForm::OmmKvn, "catalogue.kvn", {}}};
    for (Form &f : forms) {
        f.bytes = writeElementSets(sets, f.form).bytes;
        QFile out(dir.filePath(QLatin1String(f.file)));
        if (!out.open(QIODevice::WriteOnly) || out.write(f.bytes) != f.bytes.size())
            return 1;
    }

    std::printf("Reading %d element sets (CPU ms, best of %d):\n", kCatalogueSize, kRounds);
    std::printf("  %-8s %9s %8s %12s %16s\n", "form", "size", "read", "read + SGP4", "sets/s (read)");
    double csvReadMs = 0;
    for (const Form &f : forms) {
        qsizetype count = 0;
        const double readMs = bestMs([&] { count = readElementSets(f.bytes).read.sets.size(); });
        const double withSgp4Ms = bestMs([&] {
            for (const ElementSet &s : readElementSets(f.bytes).read.sets) {
                const Sgp4 satellite(s);
                count += satellite.isDeepSpace() ? 1 : 0; // kept, so the work is not thrown away
            }
        });
        if (f.form == ElementSetForm::Csv)
            csvReadMs = withSgp4Ms;
        std::printf("  %-8s %7.1f MB %8.1f %12.1f %16.0f\n", qPrintable(formName(f.form)), f.bytes.size() / 1e6,
                    readMs, withSgp4Ms, kCatalogueSize / readMs * 1000.0);
    }

    // The floor: lines and commas found, nothing read.
    const QByteArray &csv = forms[1].bytes;
    qsizetype fields = 0;
    const double floorMs = bestMs([&] {
        fields = 0;
        for (const QByteArray &line : csv.split('\n'))
            fields += line.count(',') + 1;
    });
    std::printf("  plain line and comma splitter over the CSV: %.1f ms (%lld fields)\n", floorMs, qlonglong(fields));

    QProcess python;
    python.start(QStringLiteral("/usr/bin/python3"), {QStringLiteral("-c"), QString::fromLatin1(kPythonScript),
                                                      dir.filePath(QStringLiteral("catalogue.csv")),
                                                      dir.filePath(QStringLiteral("catalogue.xml"))});
    if (!python.waitForFinished(600000) || python.exitCode() != 0) {
        std::printf("  python3-sgp4: not run (%s)\n", python.readAllStandardError().trimmed().constData());
        return 0;
    }
    std::printf("python3-sgp4 (sgp4.omm parse + Satrec initialisation, CPU ms, best of 3):\n");
    for (const QByteArray &line : python.readAllStandardOutput().trimmed().split('\n')) {
        const QList<QByteArray> f = line.split(' ');
        if (f.size() != 3)
            continue;
        if (f[0] == "accelerated") {
            // Debian's package is pure Python; built from source with its
            // C++ extension (PYTHONPATH), Satrec is Vallado's C++.
            std::printf("  Satrec in C++ (sgp4.api.accelerated): %s\n", f[1].constData());
            continue;
        }
        const double ms = f[1].toDouble();
        std::printf("  %-8s %10.1f ms for %s sets", f[0].toUpper().constData(), ms, f[2].constData());
        if (f[0] == "csv" && csvReadMs > 0)
            std::printf("   Slew's CSV read + SGP4 is %.0fx faster", ms / csvReadMs);
        std::printf("\n");
    }
    return 0;
}
