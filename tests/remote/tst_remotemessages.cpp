// SPDX-License-Identifier: GPL-3.0-or-later
// What travels over the broker, read under the input rules: the broker's
// address (TLS, no password in it, plain mqtt:// only to this machine), the
// password file, station names and topics, commands and replies, a
// station's state, telemetry, plan and schedule. Tables of good and bad messages; a bad one
// is refused whole, naming its field.

#include "remote/brokeraddress.h"
#include "remote/brokerpassword.h"
#include "remote/remotecommand.h"
#include "remote/stationplan.h"
#include "remote/stationschedule.h"
#include "remote/stationstate.h"
#include "remote/stationtelemetry.h"
#include "remote/stationtopics.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace slew::remote;
using namespace slew::face;

class RemoteMessagesTest : public QObject {
    Q_OBJECT
private slots:
    void brokerAddresses_data()
    {
        QTest::addColumn<QString>("url");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<QString>("expected"); // display() when ok, else a piece of the refusal
        QTest::newRow("tls") << "mqtts://ops@broker.example:8883" << true << "mqtts://ops@broker.example:8883";
        QTest::newRow("tls default port") << "mqtts://ops@broker.example" << true << "mqtts://ops@broker.example:8883";
        QTest::newRow("plain loopback") << "mqtt://ops@127.0.0.1" << true << "mqtt://ops@127.0.0.1:1883";
        QTest::newRow("plain localhost") << "mqtt://localhost:1884" << true << "mqtt://localhost:1884";
        QTest::newRow("plain ipv6 loopback") << "mqtt://[::1]:1883" << true << "mqtt://[::1]:1883";
        QTest::newRow("plain remote") << "mqtt://ops@broker.example" << false << "in the clear";
        QTest::newRow("plain lan") << "mqtt://192.168.1.10" << false << "in the clear";
        QTest::newRow("password") << "mqtts://ops:hunter2@broker.example" << false << "no password in the address";
        QTest::newRow("scheme") << "http://broker.example" << false << "not a broker's address";
        QTest::newRow("no host") << "mqtts://" << false << "names no broker host";
        QTest::newRow("unknown query") << "mqtts://h?insecure=1" << false << "unknown setting 'insecure'";
        QTest::newRow("cafile plain") << "mqtt://localhost?cafile=/tmp/ca.pem" << false << "goes with mqtts://";
        QTest::newRow("wildcard name") << "mqtts://h/+" << false << "wildcards";
        QTest::newRow("deep name") << "mqtts://h/a/b" << false << "wildcards";
    }
    void brokerAddresses()
    {
        QFETCH(QString, url);
        QFETCH(bool, ok);
        QFETCH(QString, expected);
        QString error;
        const auto address = parseBrokerAddress(url, &error);
        QCOMPARE(address.has_value(), ok);
        if (ok)
            QCOMPARE(address->display(), expected);
        else
            QVERIFY2(error.contains(expected), qPrintable(error));
    }

    void addressParts()
    {
        QString error;
        const auto a = parseBrokerAddress(QStringLiteral("mqtts://ops@broker.example:8884/mast?cafile=/etc/slew/ca.pem"), &error);
        QVERIFY2(a, qPrintable(error));
        QVERIFY(a->tls);
        QCOMPARE(a->user, QStringLiteral("ops"));
        QCOMPARE(a->host, QStringLiteral("broker.example"));
        QCOMPARE(a->port, quint16(8884));
        QCOMPARE(a->stationName, QStringLiteral("mast"));
        QCOMPARE(a->caFile, QStringLiteral("/etc/slew/ca.pem"));
    }

