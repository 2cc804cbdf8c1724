// SPDX-License-Identifier: GPL-3.0-or-later
// The station service's pass records as a real process: `slew --headless`
// tracks a pass rehearsed at 20 times into --pass-db and is killed with
// SIGKILL mid-pass; the file has the pass in progress with its samples up
// to the last commit, a couple of seconds before the kill; the next start
// on the same file marks it interrupted. Then `slew --pass-report` draws
// it, and refuses an unknown pass, a dropped one, a number that is not
// one and a file that is not a database, writing nothing.

#include "records/passrecordstore.h"

#include <QDateTime>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

using slew::records::Outcome;
using slew::records::PassRecordStore;

namespace {

const QString kTle = QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle");
const QString kClockStart = QStringLiteral("2018-01-22T09:17:40Z");
constexpr double kRate = 20.0;

// `slew ARGS` with no display, and what it says as it comes.
struct Slew {
    QProcess process;
    QByteArray out;

    explicit Slew(const QStringList &arguments)
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        env.remove("QT_QPA_PLATFORM");
        process.setProcessEnvironment(env);
        process.start(qEnvironmentVariable("SLEW_BIN"), arguments);
    }
    bool logged(const QString &text, int ms = 20000)
    {
        return QTest::qWaitFor(
                   [&] {
                       out += process.readAllStandardOutput();
                       return out.contains(text.toUtf8()) || process.state() == QProcess::NotRunning;
                   },
                   ms)
               && out.contains(text.toUtf8());
    }
    QByteArray said() { return out + process.readAllStandardOutput() + process.readAllStandardError(); }
    bool finish(int ms = 20000)
    {
        if (process.state() == QProcess::NotRunning)
            return true;
        QSignalSpy finished(&process, &QProcess::finished);
        return finished.wait(ms);
    }
};

// A one-shot command: its exit code, and what it said.
int run(const QStringList &arguments, QByteArray *said = nullptr)
{
    Slew slew(arguments);
    if (!slew.finish())
        return -1;
    if (said)
        *said = slew.said();
    return slew.process.exitCode();
}

// The UTC time a log line of the service's was written, found by what it says.
QDateTime loggedAt(const QByteArray &log, const QString &text)
{
    for (const QByteArray &line : log.split('\n')) {
        if (line.contains(text.toUtf8()))
            return QDateTime::fromString(QString::fromUtf8(line.left(line.indexOf(' '))), Qt::ISODateWithMs);
    }
    return {};
}

} // namespace

class ServiceRecordsTest : public QObject {
    Q_OBJECT
private slots:
    void aKilledPassIsMarkedInterruptedAtTheNextStart()
    {
        QVERIFY(m_dir.isValid());
        Slew service({"--headless", "--connect", "sim:", "--limits", "0:450,0:180", "--qth", "JO65hq", "--tle", kTle,
                      "--track", "FLOCK 2P-1", "--clock-start", kClockStart, "--clock-rate", "20", "--pass-db", db()});
        QVERIFY2(service.logged(QStringLiteral("records: passes recorded in %1, a new file").arg(db())), service.said());
        QVERIFY2(service.logged(QStringLiteral("records: pass 1 (FLOCK 2P-1) in progress")), service.said());
        const QDateTime clockStarted = loggedAt(service.out, QStringLiteral("track: tracking FLOCK 2P-1"));
        QVERIFY(clockStarted.isValid());

        // Read while it is written, as a report would: the samples come in
        // a commit every two seconds.
        QString error;
        {
            PassRecordStore reader;
            QVERIFY2(reader.open(db(), PassRecordStore::Access::Read, &error), qPrintable(error));
            QVERIFY(QTest::qWaitFor([&] { return reader.samples(1).size() >= 40; }, 20000));
            QCOMPARE(reader.pass(1)->outcome, Outcome::InProgress);
        }

        const QDateTime killedAt = QDateTime::currentDateTimeUtc();
        ::kill(pid_t(service.process.processId()), SIGKILL);
        QVERIFY(service.finish());
        QCOMPARE(service.process.exitStatus(), QProcess::CrashExit);

        // In progress, with what was committed before the kill.
        {
            PassRecordStore after;
            QVERIFY2(after.open(db(), PassRecordStore::Access::Read, &error), qPrintable(error));
            const slew::records::PassRecord r = *after.pass(1);
            QCOMPARE(r.outcome, Outcome::InProgress);
            const QList<slew::records::PassSample> samples = after.samples(1);
            QVERIFY(samples.size() >= 40);
            QVERIFY(r.figures.commands && *r.figures.commands > 0);
            // How much of the pass the kill cost, in wall seconds: the
            // station clock at the kill, against the last sample kept.
            const QDateTime start = QDateTime::fromString(kClockStart, Qt::ISODate);
            const double stationAtKillMs =
                double(start.toMSecsSinceEpoch()) + kRate * double(clockStarted.msecsTo(killedAt));
            const double lostSeconds = (stationAtKillMs - double(samples.last().unixMs)) / kRate / 1000.0;
            qInfo("killed after %lld samples; the last kept was %.2f s of wall time before the kill", qint64(samples.size()),
                  lostSeconds);
            QVERIFY2(lostSeconds < PassRecordStore::kCommitIntervalMs / 1000.0 + 1.5, qPrintable(QString::number(lostSeconds)));
            QVERIFY(lostSeconds > -1.0);
            m_lastSampleMs = samples.last().unixMs;
        }

        // The next start on the same file, tracking nothing.
        Slew again({"--headless", "--connect", "sim:", "--pass-db", db()});
        QVERIFY2(again.logged(QStringLiteral("records: 1 pass left in progress by a Slew that stopped, marked interrupted")),
                 again.said());
        // The controller's answer comes from the event loop, after the
        // service has taken SIGTERM into its own hands.
        QVERIFY2(again.logged(QStringLiteral("controller: ")), again.said());
        ::kill(pid_t(again.process.processId()), SIGTERM);
        QVERIFY(again.finish());
        QCOMPARE(again.process.exitStatus(), QProcess::NormalExit);
        QCOMPARE(again.process.exitCode(), 0);
        PassRecordStore after;
        QVERIFY2(after.open(db(), PassRecordStore::Access::Read, &error), qPrintable(error));
        const slew::records::PassRecord r = *after.pass(1);
        QCOMPARE(r.outcome, Outcome::Interrupted);
        QCOMPARE(r.reason, QStringLiteral("Slew stopped during the pass (found at the next start)"));
        QCOMPARE(r.ended.toMSecsSinceEpoch(), m_lastSampleMs);
    }

