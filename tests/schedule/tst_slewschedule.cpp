// SPDX-License-Identifier: GPL-3.0-or-later
// The schedule from the command line: `slew --schedule` prints the plan (and
// JSON), with the station's horizon from --horizon or the one the window
// keeps; the station service runs a schedule when --track is given more
// than once (and from `track` lines in its config file), logging every
// decision; and every way of asking badly is refused, saying which option.

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

namespace {

const QString kTle = QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle");

struct Run {
    int exitCode = -1;
    QByteArray out, err;
};

QTemporaryDir &home()
{
    static QTemporaryDir dir;
    return dir;
}

Run runSlew(const QStringList &arguments)
{
    Run r;
    QProcess p;
    // Settings from a directory of the test's, never the user's own.
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), home().path());
    env.remove(QStringLiteral("DISPLAY"));
    p.setProcessEnvironment(env);
    p.start(qEnvironmentVariable("SLEW_BIN"), arguments);
    if (!p.waitForFinished(120000))
        return r;
    r.exitCode = p.exitCode();
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

QString write(const QString &name, const QByteArray &text)
{
    const QString path = home().filePath(name);
    QFile f(path);
    if (f.open(QIODevice::WriteOnly))
        f.write(text);
    return path;
}

// 2018-01-22 09:00 to 10:00 over JO65hq: FLOCK 2P-1's pass of 09:15:45 to
// 09:27:10 (56°), ENVISAT's of 09:25:31 (over its end) and PERSEUS-M1's of
// 09:27:59.
const QStringList kPlan{"--schedule", "--track", "FLOCK 2P-1", "--track", "ENVISAT", "--track", "PERSEUS-M1",
                        "--qth", "JO65hq", "--tle", kTle, "--start", "2018-01-22T09:00:00Z", "--hours", "1"};

} // namespace

class SlewScheduleTest : public QObject {
    Q_OBJECT
private slots:
    void printsThePlan()
    {
        const Run r = runSlew(kPlan);
        QCOMPARE(r.exitCode, 0);
        const QString out = QString::fromUtf8(r.out);
        QVERIFY2(out.contains("priority 1: FLOCK 2P-1\npriority 2: ENVISAT\npriority 3: PERSEUS-M1\n"), qPrintable(out));
        QVERIFY2(out.contains("2018-01-22 09:15:45–09:27:10 UTC  FLOCK 2P-1 [1]  max 56.4°  taken (plan worst "),
                 qPrintable(out));
        QVERIFY2(out.contains("ENVISAT [2]  max 24.7°  dropped: overlaps FLOCK 2P-1 (priority 1, 09:15:45–09:27:10 UTC)"),
                 qPrintable(out));
        QVERIFY(out.contains("PERSEUS-M1 [3]"));
        QVERIFY(out.contains(" taken, ") && out.contains(" dropped, 2018-01-22 09:00 to 2018-01-22 10:00 UTC"));

        // A day's limit: FLOCK 2P-1's elements (epoch 2018-01-20 22:08) are
        // 1.5 days from its AOS, and the pass is dropped, saying so.
        const Run strict = runSlew(kPlan + QStringList{"--max-element-age", "1"});
        QCOMPARE(strict.exitCode, 0);
        const QString dropped = QString::fromUtf8(strict.out);
        QVERIFY2(dropped.contains("FLOCK 2P-1 [1]  max 56.4°  dropped: its elements are 1.5 days from AOS (epoch "
                                  "2018-01-20T22:08:"),
                 qPrintable(dropped));
        QVERIFY2(dropped.contains("the limit is 1 days"), qPrintable(dropped));
    }

