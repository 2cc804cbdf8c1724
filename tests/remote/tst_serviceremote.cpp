// SPDX-License-Identifier: GPL-3.0-or-later
// The station service on a real broker: `slew --headless --mqtt …` as a
// process on the built-in simulator, a Mosquitto of the test's own with TLS,
// accounts and an access list, and mosquitto_sub / mosquitto_pub as the
// independent peers an operator's tools would be. Retained state appears;
// a go-to moves the simulator and is answered; an out-of-range go-to is
// refused in the gate's own words and nothing moves; a watcher's go-to is
// refused by the broker and never reaches the station; a wrong password is
// refused; a jog lease that is not renewed stops the rotator; a flood of
// commands is logged once; and a station that goes, cleanly or killed,
// says online = false.

#include "../common/mosquittobroker.h"
#include "../common/stationprocess.h"

#include "model/movegate.h"
#include "sky/elementsetformat.h"
#include "sky/utctime.h"
#include "remote/stationplan.h"
#include "remote/stationschedule.h"
#include "remote/stationstate.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <csignal>

namespace {

using Service = StationProcess;

QJsonObject json(const QByteArray &payload)
{
    return QJsonDocument::fromJson(payload).object();
}

// The last state the subscriber has seen, parsed.
std::optional<slew::face::StationState> lastState(MosquittoSubscriber &sub)
{
    const QList<QByteArray> all = sub.payloads(QStringLiteral("slew/mast/state"));
    if (all.isEmpty())
        return std::nullopt;
    QString error;
    return slew::remote::parseStationState(all.last(), &error);
}

} // namespace

class ServiceRemoteTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QString error;
        QVERIFY2(m_broker.start(&error), qPrintable(error));
    }

    void publishesRetainedStateAndObeys()
    {
        MosquittoSubscriber watcher(m_broker, QStringLiteral("watcher"),
                                    {QStringLiteral("slew/mast/#")});
        Service slew(stationArguments());
        QVERIFY2(slew.logged("remote: connected to mqtts://station-mast@localhost:"), slew.said().constData());

        // Online, and the retained state: the rotator connected, where it is.
        QVERIFY(watcher.waitFor(QStringLiteral("slew/mast/online"), [](const QByteArray &p) { return p == "true"; }));
        QVERIFY2(watcher.waitFor(QStringLiteral("slew/mast/state"),
                                 [](const QByteArray &p) {
                                     QString e;
                                     const auto s = slew::remote::parseStationState(p, &e);
                                     return s && s->link == u"connected" && s->position && !s->stale;
                                 }),
                 watcher.errors().constData());
        // Retained: a watcher who comes later has it at once.
        {
            QString error;
            QStringList once = m_broker.clientArguments(QStringLiteral("watcher"));
            once << QStringLiteral("-t") << QStringLiteral("slew/mast/state") << QStringLiteral("-C") << QStringLiteral("1")
                 << QStringLiteral("-W") << QStringLiteral("5");
            const auto late = MosquittoBroker::run(MosquittoBroker::program("mosquitto_sub"), once, &error);
            QVERIFY2(late && late->contains("\"link\":\"connected\""), qPrintable(error));
        }
        // Telemetry flows.
        QVERIFY(watcher.waitFor(QStringLiteral("slew/mast/telemetry"), [](const QByteArray &p) { return json(p).contains(QStringLiteral("az")); }));

        // A go-to from the operator's account moves the simulator, and is answered.
        QCOMPARE(m_broker.publish(QStringLiteral("operator"), QStringLiteral("slew/mast/command"),
                                  R"j({"id":"7","cmd":"goto","az":20,"el":10})j").exitCode,
                 0);
        QVERIFY(watcher.waitFor(QStringLiteral("slew/mast/reply"), [](const QByteArray &p) { return p == R"j({"id":"7","ok":true})j"; }));
        QVERIFY2(watcher.waitFor(QStringLiteral("slew/mast/state"),
                                 [](const QByteArray &p) {
                                     QString e;
                                     const auto s = slew::remote::parseStationState(p, &e);
                                     return s && s->position && std::abs(s->position->x() - 20) < 1
                                            && std::abs(s->position->y() - 10) < 1 && !s->moving;
                                 },
                                 30000),
                 slew.said().right(2000).constData());
        QVERIFY2(slew.logged("remote: go to az 20.0°, el 10.0° (id 7)"), slew.said().right(3000).constData());

        // Out of the travel: refused in the gate's words, and nothing moves.
        const auto before = lastState(watcher);
        QVERIFY(before && before->position);
        const QString gate = slew::model::MoveGate(slew::model::RotatorLimits{0, 450, 0, 180})
                                 .pointing(999, 30, before->position->x())
                                 .refusal;
        QVERIFY(!gate.isEmpty());
        QCOMPARE(m_broker.publish(QStringLiteral("operator"), QStringLiteral("slew/mast/command"),
                                  R"j({"id":"8","cmd":"goto","az":999,"el":30})j").exitCode,
                 0);
        const auto refusal = watcher.waitFor(QStringLiteral("slew/mast/reply"), [](const QByteArray &p) { return p.contains("\"id\":\"8\""); });
        QVERIFY(refusal);
        QCOMPARE(json(*refusal).value(QStringLiteral("ok")).toBool(true), false);
        QCOMPARE(json(*refusal).value(QStringLiteral("error")).toString(), gate);
        // Three telemetry samples after the refusal: all where it stood.
        const int seen = watcher.payloads(QStringLiteral("slew/mast/telemetry")).size();
        QVERIFY(QTest::qWaitFor([&] { return watcher.payloads(QStringLiteral("slew/mast/telemetry")).size() >= seen + 3; }, 15000));
        for (const QByteArray &p : watcher.payloads(QStringLiteral("slew/mast/telemetry")).mid(seen)) {
            QVERIFY2(std::abs(json(p).value(QStringLiteral("az")).toDouble(999) - before->position->x()) < 0.2, p.constData());
            QVERIFY2(std::abs(json(p).value(QStringLiteral("el")).toDouble(999) - before->position->y()) < 0.2, p.constData());
        }

        // A watcher may not command: the broker refuses the publish, and it
        // never reaches the station (the operator's stop after it does).
        const MosquittoBroker::PubResult denied = m_broker.publish(
            QStringLiteral("watcher"), QStringLiteral("slew/mast/command"), R"j({"id":"w1","cmd":"goto","az":100,"el":40})j");
        QVERIFY2(denied.said.contains("Not authorized"), denied.said.constData());
        QCOMPARE(m_broker.publish(QStringLiteral("operator"), QStringLiteral("slew/mast/command"),
                                  R"j({"id":"s1","cmd":"stop"})j").exitCode,
                 0);
        QVERIFY(watcher.waitFor(QStringLiteral("slew/mast/reply"), [](const QByteArray &p) { return p == R"j({"id":"s1","ok":true})j"; }));
        QVERIFY(!watcher.waitFor(QStringLiteral("slew/mast/reply"), [](const QByteArray &p) { return p.contains("w1"); }, 1));
        QVERIFY(slew.logged("remote: stop (id s1)"));
        QVERIFY(!slew.out.contains("(id w1)"));

        // A bad message changes nothing and is answered in words.
        QCOMPARE(m_broker.publish(QStringLiteral("operator"), QStringLiteral("slew/mast/command"),
                                  R"j({"id":"b1","cmd":"goto","az":"north","el":30})j").exitCode,
                 0);
        const auto bad = watcher.waitFor(QStringLiteral("slew/mast/reply"), [](const QByteArray &p) { return p.contains("\"id\":\"b1\""); });
        QVERIFY(bad);
        QCOMPARE(json(*bad).value(QStringLiteral("error")).toString(), QStringLiteral("'az' is not a number"));

        // A clean exit: the last state, then online = false, then gone.
        QCOMPARE(slew.stop(SIGTERM), 0);
        QVERIFY(watcher.waitFor(QStringLiteral("slew/mast/online"), [](const QByteArray &p) { return p == "false"; }, 5000));
        QVERIFY(slew.logged("stopping: signal 15"));
    }

    void aJogLeaseNotRenewedStopsTheRotator()
    {
        MosquittoSubscriber watcher(m_broker, QStringLiteral("watcher"), {QStringLiteral("slew/mast/#")});
        Service slew(stationArguments());
        QVERIFY2(slew.logged("remote: connected to "), slew.said().constData());
        QVERIFY(watcher.waitFor(QStringLiteral("slew/mast/state"), [](const QByteArray &p) { return p.contains("\"link\":\"connected\"") && p.contains("\"stale\":false"); }));
        // Jogging right at 5°/s, renewed four times, then never again.
        for (int i = 0; i < 4; ++i) {
            QCOMPARE(m_broker.publish(QStringLiteral("operator"), QStringLiteral("slew/mast/command"),
                                      QStringLiteral(R"j({"id":"j%1","cmd":"jog","az_speed":5,"el_speed":0,"lease_ms":1000})j").arg(i).toUtf8())
                         .exitCode,
                     0);
            QVERIFY(watcher.waitFor(QStringLiteral("slew/mast/reply"), [i](const QByteArray &p) { return p == QStringLiteral(R"j({"id":"j%1","ok":true})j").arg(i).toUtf8(); }));
        }
        QVERIFY(watcher.waitFor(QStringLiteral("slew/mast/state"), [](const QByteArray &p) { return p.contains("\"moving\":true"); }));
        // The lease runs out a second after the last renewal: the rotator stops.
        QVERIFY2(slew.logged("remote jog (az 5.0°/s, el 0.0°/s) not renewed within its lease of 1000 ms: stopped"),
                 slew.said().right(2000).constData());
        const int seen = watcher.payloads(QStringLiteral("slew/mast/state")).size();
        QVERIFY(watcher.waitFor(QStringLiteral("slew/mast/state"), [&](const QByteArray &p) {
            return p.contains("\"moving\":false") && watcher.payloads(QStringLiteral("slew/mast/state")).indexOf(p) >= seen;
        }));
        // And it stays stopped: three telemetry samples later, at one place.
        const int samples = watcher.payloads(QStringLiteral("slew/mast/telemetry")).size();
        QVERIFY(QTest::qWaitFor([&] { return watcher.payloads(QStringLiteral("slew/mast/telemetry")).size() >= samples + 4; }, 15000));
        const QList<QByteArray> after = watcher.payloads(QStringLiteral("slew/mast/telemetry")).mid(samples + 1);
        for (const QByteArray &p : after)
            QVERIFY2(std::abs(json(p).value(QStringLiteral("az")).toDouble() - json(after.first()).value(QStringLiteral("az")).toDouble()) < 0.05,
                     p.constData());
        QCOMPARE(slew.stop(SIGTERM), 0);
    }

    void aFloodOfCommandsIsLoggedOnce()
    {
        MosquittoSubscriber watcher(m_broker, QStringLiteral("watcher"), {QStringLiteral("slew/mast/reply")});
        Service slew(stationArguments());
        QVERIFY2(slew.logged("remote: connected to "), slew.said().constData());
        // 300 commands in one go, each on a line of mosquitto_pub -l.
        QProcess pub;
        QStringList arguments = m_broker.clientArguments(QStringLiteral("operator"));
        arguments << QStringLiteral("-q") << QStringLiteral("1") << QStringLiteral("-t") << QStringLiteral("slew/mast/command")
                  << QStringLiteral("-l");
        QSignalSpy finished(&pub, &QProcess::finished);
        pub.start(MosquittoBroker::program("mosquitto_pub"), arguments);
        QByteArray lines;
        for (int i = 0; i < 300; ++i)
            lines += QStringLiteral(R"j({"id":"f%1","cmd":"park"})j").arg(i).toUtf8() + '\n';
        pub.write(lines);
        pub.closeWriteChannel();
        QVERIFY(finished.wait(20000));
        QVERIFY2(slew.logged("remote: commands are arriving faster than 10 a second"), slew.said().constData());
        QVERIFY2(slew.logged("remote: the flood of commands has ended: "), slew.said().right(3000).constData());
        QCOMPARE(slew.out.count("arriving faster than"), 1);
        const QRegularExpressionMatch m = QRegularExpression(QStringLiteral("has ended: (\\d+) dropped")).match(QString::fromUtf8(slew.out));
        QVERIFY(m.hasMatch());
        QVERIFY2(m.captured(1).toInt() >= 200, qPrintable(m.captured(0)));
        // The log stays short: the commands it took are at most its burst.
        QVERIFY2(slew.out.count("remote: park") <= 30, slew.out.right(3000).constData());
        // Still obeying afterwards.
        QCOMPARE(m_broker.publish(QStringLiteral("operator"), QStringLiteral("slew/mast/command"), R"j({"id":"after","cmd":"stop"})j").exitCode, 0);
        QVERIFY(watcher.waitFor(QStringLiteral("slew/mast/reply"), [](const QByteArray &p) { return p == R"j({"id":"after","ok":true})j"; }));
        QCOMPARE(slew.stop(SIGTERM), 0);
    }

    void aKilledStationLeavesItsWill()
    {
        MosquittoSubscriber watcher(m_broker, QStringLiteral("watcher"), {QStringLiteral("slew/mast/online")});
        Service slew(stationArguments());
        QVERIFY2(slew.logged("remote: connected to "), slew.said().constData());
        QVERIFY(watcher.waitFor(QStringLiteral("slew/mast/online"), [](const QByteArray &p) { return p == "true"; }));
        const int before = watcher.payloads(QStringLiteral("slew/mast/online")).size();
        slew.stop(SIGKILL);
        // The broker sees the connection drop and publishes the will.
        QVERIFY(QTest::qWaitFor([&] {
            const auto all = watcher.payloads(QStringLiteral("slew/mast/online"));
            return all.size() > before && all.last() == "false";
        }, 20000));
    }

    void wrongPasswordsAreRefused()
    {
        // The station's own account with the wrong password (from the
        // environment this time): refused, said in the log, tried again later.
        QStringList arguments = stationArguments();
        const qsizetype file = arguments.indexOf(QStringLiteral("--mqtt-password-file"));
        arguments.remove(file, 2);
        Service slew(arguments, QStringLiteral("wrong"));
        QVERIFY2(slew.logged("the broker refused the connection"), slew.said().constData());
        QVERIFY2(slew.out.contains("user name or password") || slew.out.contains("authori"), slew.out.constData());
        QVERIFY(slew.logged("trying again in 1 s"));
        QCOMPARE(slew.stop(SIGTERM), 0);
        // And a peer with a wrong password gets nothing.
        QString error;
        QStringList sub = m_broker.clientArguments(QStringLiteral("watcher"), QStringLiteral("wrong"));
        sub << QStringLiteral("-t") << QStringLiteral("slew/#") << QStringLiteral("-C") << QStringLiteral("1")
            << QStringLiteral("-W") << QStringLiteral("5");
        QVERIFY(!MosquittoBroker::run(MosquittoBroker::program("mosquitto_sub"), sub, &error));
    }

    void publishesTheScheduleAndThePlan()
    {
        // Two targets by priority on a rehearsed clock at 20 times, from
        // inside FLOCK 2P-1's pass over JO65hq (09:15:45 to 09:27:10 UTC).
        // FLOCK 2P-1 carries a six-digit number, as every satellite
        // catalogued since July 2026 does, so the sets are GP CSV.
        QTemporaryDir dir;
        const QString gp = dir.filePath(QStringLiteral("gp.csv"));
        {
            QList<slew::sky::ElementSet> sets =
                slew::sky::readElementSetFile(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle")).sets;
            for (slew::sky::ElementSet &s : sets)
                if (s.name == u"FLOCK 2P-1")
                    s.catalogueNumber = 241617;
            QFile file(gp);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(slew::sky::writeElementSets(sets, slew::sky::ElementSetForm::Csv).bytes);
        }
        MosquittoSubscriber watcher(m_broker, QStringLiteral("watcher"),
                                    {QStringLiteral("slew/mast/schedule"), QStringLiteral("slew/mast/plan"),
                                     QStringLiteral("slew/mast/state")});
        Service slew(stationArguments()
                     + QStringList{"--qth", "JO65hq", "--tle", gp, "--track", "241617", "--track", "PERSEUS-M1",
                                   "--clock-start", "2018-01-22T09:16:00Z", "--clock-rate", "20"});
        QVERIFY2(slew.logged("remote: connected to mqtts://station-mast@localhost:"), slew.said().constData());

        // The schedule: both targets in their order, every pass with its
        // decision, and FLOCK 2P-1's pass the one being followed.
        std::optional<slew::face::StationSchedule> schedule;
        QVERIFY2(watcher.waitFor(QStringLiteral("slew/mast/schedule"),
                                 [&](const QByteArray &p) {
                                     QString e;
                                     schedule = slew::remote::parseStationSchedule(p, &e);
                                     return schedule && schedule->running && schedule->current;
                                 },
                                 60000),
                 (watcher.errors() + slew.said()).constData());
        QCOMPARE(schedule->schedule.targets, QStringList({"FLOCK 2P-1", "PERSEUS-M1"}));
        const slew::schedule::ScheduledPass &current = schedule->schedule.passes.at(*schedule->current);
        QCOMPARE(current.target, QStringLiteral("FLOCK 2P-1"));
        QVERIFY(current.taken);
        QVERIFY(schedule->clockRate == 20);
        // Under way when the schedule started at 09:16:00 (AOS 09:15:45 on
        // a flat horizon): highest, 56.4°, at 09:21:28.
        QVERIFY2(std::abs(current.pass.tca.julian - *slew::sky::julianFromIso(QStringLiteral("2018-01-22T09:21:28Z")))
                     * 86400 < 5,
                 qPrintable(slew::sky::isoUtc(current.pass.tca.julian)));
        QVERIFY2(std::abs(current.pass.maxElevationDeg() - 56.4) < 0.1, qPrintable(QString::number(current.pass.maxElevationDeg())));

        // The plan of that pass: its sky and the antenna's path, at most
        // kMostPlanPoints of each, the AOS point first.
        std::optional<slew::face::StationPlan> plan;
        QVERIFY2(watcher.waitFor(QStringLiteral("slew/mast/plan"),
                                 [&](const QByteArray &p) {
                                     QString e;
                                     plan = slew::remote::parseStationPlan(p, &e);
                                     return plan && plan->target == u"FLOCK 2P-1";
                                 },
                                 30000),
                 (watcher.errors() + slew.said()).constData());
        QVERIFY(plan->sky.size() > 50 && plan->sky.size() <= slew::remote::kMostPlanPoints);
        QVERIFY(plan->path.size() > 50 && plan->path.size() <= slew::remote::kMostPlanPoints);
        QVERIFY(plan->aosMs && plan->losMs && *plan->losMs - *plan->aosMs > 400000);
        QVERIFY(plan->maxElevation && *plan->maxElevation > 50);
        QVERIFY(plan->plannedWorstDeg && *plan->plannedWorstDeg < 1.0);
        QCOMPARE(plan->norad, 241617);
        // The state names the satellite by its number too.
        QVERIFY2(watcher.waitFor(QStringLiteral("slew/mast/state"),
                                 [&](const QByteArray &p) {
                                     QString e;
                                     const auto state = slew::remote::parseStationState(p, &e);
                                     return state && state->trackingNorad == 241617
                                            && state->trackingTarget == u"FLOCK 2P-1";
                                 },
                                 30000),
                 (watcher.errors() + slew.said()).constData());
        // Retained: a window that comes later has both at once.
        for (const char *topic : {"slew/mast/schedule", "slew/mast/plan"}) {
            QString error;
            QStringList once = m_broker.clientArguments(QStringLiteral("watcher"));
            once << QStringLiteral("-t") << QLatin1String(topic) << QStringLiteral("-C") << QStringLiteral("1")
                 << QStringLiteral("-W") << QStringLiteral("5");
            const auto late = MosquittoBroker::run(MosquittoBroker::program("mosquitto_sub"), once, &error);
            QVERIFY2(late && late->contains("\"target\":\"FLOCK 2P-1\""), qPrintable(topic + (": " + error)));
        }
        // At rest between changes it publishes nothing more here: a handful
        // of schedules and plans over the pass, not one a state.
        // After LOS the schedule goes on to its next pass: the plan that
        // says so is the last message of this pass.
        QVERIFY(slew.logged("LOS: pointing error RMS", 60000));
        const qint64 followedAos = *plan->aosMs;
        QVERIFY2(watcher.waitFor(QStringLiteral("slew/mast/plan"),
                                 [&](const QByteArray &p) {
                                     QString e;
                                     const auto next = slew::remote::parseStationPlan(p, &e);
                                     return next && next->aosMs.value_or(0) > followedAos; // a later pass
                                 },
                                 30000),
                 (watcher.errors() + slew.said()).constData());
        const int schedules = int(watcher.payloads(QStringLiteral("slew/mast/schedule")).size());
        const int plans = int(watcher.payloads(QStringLiteral("slew/mast/plan")).size());
        QVERIFY2(schedules < 10 && plans < 10, qPrintable(QStringLiteral("%1 schedules, %2 plans").arg(schedules).arg(plans)));
        QCOMPARE(slew.stop(SIGTERM), 0);
    }

    void badSettingsStopItAtStart()
    {
        auto refused = [](const QStringList &arguments, const char *text) {
            Service slew(arguments);
            QSignalSpy finished(&slew.process, &QProcess::finished);
            if (slew.process.state() != QProcess::NotRunning)
                finished.wait(15000);
            const QByteArray said = slew.said();
            return slew.process.exitCode() == 2 && said.contains(text) ? QByteArray() : said;
        };
        const QString pw = m_broker.passwordFile(QStringLiteral("station-mast"));
        QByteArray said = refused({"--connect", "sim:", "--mqtt", "mqtt://station-mast@192.0.2.1", "--station-name", "mast",
                                   "--mqtt-password-file", pw},
                                  "in the clear");
        QVERIFY2(said.isEmpty(), said.constData());
        said = refused({"--connect", "sim:", "--mqtt", "mqtts://a:b@localhost", "--station-name", "mast"}, "no password in the address");
        QVERIFY2(said.isEmpty(), said.constData());
        said = refused({"--connect", "sim:", "--mqtt", m_broker.url(QStringLiteral("station-mast"))}, "needs --station-name");
        QVERIFY2(said.isEmpty(), said.constData());
        said = refused({"--connect", "sim:", "--mqtt", m_broker.url(QStringLiteral("station-mast")), "--station-name", "ma/st"},
                       "--station-name: 'ma/st'");
        QVERIFY2(said.isEmpty(), said.constData());
        said = refused({"--connect", "sim:", "--station-name", "mast"}, "--station-name goes with --mqtt");
        QVERIFY2(said.isEmpty(), said.constData());
        said = refused({"--connect", "sim:", "--mqtt", m_broker.url(QStringLiteral("station-mast")), "--station-name", "mast",
                        "--mqtt-password-file", "/dev/zero"},
                       "--mqtt-password-file: password file");
        QVERIFY2(said.isEmpty(), said.constData());
    }

private:
    QStringList stationArguments() const
    {
        return {QStringLiteral("--connect"), QStringLiteral("sim:?start_az=10&start_el=5"), QStringLiteral("--limits"),
                QStringLiteral("0:450,0:180"), QStringLiteral("--mqtt"), m_broker.url(QStringLiteral("station-mast")),
                QStringLiteral("--station-name"), QStringLiteral("mast"), QStringLiteral("--mqtt-password-file"),
                m_broker.passwordFile(QStringLiteral("station-mast"))};
    }

    MosquittoBroker m_broker;
};

QTEST_GUILESS_MAIN(ServiceRemoteTest)
#include "tst_serviceremote.moc"
