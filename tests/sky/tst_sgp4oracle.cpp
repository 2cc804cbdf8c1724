// SPDX-License-Identifier: GPL-3.0-or-later
// SGP4/SDP4 against an independent implementation: Debian's python3-sgp4,
// run as a real process, on random (satellite, time) pairs drawn from a real
// element-set snapshot (tests/data, source named in the file).

#include "sky/tleformat.h"
#include "sky/sgp4.h"
#include "sky/elementsetformat.h"

#include <QFile>
#include <QHash>
#include <QProcess>
#include <QRandomGenerator>
#include <QTest>

#include <algorithm>

using namespace slew::sky;

namespace {

// The interpreter Debian's python3-sgp4 installs into; a python3 earlier in
// PATH (a virtual environment) may not have it.
const QString kPython = QStringLiteral("/usr/bin/python3");

const char *kOracleScript = R"(
import sys
from sgp4.api import Satrec
for line in sys.stdin:
    l1, l2, t = line.rstrip('\n').split('|')
    e, r, v = Satrec.twoline2rv(l1, l2).sgp4_tsince(float(t))
    print(e, *('%.12g' % x for x in r + v))
)";

struct Pair {
    const ElementSet *tle;
    double minutes;
};

} // namespace

class TestSgp4Oracle : public QObject {
    Q_OBJECT
private slots:
    void agreesWithPythonSgp4();
};

void TestSgp4Oracle::agreesWithPythonSgp4()
{
    QFile file(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    QVERIFY2(file.open(QIODevice::ReadOnly), "tests/data/gpredict-satellites-2018.tle is missing");
    const QByteArray text = file.readAll();
    const ElementSetRead read = readTleText(QString::fromLatin1(text));
    QVERIFY(read.refusals.isEmpty());
    // The oracle reads the file's own lines, not anything Slew made of them.
    QHash<int, QByteArray> linesOf;
    const QList<QByteArray> lines = text.split('\n');
    for (qsizetype i = 0; i + 1 < lines.size(); ++i)
        if (lines[i].startsWith("1 ") && lines[i + 1].startsWith("2 "))
            linesOf.insert(catalogueNumberFromAlpha5(QString::fromLatin1(lines[i].mid(2, 5))).value_or(0),
                           lines[i].trimmed() + '|' + lines[i + 1].trimmed());
    QVERIFY(read.sets.size() > 900);

    QProcess probe;
    probe.start(kPython, {QStringLiteral("-c"), QStringLiteral("import sgp4.api")});
    if (!probe.waitForFinished(60000) || probe.exitStatus() != QProcess::NormalExit || probe.exitCode() != 0)
        QFAIL("python3 cannot import sgp4: install the Debian package python3-sgp4");

    // A fixed seed: the same pairs every run, so a failure can be replayed.
    QRandomGenerator random(20261122);
    QList<Pair> pairs;
    QByteArray input;
    for (int i = 0; i < 1200; ++i) {
        const ElementSet &tle = read.sets[random.bounded(int(read.sets.size()))];
        const double minutes = (random.generateDouble() * 2.0 - 1.0) * 3.0 * kMinutesPerDay;
        pairs.append({&tle, minutes});
        input += linesOf.value(tle.catalogueNumber) + '|' + QByteArray::number(minutes, 'g', 17) + '\n';
    }

    QProcess oracle;
    oracle.start(kPython, {QStringLiteral("-c"), QString::fromLatin1(kOracleScript)});
    QVERIFY(oracle.waitForStarted(30000));
    oracle.write(input);
    oracle.closeWriteChannel();
    QVERIFY2(oracle.waitForFinished(300000), "python3-sgp4 did not finish");
    QCOMPARE(oracle.exitCode(), 0);
    const QList<QByteArray> answers = oracle.readAllStandardOutput().trimmed().split('\n');
    QCOMPARE(answers.size(), pairs.size());

    QList<double> errors;
    double worst = 0, worstVelocity = 0;
    int compared = 0, bothFailed = 0, deepSpace = 0;
    for (int i = 0; i < pairs.size(); ++i) {
        const QList<QByteArray> f = answers[i].split(' ');
        QCOMPARE(f.size(), 7);
        const int theirError = f[0].toInt();
        const Sgp4 sgp4(*pairs[i].tle);
        const Sgp4State ours = sgp4.propagate(pairs[i].minutes);
        QVERIFY2(int(ours.error) == theirError,
                 qPrintable(QStringLiteral("%1 at %2 min: error %3 here, %4 in python3-sgp4")
                                .arg(pairs[i].tle->catalogueNumber)
                                .arg(pairs[i].minutes)
                                .arg(int(ours.error))
                                .arg(theirError)));
        if (theirError != 0 && theirError != int(Sgp4Error::Decayed)) {
            ++bothFailed;
            continue;
        }
        const Vec3 r{f[1].toDouble(), f[2].toDouble(), f[3].toDouble()};
        const Vec3 v{f[4].toDouble(), f[5].toDouble(), f[6].toDouble()};
        const double dr = (ours.positionKm - r).norm() * 1000.0;
        const double dv = (ours.velocityKmS - v).norm() * 1e6;
        errors.append(dr);
        worst = std::max(worst, dr);
        worstVelocity = std::max(worstVelocity, dv);
        deepSpace += sgp4.isDeepSpace() ? 1 : 0;
        ++compared;
        QVERIFY2(dr <= 1.0, qPrintable(QStringLiteral("%1 (%2) at %3 min: %4 m from python3-sgp4")
                                           .arg(pairs[i].tle->catalogueNumber)
                                           .arg(pairs[i].tle->name)
                                           .arg(pairs[i].minutes)
                                           .arg(dr)));
    }
    QVERIFY(compared >= 1000);
    std::sort(errors.begin(), errors.end());
    qInfo("python3-sgp4 oracle: %d pairs compared (%d deep-space), %d failed alike", compared, deepSpace, bothFailed);
    qInfo("  position: median %.3g m, worst %.3g m; velocity worst %.3g mm/s", errors[errors.size() / 2], worst,
          worstVelocity);
}

QTEST_GUILESS_MAIN(TestSgp4Oracle)
#include "tst_sgp4oracle.moc"