    void drawsTheRecordedPass()
    {
        const QString png = m_dir.filePath(QStringLiteral("pass-1.png"));
        QByteArray said;
        QCOMPARE(run({"--pass-report", "1", "--out", png, "--pass-db", db()}, &said), 0);
        QVERIFY2(said.contains("pass 1 (FLOCK 2P-1, interrupted): "), said.constData());
        const QImage picture(png);
        QCOMPARE(picture.size(), QSize(1200, 900));
        // Not blank: the target's blue and the antenna's green are on it.
        int blue = 0, green = 0;
        for (int y = 0; y < picture.height(); ++y) {
            for (int x = 0; x < picture.width(); ++x) {
                const QColor c = picture.pixelColor(x, y);
                blue += c.blue() > 200 && c.red() < 120 ? 1 : 0;
                green += c.green() > 180 && c.red() < 120 && c.blue() < 140 ? 1 : 0;
            }
        }
        QVERIFY2(blue > 100 && green > 100, qPrintable(QStringLiteral("blue %1, green %2").arg(blue).arg(green)));
        if (const QByteArray dir = qgetenv("SLEW_SCREENSHOT_DIR"); !dir.isEmpty())
            QFile::copy(png, QString::fromLocal8Bit(dir) + QStringLiteral("/pass-report.png"));
    }

    void refusesWhatItCannotDrawAndWritesNothing()
    {
        const QString png = m_dir.filePath(QStringLiteral("nothing.png"));
        QByteArray said;
        QCOMPARE(run({"--pass-report", "99", "--out", png, "--pass-db", db()}, &said), 1);
        QVERIFY2(said.contains("no pass 99 in "), said.constData());
        QCOMPARE(run({"--pass-report", "abc", "--out", png, "--pass-db", db()}, &said), 2);
        QVERIFY2(said.contains("'abc' is not a whole number"), said.constData());
        QCOMPARE(run({"--pass-report", "0", "--out", png, "--pass-db", db()}), 2);
        QCOMPARE(run({"--pass-report", "1", "--pass-db", db()}), 2); // no --out
        QCOMPARE(run({"--pass-report", "1", "--out", png, "--pass-db", m_dir.filePath(QStringLiteral("none.sqlite"))}), 1);

        // A dropped pass has no samples to draw.
        {
            PassRecordStore store;
            QString error;
            QVERIFY2(store.open(db(), PassRecordStore::Access::Record, &error), qPrintable(error));
            slew::records::PassPlanned planned;
            planned.target = QStringLiteral("FLOCK 2P-1");
            planned.aos = QDateTime::currentDateTimeUtc();
            planned.los = planned.aos.addSecs(600);
            QCOMPARE(*store.recordDropped(planned, QStringLiteral("another pass had the rotator")), 2);
        }
        QCOMPARE(run({"--pass-report", "2", "--out", png, "--pass-db", db()}, &said), 1);
        QVERIFY2(said.contains("a dropped pass is not tracked"), said.constData());

        // A file that is not a database: named, and left as it is.
        const QString text = m_dir.filePath(QStringLiteral("notes.txt"));
        QFile notes(text);
        QVERIFY(notes.open(QIODevice::WriteOnly));
        notes.write("not a database\n");
        notes.close();
        QCOMPARE(run({"--pass-report", "1", "--out", png, "--pass-db", text}, &said), 2);
        QVERIFY2(said.contains(text.toUtf8() + " is not an SQLite database"), said.constData());
        QVERIFY(!QFile::exists(png));
        // And the service will not record into it.
        QCOMPARE(run({"--headless", "--connect", "sim:", "--pass-db", text}, &said), 2);
        QVERIFY2(said.contains("pass records: " + text.toUtf8()), said.constData());
        QFile check(text);
        QVERIFY(check.open(QIODevice::ReadOnly));
        QCOMPARE(check.readAll(), QByteArray("not a database\n"));
    }

private:
    QString db() const { return m_dir.filePath(QStringLiteral("passes.sqlite")); }

    QTemporaryDir m_dir;
    qint64 m_lastSampleMs = 0;
};

QTEST_GUILESS_MAIN(ServiceRecordsTest)
#include "tst_servicerecords.moc"