    void passwordFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("pw"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("s3cret\r\nsecond line\n");
        f.close();
        QString error;
        // Readable by everyone: refused, and says how to fix it.
        f.setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ReadOther);
        QVERIFY(!readPasswordFile(path, &error));
        QVERIFY2(error.contains(QStringLiteral("chmod")), qPrintable(error));
        f.setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner);
        QCOMPARE(readPasswordFile(path, &error).value_or(QString()), QStringLiteral("s3cret"));
        QVERIFY(!readPasswordFile(QStringLiteral("/dev/zero"), &error));
        QVERIFY(!readPasswordFile(dir.filePath(QStringLiteral("missing")), &error));
        qputenv(kPasswordVariable, "from-env");
        QCOMPARE(brokerPassword({}, &error).value_or(QString()), QStringLiteral("from-env"));
        qunsetenv(kPasswordVariable);
    }

    void topics()
    {
        QCOMPARE(stationTopic(QStringLiteral("mast"), StationTopic::State), QStringLiteral("slew/mast/state"));
        QCOMPARE(stationFilter(QStringLiteral("mast")), QStringLiteral("slew/mast/#"));
        QCOMPARE(everyStationFilter(StationTopic::Online), QStringLiteral("slew/+/online"));
        const auto t = parseStationTopic(QStringLiteral("slew/dish-2/telemetry"));
        QVERIFY(t);
        QCOMPARE(t->stationName, QStringLiteral("dish-2"));
        QCOMPARE(t->topic, StationTopic::Telemetry);
        QVERIFY(!parseStationTopic(QStringLiteral("slew/dish-2/other")));
        QVERIFY(!parseStationTopic(QStringLiteral("slew/a/b/state")));
        QVERIFY(!parseStationTopic(QStringLiteral("other/dish/state")));
        QVERIFY(!checkStationName(QStringLiteral("a#")).isEmpty());
        QVERIFY(!checkStationName(QString(65, u'a')).isEmpty());
        QVERIFY(checkStationName(QStringLiteral("JO65hq_dish-1.a")).isEmpty());
    }

    void commands_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("error"); // empty: accepted
        QTest::addColumn<QString>("id");
        QTest::newRow("goto") << QByteArray(R"j({"id":"7","cmd":"goto","az":120,"el":30})j") << "" << "7";
        QTest::newRow("numeric id") << QByteArray(R"j({"id":42,"cmd":"stop"})j") << "" << "42";
        QTest::newRow("no id") << QByteArray(R"j({"cmd":"park"})j") << "" << "";
        QTest::newRow("jog") << QByteArray(R"j({"id":"j","cmd":"jog","az_speed":-5.0,"el_speed":0,"lease_ms":1000})j") << "" << "j";
        QTest::newRow("track") << QByteArray(R"j({"id":"t","cmd":"track","target":"ISS (ZARYA)","min_el":5})j") << "" << "t";
        QTest::newRow("goto out of range reaches the gate") << QByteArray(R"j({"id":"g","cmd":"goto","az":999,"el":30})j") << "" << "g";
        QTest::newRow("not json") << QByteArray("goto 1 2") << "not JSON" << "";
        QTest::newRow("array") << QByteArray("[1]") << "not a JSON object" << "";
        QTest::newRow("unknown cmd") << QByteArray(R"j({"id":"1","cmd":"fire"})j") << "unknown command 'fire'" << "1";
        QTest::newRow("missing el") << QByteArray(R"j({"id":"1","cmd":"goto","az":1})j") << "'el' is missing" << "1";
        QTest::newRow("text az") << QByteArray(R"j({"id":"1","cmd":"goto","az":"1","el":2})j") << "'az' is not a number" << "1";
        // Qt's JSON reader refuses a number past a double's range outright.
        QTest::newRow("huge az") << QByteArray(R"j({"id":"1","cmd":"goto","az":1e999,"el":2})j") << "not JSON" << "";
        QTest::newRow("negative lease") << QByteArray(R"j({"id":"2","cmd":"jog","az_speed":1,"lease_ms":-1})j") << "'lease_ms'" << "2";
        QTest::newRow("jog too fast") << QByteArray(R"j({"cmd":"jog","az_speed":500})j") << "'az_speed'" << "";
        QTest::newRow("lease too long") << QByteArray(R"j({"cmd":"jog","az_speed":5,"lease_ms":60000})j") << "'lease_ms'" << "";
        QTest::newRow("lease fraction") << QByteArray(R"j({"cmd":"jog","az_speed":5,"lease_ms":500.5})j") << "whole number" << "";
        QTest::newRow("jog no speed") << QByteArray(R"j({"cmd":"jog"})j") << "names az_speed" << "";
        QTest::newRow("extra field") << QByteArray(R"j({"id":"1","cmd":"stop","force":true})j") << "unknown field 'force'" << "1";
        QTest::newRow("escape in target") << QByteArray("{\"cmd\":\"track\",\"target\":\"a\\u001b[2Jb\"}") << "control characters" << "";
        QTest::newRow("long id") << (QByteArray("{\"id\":\"") + QByteArray(100, 'x') + "\",\"cmd\":\"stop\"}") << "'id'" << "";
        QTest::newRow("too large") << (QByteArray("{\"cmd\":\"stop\",\"pad\":\"") + QByteArray(40000, ' ') + "\"}") << "over the" << "";
        QTest::newRow("schedule") << QByteArray(R"j({"id":"s","cmd":"schedule","targets":["FLOCK 2P-1","43218"],"hours":12,"min_el":5,"guard_s":60})j") << "" << "s";
        QTest::newRow("schedule with defaults") << QByteArray(R"j({"cmd":"schedule","targets":["sun"]})j") << "" << "";
        QTest::newRow("schedule of nothing is the station's to refuse") << QByteArray(R"j({"cmd":"schedule","targets":[]})j") << "" << "";
        QTest::newRow("unschedule") << QByteArray(R"j({"id":"u","cmd":"unschedule"})j") << "" << "u";
        QTest::newRow("clear the motion guard's fault") << QByteArray(R"j({"id":"c","cmd":"clear_fault"})j") << "" << "c";
        QTest::newRow("schedule preview") << QByteArray(R"j({"id":"p","cmd":"schedule_preview","targets":["AO-91","sun"],"hours":12})j") << "" << "p";
        QTest::newRow("radio hold") << QByteArray(R"j({"id":"r","cmd":"radio_hold","held":true})j") << "" << "r";
        QTest::newRow("radio release") << QByteArray(R"j({"cmd":"radio_hold","held":false})j") << "" << "";
        QTest::newRow("schedule without targets") << QByteArray(R"j({"id":"1","cmd":"schedule"})j") << "'targets' is missing" << "1";
        QTest::newRow("schedule of a number") << QByteArray(R"j({"id":"1","cmd":"schedule","targets":["sun",25544]})j") << "'targets' holds an item that is not text" << "1";
        QTest::newRow("schedule of one text") << QByteArray(R"j({"cmd":"schedule","targets":"sun"})j") << "'targets' is not a list" << "";
        QTest::newRow("schedule of an empty name") << QByteArray(R"j({"cmd":"schedule","targets":["sun"," "]})j") << "'targets' item 2 is empty" << "";
        QTest::newRow("schedule with a long name") << (QByteArray(R"j({"cmd":"schedule","targets":[")j") + QByteArray(101, 'x') + "\"]}") << "'targets' holds an item" << "";
        QTest::newRow("schedule with an escape") << QByteArray("{\"cmd\":\"schedule\",\"targets\":[\"a\\u001b[2Jb\"]}") << "control characters" << "";
        QTest::newRow("schedule for negative hours") << QByteArray(R"j({"id":"2","cmd":"schedule","targets":["sun"],"hours":-1})j") << "'hours'" << "2";
        QTest::newRow("schedule for a month") << QByteArray(R"j({"cmd":"schedule","targets":["sun"],"hours":720})j") << "'hours'" << "";
        QTest::newRow("schedule below the ground") << QByteArray(R"j({"cmd":"schedule","targets":["sun"],"min_el":-30})j") << "'min_el'" << "";
        QTest::newRow("schedule with a guard of a day") << QByteArray(R"j({"cmd":"schedule","targets":["sun"],"guard_s":86400})j") << "'guard_s'" << "";
        QTest::newRow("schedule with text hours") << QByteArray(R"j({"cmd":"schedule","targets":["sun"],"hours":"24"})j") << "'hours' is not a number" << "";
        QTest::newRow("schedule with a lease") << QByteArray(R"j({"cmd":"schedule","targets":["sun"],"lease_ms":100})j") << "unknown field 'lease_ms'" << "";
        QTest::newRow("schedule preview with no id to answer by") << QByteArray(R"j({"cmd":"schedule_preview","targets":["sun"]})j") << "needs an 'id'" << "";
        QTest::newRow("schedule preview for a month") << QByteArray(R"j({"id":"q","cmd":"schedule_preview","targets":["sun"],"hours":720})j") << "'hours'" << "q";
        QTest::newRow("clear a fault with an axis") << QByteArray(R"j({"cmd":"clear_fault","axis":"az"})j") << "unknown field 'axis'" << "";
        QTest::newRow("unschedule with targets") << QByteArray(R"j({"cmd":"unschedule","targets":["sun"]})j") << "unknown field 'targets'" << "";
        QTest::newRow("radio hold not a flag") << QByteArray(R"j({"id":"3","cmd":"radio_hold","held":1})j") << "'held' is not true or false" << "3";
        QTest::newRow("radio hold as text") << QByteArray(R"j({"cmd":"radio_hold","held":"true"})j") << "'held' is not true or false" << "";
        QTest::newRow("radio hold unsaid") << QByteArray(R"j({"cmd":"radio_hold"})j") << "'held' is missing" << "";
        QTest::newRow("radio hold with a frequency") << QByteArray(R"j({"cmd":"radio_hold","held":true,"hz":145800000})j") << "unknown field 'hz'" << "";
        QByteArray many = R"j({"cmd":"schedule","targets":[)j";
        for (int i = 0; i <= kMostScheduleTargets; ++i)
            many += (i ? ",\"" : "\"") + QByteArray::number(40000 + i) + "\"";
        QTest::newRow("schedule of too many") << many + "]}" << QStringLiteral("'targets' has %1 items, over the %2").arg(kMostScheduleTargets + 1).arg(kMostScheduleTargets) << "";
    }

    // The largest schedule a station takes, every name as long as it may
    // be in three-byte characters, is a command it reads.
    void theLargestScheduleFits()
    {
        RemoteCommand c;
        c.id = QString(kLongestCommandId, QLatin1Char('i'));
        c.kind = RemoteCommand::Kind::Schedule;
        for (int i = 0; i < kMostScheduleTargets; ++i)
            c.targets << QString(kLongestTrackTarget, QChar(0x20ac)); // €, three bytes in UTF-8
        c.schedule = {168.0 - 1.0 / 3.0, -4.123456789, 3599.987654321};
        const ParsedCommand parsed = parseRemoteCommand(encodeRemoteCommand(c));
        QVERIFY2(parsed.command, qPrintable(parsed.error));
        QCOMPARE(parsed.command->targets, c.targets);
    }
    void commands()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, error);
        QFETCH(QString, id);
        const ParsedCommand parsed = parseRemoteCommand(json);
        QCOMPARE(parsed.id, id);
        if (error.isEmpty()) {
            QVERIFY2(parsed.command, qPrintable(parsed.error));
            // What a window sends reads back the same.
            const ParsedCommand again = parseRemoteCommand(encodeRemoteCommand(*parsed.command));
            QVERIFY(again.command);
            QCOMPARE(again.command->kind, parsed.command->kind);
            QCOMPARE(again.command->azimuth, parsed.command->azimuth);
            QCOMPARE(again.command->azSpeed, parsed.command->azSpeed);
            QCOMPARE(again.command->leaseMs, parsed.command->leaseMs);
            QCOMPARE(again.command->target, parsed.command->target);
            QCOMPARE(again.command->targets, parsed.command->targets);
            QCOMPARE(again.command->schedule.hours, parsed.command->schedule.hours);
            QCOMPARE(again.command->schedule.minElevationDeg, parsed.command->schedule.minElevationDeg);
            QCOMPARE(again.command->schedule.guardSeconds, parsed.command->schedule.guardSeconds);
            QCOMPARE(again.command->held, parsed.command->held);
        } else {
            QVERIFY(!parsed.command);
            QVERIFY2(parsed.error.contains(error), qPrintable(parsed.error));
        }
    }

    void replies()
    {
        QString error;
        const auto ok = parseRemoteReply(encodeRemoteReply({QStringLiteral("7"), true, {}, std::nullopt}), &error);
        QVERIFY(ok && ok->ok && ok->id == QStringLiteral("7"));
        const auto no = parseRemoteReply(R"j({"id":"7","ok":false,"error":"azimuth 999.0° is outside 0..360°"})j", &error);
        QVERIFY(no && !no->ok);
        QCOMPARE(no->error, QStringLiteral("azimuth 999.0° is outside 0..360°"));
        QVERIFY(!parseRemoteReply(R"j({"id":"7","ok":false})j", &error));
        // Found by fuzz_remotemessages: a refusal must say why.
        QVERIFY(!parseRemoteReply(R"j({"id":"7","ok":false,"error":""})j", &error));
        QVERIFY2(error.contains(QStringLiteral("without its reason")), qPrintable(error));
        QVERIFY(!parseRemoteReply(R"j({"id":"7","ok":"yes"})j", &error));
    }

    // The answer to a schedule_preview: each target as the station named
    // it, and the plan of those found, or why none was made.
    void previewReplies()
    {
        slew::face::SchedulePreview p;
        p.targets = {{QStringLiteral("ao-91"), QStringLiteral("FOX-1B (AO-91)"), 43017, {}},
                     {QStringLiteral("NO SUCH"), {}, 0, QStringLiteral("no satellite 'NO SUCH' among the station's element sets")},
                     {QStringLiteral("sun"), QStringLiteral("Sun"), 0, {}}};
        p.schedule.settings.startJulian = 2458140.5;
        p.schedule.settings.hours = 12;
        p.schedule.targets = {QStringLiteral("FOX-1B (AO-91)"), QStringLiteral("Sun")};
        slew::schedule::ScheduledPass pass;
        pass.target = p.schedule.targets[0];
        pass.norad = 43017;
        pass.pass.aos.julian = pass.startJulian = 2458140.6;
        pass.pass.tca.julian = 2458140.603;
        pass.pass.los.julian = pass.endJulian = 2458140.606;
        pass.pass.tca.elevationDeg = 33;
        pass.taken = true;
        p.schedule.passes = {pass};
        QString error;
        const auto back = parseRemoteReply(encodeRemoteReply({QStringLiteral("9"), true, {}, p}), &error);
        QVERIFY2(back && back->preview, qPrintable(error));
        QCOMPARE(back->preview->targets.size(), 3);
        QCOMPARE(back->preview->targets[0].name, QStringLiteral("FOX-1B (AO-91)"));
        QCOMPARE(back->preview->targets[0].spec(), QStringLiteral("43017"));
        QCOMPARE(back->preview->targets[1].problem, p.targets[1].problem);
        QCOMPARE(back->preview->targets[2].spec(), QStringLiteral("sun"));
        QCOMPARE(back->preview->schedule.targets, p.schedule.targets);
        QCOMPARE(back->preview->schedule.passes.size(), 1);
        QCOMPARE(back->preview->schedule.settings.hours, 12.0);
        // Named, not planned.
        slew::face::SchedulePreview unplanned;
        unplanned.targets = {p.targets[2]};
        unplanned.notPlanned = QStringLiteral("a schedule needs the station's place");
        const auto named = parseRemoteReply(encodeRemoteReply({QStringLiteral("10"), true, {}, unplanned}), &error);
        QVERIFY2(named && named->preview, qPrintable(error));
        QCOMPARE(named->preview->notPlanned, unplanned.notPlanned);
        QVERIFY(named->preview->schedule.passes.isEmpty());
        // A refusal carries no preview.
        QVERIFY(!encodeRemoteReply({QStringLiteral("11"), false, QStringLiteral("no"), p}).contains("preview"));
        // Bad ones, refused whole.
        const char *bad[][2] = {
            {R"j({"id":"1","ok":true,"preview":{"named":[{"asked":"x"}]}})j", "a name or a problem"},
            {R"j({"id":"1","ok":true,"preview":{"named":[{"asked":"x","name":"X","problem":"no"}]}})j", "a name or a problem"},
            {R"j({"id":"1","ok":true,"preview":{"named":[{"asked":"x","problem":"no","norad":5}]}})j", "no catalogue number"},
            {R"j({"id":"1","ok":true,"preview":{}})j", "'named' is missing"},
            {R"j({"id":"1","ok":true,"preview":[]})j", "not an object"},
            {R"j({"id":"1","ok":false,"error":"no","preview":{"named":[]}})j", "a refusal with a preview"},
            {R"j({"id":"1","ok":true,"preview":{"named":[],"not_planned":"no place","start_ms":1000,"end_ms":2000,"passes":[]}})j", "not_planned"},
            {R"j({"id":"1","ok":true,"preview":{"named":[],"current":0}})j", "unknown field 'current'"},
        };
        for (const auto &b : bad) {
            QVERIFY2(!parseRemoteReply(b[0], &error), b[0]);
            QVERIFY2(error.contains(QString::fromUtf8(b[1])), qPrintable(error));
        }
    }

    void stateRoundTrip()
    {
        StationState s;
        s.unixMs = 1790000000123;
        s.link = QStringLiteral("connected");
        s.position = QPointF(120.5, 30.25);
        s.stale = false;
        s.target = QPointF(200, 45);
        s.moving = true;
        s.limits = {0, 450, 0, 180};
        s.park = QPointF(0, 90);
        s.tracking = QStringLiteral("tracking");
        s.trackingTarget = QStringLiteral("GP TEST LEO-9");
        s.trackingNorad = 270033591; // nine digits
        s.clockMs = 1516612740000; // a rehearsal's clock, at twice real time
        s.clockRate = 2.0;
        s.passAosMs = 1790000000000;
        s.passLosMs = 1790000600000;
        s.passMaxElevation = 56.1;
        s.alarms = {QStringLiteral("GE: motor error")};
        s.severe = true;
        s.operatorHold = true;
        s.motionHeld = true;
        s.controllerVersion = QStringLiteral("SatNOGS 1.2");
        s.slewVersion = QStringLiteral("0.1.0");
        // What a face shows besides: each axis' status, the controller's
        // errors and what it can do, the profile's own travel.
        s.azimuthStatus = QStringLiteral("moving, pointing");
        s.elevationStatus = QStringLiteral("at rest");
        s.axisError = true;
        s.homingFailed = true;
        s.controllerErrors = QStringLiteral("homing error");
        s.dialect = QStringLiteral("easycomm3");
        s.probed = true;
        s.jogSpeed = false;
        s.canHome = false;
        s.parkCommand = false;
        s.profileLimits = {0, 450, 0, 90};
        s.radioLink = QStringLiteral("reconnecting");
        s.radioHeld = true;
        s.radioSteering = true;
        s.radioReceiveHz = 435123456.5;
        s.radioTransmitHz = 145912345;
        QString error;
        const auto back = parseStationState(encodeStationState(s), &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(encodeStationState(*back), encodeStationState(s));
        QCOMPARE(back->elevationStatus, s.elevationStatus);
        QVERIFY(back->operatorHold && back->motionHeld);
        QCOMPARE(back->profileLimits.elMax, 90.0);
        QVERIFY(!back->jogSpeed && !back->canHome && !back->parkCommand && back->homingFailed);
        // A station that says none of these: what most controllers can, and
        // the travel in force for the profile's.
        const QByteArray older = R"j({"unix_ms":1,"link":"connected","az_min":0,"az_max":360,"el_min":0,"el_max":90})j";
        const auto old = parseStationState(older, &error);
        QVERIFY2(old, qPrintable(error));
        QVERIFY(old->jogSpeed && old->canHome && old->parkCommand && !old->probed && !old->azimuthStatus);
        QCOMPARE(old->profileLimits, old->limits);
        QCOMPARE(back->clockMs, s.clockMs);
        QCOMPARE(back->clockRate, 2.0);
        QCOMPARE(back->radioLink, s.radioLink);
        QVERIFY(back->radioHeld && back->radioSteering);
        QCOMPARE(back->radioReceiveHz, s.radioReceiveHz);
        QCOMPARE(back->radioTransmitHz, s.radioTransmitHz);
        // A station with no radio says so; one that has not read it yet
        // says no frequency.
        s.radioLink = QStringLiteral("none");
        s.radioHeld = s.radioSteering = false;
        s.radioReceiveHz.reset();
        s.radioTransmitHz.reset();
        const QByteArray none = encodeStationState(s);
        QVERIFY(!none.contains("radio_rx_hz") && !none.contains("radio_tx_hz"));
        QCOMPARE(parseStationState(none, &error)->radioLink, QStringLiteral("none"));
        // On the wall clock: neither is sent, and the rate reads 1.
        s.clockMs.reset();
        const QByteArray wall = encodeStationState(s);
        QVERIFY(!wall.contains("clock_ms") && !wall.contains("clock_rate"));
        QCOMPARE(parseStationState(wall, &error)->clockRate, 1.0);
    }

    void badStates_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("error");
        const QByteArray base = R"j("unix_ms":1,"link":"connected","az_min":0,"az_max":360,"el_min":0,"el_max":90)j";
        QTest::newRow("good") << "{" + base + "}" << "";
        QTest::newRow("az alone") << "{" + base + R"j(,"az":3})j" << "come together";
        QTest::newRow("az out") << "{" + base + R"j(,"az":9999,"el":3})j" << "'az'";
        QTest::newRow("bad link") << QByteArray(R"j({"unix_ms":1,"link":"up","az_min":0,"az_max":360,"el_min":0,"el_max":90})j") << "'link'";
        QTest::newRow("travel backwards") << QByteArray(R"j({"unix_ms":1,"link":"connected","az_min":300,"az_max":10,"el_min":0,"el_max":90})j") << "travel";
        QTest::newRow("alarm escape") << "{" + base + ",\"alarms\":[\"\\u001b[31m\"]}" << "'alarms'";
        QTest::newRow("unknown") << "{" + base + R"j(,"x":1})j" << "unknown field";
        QTest::newRow("ten-digit norad") << "{" + base + R"j(,"tracking_norad":1000000000})j" << "'tracking_norad'";
        QTest::newRow("clock too fast") << "{" + base + R"j(,"clock_ms":1,"clock_rate":1000})j" << "'clock_rate'";
        QTest::newRow("clock backwards") << "{" + base + R"j(,"clock_ms":1,"clock_rate":-1})j" << "'clock_rate'";
        QTest::newRow("profile travel backwards") << "{" + base + R"j(,"profile_az_min":300,"profile_az_max":10})j" << "profile's travel";
        QTest::newRow("status not words") << "{" + base + R"j(,"az_status":5})j" << "'az_status'";
        QTest::newRow("homing failed not a flag") << "{" + base + R"j(,"homing_failed":"yes"})j" << "'homing_failed'";
        QTest::newRow("negative time") << QByteArray(R"j({"unix_ms":-5,"link":"connected","az_min":0,"az_max":360,"el_min":0,"el_max":90})j") << "'unix_ms'";
        QTest::newRow("radio") << "{" + base + R"j(,"radio_link":"connected","radio_held":false,"radio_steering":true,"radio_rx_hz":145800000})j" << "";
        QTest::newRow("no radio") << "{" + base + R"j(,"radio_link":"none","radio_held":true,"radio_steering":false})j" << "";
        QTest::newRow("radio link unknown") << "{" + base + R"j(,"radio_link":"up"})j" << "'radio_link'";
        QTest::newRow("radio link a flag") << "{" + base + R"j(,"radio_link":true})j" << "'radio_link' is not text";
        QTest::newRow("radio held as text") << "{" + base + R"j(,"radio_link":"connected","radio_held":"yes"})j" << "'radio_held'";
        QTest::newRow("radio steering a number") << "{" + base + R"j(,"radio_link":"connected","radio_steering":1})j" << "'radio_steering'";
        QTest::newRow("radio below 1 Hz") << "{" + base + R"j(,"radio_link":"connected","radio_rx_hz":-145800000})j" << "'radio_rx_hz'";
        QTest::newRow("radio past a terahertz") << "{" + base + R"j(,"radio_link":"connected","radio_tx_hz":1e13})j" << "'radio_tx_hz'";
        QTest::newRow("radio frequency as text") << "{" + base + R"j(,"radio_link":"connected","radio_rx_hz":"145.8 MHz"})j" << "'radio_rx_hz'";
        QTest::newRow("radio hold without its link") << "{" + base + R"j(,"radio_held":true})j" << "'radio_held' comes with 'radio_link'";
    }
    void badStates()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, error);
        QString why;
        const auto s = parseStationState(json, &why);
        QVERIFY2(s.has_value() == error.isEmpty(), qPrintable(why));
        if (!error.isEmpty())
            QVERIFY2(why.contains(error), qPrintable(why));
    }

    // A station older than the radio's fields says none of them: its state
    // still reads, with the radio not said (not "none": it may have one).
    void aStateWithoutTheRadioStillReads()
    {
        const QByteArray older = R"j({"unix_ms":1790000000123,"time":"2026-09-21T12:53:20.123Z","link":"connected","az":120,"el":30,"stale":false,"moving":false,"az_min":0,"az_max":450,"el_min":0,"el_max":180,"azimuth_only":false,"tracking":"off","alarms":[],"severe":false,"operator_hold":false,"slew":"0.1.0"})j";
        QString error;
        const auto s = parseStationState(older, &error);
        QVERIFY2(s, qPrintable(error));
        QVERIFY(s->radioLink.isEmpty());
        QVERIFY(!s->radioHeld && !s->radioSteering && !s->radioReceiveHz && !s->radioTransmitHz);
        QVERIFY(!encodeStationState(*s).contains("radio"));
    }

    void telemetry()
    {
        TelemetrySample t;
        t.unixMs = 5;
        t.az = 1.5;
        t.azSpeed = -3;
        t.gs = 0x0402;
        t.pointingError = 0.2;
        QString error;
        const auto back = parseTelemetry(encodeTelemetry(t), &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->az, t.az);
        QCOMPARE(back->azSpeed, t.azSpeed);
        QCOMPARE(back->gs, t.gs);
        QVERIFY(!back->el);
        QVERIFY(!parseTelemetry(R"j({"unix_ms":5,"temperature":1e400})j", &error));
        QVERIFY(!parseTelemetry(R"j({"unix_ms":5,"gs":70000})j", &error));
        QVERIFY2(error.contains(QStringLiteral("'gs'")), qPrintable(error));
    }
    void planRoundTrip()
    {
        StationPlan p;
        p.unixMs = 1516612671000;
        p.target = QStringLiteral("FLOCK 2P-1");
        p.norad = 43218;
        p.aosMs = 1516612671000;
        p.tcaMs = 1516612891000;
        p.losMs = 1516613104000;
        p.maxElevation = 56.2;
        p.plannedWorstDeg = 0.21;
        p.flipped = true;
        p.azimuthTurnEnd = 360;
        // A pass sampled each second: thinned to the most a message takes,
        // its first and last points kept.
        for (int i = 0; i < 1000; ++i) {
            p.sky.append(QPointF(350 + i * 0.2, 10 + i * 0.04));
            p.path.append(QPointF(350 + i * 0.2, 10 + i * 0.04));
        }
        QString error;
        const auto back = parseStationPlan(encodeStationPlan(p), &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->target, p.target);
        QCOMPARE(back->norad, p.norad);
        QCOMPARE(back->losMs, p.losMs);
        QVERIFY(back->flipped);
        QVERIFY(back->sky.size() <= kMostPlanPoints && back->sky.size() > kMostPlanPoints / 2);
        QCOMPARE(back->sky.first(), p.sky.first());
        QVERIFY(std::abs(back->sky.last().x() - p.sky.last().x()) < 1e-6);
        // No pass ahead: no target, no path.
        const auto none = parseStationPlan(encodeStationPlan(StationPlan{}), &error);
        QVERIFY2(none && none->target.isEmpty() && none->sky.isEmpty(), qPrintable(error));
    }

    void badPlans_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("error");
        QTest::newRow("good") << QByteArray(R"j({"unix_ms":1,"target":"X","sky":[[1,2]],"path":[[1,2]]})j") << "";
        QTest::newRow("a path with no target") << QByteArray(R"j({"unix_ms":1,"sky":[[1,2]]})j") << "without a 'target'";
        QTest::newRow("a point of three") << QByteArray(R"j({"unix_ms":1,"target":"X","sky":[[1,2,3]]})j") << "'sky' point 1";
        QTest::newRow("a point as text") << QByteArray(R"j({"unix_ms":1,"target":"X","path":[["1",2]]})j") << "'path' point 1";
        QTest::newRow("elevation out") << QByteArray(R"j({"unix_ms":1,"target":"X","sky":[[1,2],[3,400]]})j") << "'sky' point 2";
        QTest::newRow("los before aos") << QByteArray(R"j({"unix_ms":1,"target":"X","aos_ms":5,"los_ms":4})j") << "before";
        QTest::newRow("target with escape") << QByteArray("{\"unix_ms\":1,\"target\":\"\\u001b[2J\"}") << "'target'";
        QTest::newRow("unknown") << QByteArray(R"j({"unix_ms":1,"x":1})j") << "unknown field";
        QByteArray many = R"j({"unix_ms":1,"target":"X","sky":[)j";
        for (int i = 0; i <= kMostPlanPoints; ++i)
            many += (i ? ",[1,2]" : "[1,2]");
        QTest::newRow("too many points") << many + "]}" << "over the";
    }
    void badPlans()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, error);
        QString why;
        const auto p = parseStationPlan(json, &why);
        QCOMPARE(p.has_value(), error.isEmpty());
        if (!error.isEmpty())
            QVERIFY2(why.contains(error), qPrintable(why));
    }

    void scheduleRoundTrip()
    {
        slew::schedule::Schedule s;
        s.settings.startJulian = 2458140.5;
        s.settings.hours = 24;
        s.settings.guardSeconds = 30;
        s.targets = {QStringLiteral("FLOCK 2P-1"), QStringLiteral("PERSEUS-M1")};
        slew::schedule::ScheduledPass taken;
        taken.target = s.targets[0];
        taken.norad = 43218;
        taken.pass.aos.julian = 2458140.8874;
        taken.pass.tca.julian = 2458140.8900;
        taken.pass.los.julian = 2458140.8924;
        taken.pass.tca.elevationDeg = 56.2;
        taken.pass.aos.azimuthDeg = 350.5;
        taken.startJulian = taken.pass.aos.julian;
        taken.endJulian = taken.pass.los.julian;
        taken.taken = true;
        slew::schedule::ScheduledPass dropped = taken;
        dropped.target = s.targets[1];
        dropped.priority = 1;
        dropped.norad = 0;
        dropped.taken = false;
        dropped.reason = slew::schedule::DropReason::Overlap;
        dropped.why = QStringLiteral("overlaps FLOCK 2P-1 (priority 1)");
        s.passes = {taken, dropped};
        QString error;
        const auto back = parseStationSchedule(encodeStationSchedule(1516612671000, 1516612000000, 20, true, s, taken), &error);
        QVERIFY2(back, qPrintable(error));
        QVERIFY(back->running && back->planned);
        QCOMPARE(back->clockRate, 20.0);
        QCOMPARE(back->clockMs, 1516612000000);
        QCOMPARE(back->schedule.targets, s.targets);
        QCOMPARE(back->schedule.passes.size(), 2);
        QCOMPARE(back->current, std::optional<int>(0));
        QCOMPARE(back->schedule.passes[1].reason, slew::schedule::DropReason::Overlap);
        QCOMPARE(back->schedule.passes[1].why, dropped.why);
        QCOMPARE(back->schedule.passes[1].priority, 1);
        QVERIFY(std::abs(back->schedule.passes[0].pass.los.julian - taken.pass.los.julian) * 86400 < 0.002);
        QCOMPARE(back->schedule.passes[0].pass.maxElevationDeg(), 56.2);
        // Running, its first plan not made yet: no window, no passes.
        const auto planning = parseStationSchedule(encodeStationSchedule(1, 1, 1, true, slew::schedule::Schedule{}, std::nullopt), &error);
        QVERIFY2(planning && planning->running && !planning->planned, qPrintable(error));
        // Not running: nothing but that.
        const auto idle = parseStationSchedule(encodeStationSchedule(1, 1, 1, false, s, std::nullopt), &error);
        QVERIFY2(idle && !idle->running && idle->schedule.passes.isEmpty(), qPrintable(error));
    }

    void badSchedules_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("error");
        const QByteArray head = R"j({"unix_ms":1,"running":true,"start_ms":1000,"end_ms":86401000,"targets":["A"],)j";
        const QByteArray pass = R"j("target":"A","priority":1,"aos_ms":2000,"tca_ms":3000,"los_ms":4000,"start_ms":2000,"end_ms":4000,"max_el":40)j";
        QTest::newRow("good") << head + R"j("passes":[{)j" + pass + R"j(,"taken":true,"reason":"taken"}],"current":0})j" << "";
        QTest::newRow("a priority past the list")
            << head + R"j("passes":[{"target":"A","priority":2,"aos_ms":2000,"tca_ms":3000,"los_ms":4000,"start_ms":2000,"end_ms":4000,"max_el":40,"taken":true,"reason":"taken"}]})j"
            << "'priority'";
        QTest::newRow("reason against taken") << head + R"j("passes":[{)j" + pass + R"j(,"taken":true,"reason":"overlap"}]})j" << "disagree";
        QTest::newRow("a reason unheard of") << head + R"j("passes":[{)j" + pass + R"j(,"taken":false,"reason":"bored"}]})j" << "'reason'";
        QTest::newRow("times out of order")
            << head + R"j("passes":[{"target":"A","priority":1,"aos_ms":5000,"tca_ms":3000,"los_ms":4000,"start_ms":2000,"end_ms":4000,"max_el":40,"taken":true,"reason":"taken"}]})j"
            << "out of order";
        QTest::newRow("current a dropped pass") << head + R"j("passes":[{)j" + pass + R"j(,"taken":false,"reason":"overlap"}],"current":0})j" << "'current'";
        QTest::newRow("current past the list") << head + R"j("passes":[],"current":3})j" << "'current'";
        QTest::newRow("a pass not an object") << head + R"j("passes":[7]})j" << "not an object";
        QTest::newRow("a year long") << QByteArray(R"j({"unix_ms":1,"running":true,"start_ms":1000,"end_ms":31536001000})j") << "14 days";
        QTest::newRow("being planned") << QByteArray(R"j({"unix_ms":1,"running":true,"targets":["A"]})j") << "";
        QTest::newRow("a start with no end") << QByteArray(R"j({"unix_ms":1,"running":true,"start_ms":1000})j") << "come together";
        QTest::newRow("passes with no window") << QByteArray(R"j({"unix_ms":1,"running":true,"targets":["A"],"passes":[]})j") << "'start_ms' is missing";
        QTest::newRow("passes when not running") << QByteArray(R"j({"unix_ms":1,"running":false,"start_ms":1000,"end_ms":2000,"passes":[]})j") << "not running";
        QTest::newRow("unknown in a pass") << head + R"j("passes":[{)j" + pass + R"j(,"taken":true,"reason":"taken","x":1}]})j" << "pass 1: unknown field";
    }
    void badSchedules()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, error);
        QString why;
        const auto s = parseStationSchedule(json, &why);
        QCOMPARE(s.has_value(), error.isEmpty());
        if (!error.isEmpty())
            QVERIFY2(why.contains(error), qPrintable(why));
    }
};

QTEST_GUILESS_MAIN(RemoteMessagesTest)
#include "tst_remotemessages.moc"