    void printsJson()
    {
        const Run r = runSlew(kPlan + QStringList{"--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject json = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(json["targets"].toArray().size(), 3);
        QCOMPARE(json["start"].toString(), QStringLiteral("2018-01-22T09:00:00.000Z"));
        bool sawDrop = false;
        for (const QJsonValue &v : json["passes"].toArray()) {
            const QJsonObject p = v.toObject();
            if (p["target"].toString() == "ENVISAT" && !p["taken"].toBool()) {
                sawDrop = true;
                QCOMPARE(p["reason"].toString(), QStringLiteral("overlap"));
                QVERIFY(p["norad"].isDouble());
            }
        }
        QVERIFY(sawDrop);
    }

    void theHorizonHidesAPass()
    {
        // A ridge of 30° all round: ENVISAT (24.7°) never clears it.
        const QString ridge = write("ridge.horizon", "# all round\n0 30\n");
        const Run r = runSlew(kPlan + QStringList{"--horizon", ridge});
        QCOMPARE(r.exitCode, 0);
        const QString out = QString::fromUtf8(r.out);
        QVERIFY2(out.contains("ENVISAT [2]  max 24.7°  dropped: never clears the horizon mask: highest 24.7°"),
                 qPrintable(out));
        QVERIFY2(out.contains("\nhorizon mask: 1 point, 30.0° to 30.0°"), qPrintable(out)); // under the station's line
        // --passes too: FLOCK's pass now rises on the ridge.
        const Run passes = runSlew({"--passes", "FLOCK 2P-1", "--qth", "JO65hq", "--tle", kTle, "--start",
                                    "2018-01-22T09:00:00Z", "--hours", "1", "--min-el", "0", "--horizon", ridge,
                                    "--json"});
        QCOMPARE(passes.exitCode, 0);
        const QJsonArray list = QJsonDocument::fromJson(passes.out).array();
        QCOMPARE(list.size(), 1);
        // Without the ridge it rises at 09:15:45; on it, at 09:19:54.
        QCOMPARE(list.at(0).toObject()["aos"].toObject()["time"].toString(), QStringLiteral("2018-01-22T09:19:54Z"));
        QCOMPARE(list.at(0).toObject()["max_elevation"].toDouble(), 56.4);
    }

    void theWindowsHorizonIsTheSavedStations()
    {
        // Saved as the window saves them (Sky → Station…): --qth left out, the
        // station and its mask come from the settings.
        const QString wall = write("wall.horizon", "0 30\n");
        {
            QSettings settings(home().filePath(QStringLiteral("Slew/slew.conf")), QSettings::IniFormat);
            settings.setValue("sky/station", "JO65hq");
            settings.setValue("sky/horizonFile", wall);
        }
        QStringList arguments = kPlan;
        arguments.removeAt(arguments.indexOf("--qth") + 1);
        arguments.removeAll("--qth");
        const Run r = runSlew(arguments);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(r.out.contains("dropped: never clears the horizon mask"), r.out.constData());
        QSettings(home().filePath(QStringLiteral("Slew/slew.conf")), QSettings::IniFormat).clear();
    }

    void refusesWhatItCannotUse_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        const QStringList base{"--schedule", "--qth", "JO65hq", "--tle", kTle};
        QTest::newRow("no target") << base << "--schedule needs --track";
        QTest::newRow("unknown") << base + QStringList{"--track", "NO SUCH SAT"} << "--track: ";
        QTest::newRow("twice") << base + QStringList{"--track", "FLOCK 2P-1", "--track", "41617"}
                               << "--track 41617: FLOCK 2P-1 is given twice";
        QTest::newRow("hours nan") << base + QStringList{"--track", "sun", "--hours", "nan"}
                                   << "--hours: 'nan' is not a finite number";
        QTest::newRow("hours too many") << base + QStringList{"--track", "sun", "--hours", "1000"} << "--hours: 1000";
        QTest::newRow("guard") << base + QStringList{"--track", "sun", "--guard", "-1"} << "--guard: -1";
        QTest::newRow("max-element-age") << base + QStringList{"--track", "sun", "--max-element-age", "0.1"}
                                         << "--max-element-age: 0.1";
        QTest::newRow("horizon device") << base + QStringList{"--track", "sun", "--horizon", "/dev/zero"}
                                        << "--horizon: /dev/zero is a character device";
        QTest::newRow("horizon bad line")
            << base + QStringList{"--track", "sun", "--horizon", write("bad.horizon", "0 5\n90 nan\n")}
            << "bad.horizon:2: elevation 'nan' is not a finite number";
        QTest::newRow("start") << base + QStringList{"--track", "sun", "--start", "yesterday"} << "--start wants";
    }

    void refusesWhatItCannotUse()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        const Run r = runSlew(arguments);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message.toUtf8()), r.err.constData());
        QVERIFY(r.out.isEmpty());
    }

    void theServiceRunsASchedule()
    {
        // From a config file, a track line each, and the horizon with it.
        const QString ridge = write("service.horizon", "0 2\n180 2\n");
        const QString config = write("station.conf", QStringLiteral("connect = sim:\nqth = JO65hq\nhorizon = %1\n"
                                                                    "tle = %2\ntrack = FLOCK 2P-1\ntrack = ENVISAT\n"
                                                                    "track = PERSEUS-M1\n")
                                                         .arg(ridge, kTle)
                                                         .toUtf8());
        QProcess slew;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), home().path());
        env.remove(QStringLiteral("DISPLAY"));
        slew.setProcessEnvironment(env);
        // A rehearsal: the elements are of 2018.
        slew.start(qEnvironmentVariable("SLEW_BIN"),
                   {"--headless", "--config", config, "--clock-start", "2018-01-22T09:20:00Z"});
        QByteArray out;
        // The plan's lines follow its heading and may arrive in a later read: wait for the last one looked for.
        const auto planPrinted = [&] {
            return out.contains("schedule: planned (started)") && out.contains("FLOCK 2P-1 [1]") &&
                   out.contains("ENVISAT [2]") && out.contains("dropped: overlaps FLOCK 2P-1");
        };
        const bool planned = QTest::qWaitFor(
            [&] {
                out += slew.readAllStandardOutput();
                return planPrinted() || slew.state() == QProcess::NotRunning;
            },
            30000);
        QVERIFY2(planned && out.contains("schedule: planned (started)"), (out + slew.readAllStandardError()).constData());
        QVERIFY2(out.contains("schedule: targets by priority: 1. FLOCK 2P-1, 2. ENVISAT, 3. PERSEUS-M1"), out.constData());
        QVERIFY2(out.contains("horizon mask: 2 points"), out.constData());
        QVERIFY2(out.contains("FLOCK 2P-1 [1]") && out.contains("ENVISAT [2]") && out.contains("dropped: overlaps FLOCK 2P-1"),
                 out.constData());
        ::kill(pid_t(slew.processId()), SIGTERM);
        QVERIFY(QTest::qWaitFor([&] { return slew.state() == QProcess::NotRunning; }, 10000));
        QCOMPARE(slew.exitCode(), 0);

        // The command line's --track replaces the file's: one target, no schedule.
        const Run single = runSlew({"--headless", "--config", config, "--track", "FLOCK 2P-1", "--guard", "10"});
        QCOMPARE(single.exitCode, 2);
        QVERIFY2(single.err.contains("--guard goes with a schedule: --track given more than once"), single.err.constData());
        const Run noQth = runSlew({"--headless", "--horizon", ridge});
        QCOMPARE(noQth.exitCode, 2);
        QVERIFY2(noQth.err.contains("--horizon goes with --qth"), noQth.err.constData());
    }
};

QTEST_GUILESS_MAIN(SlewScheduleTest)
#include "tst_slewschedule.moc"
