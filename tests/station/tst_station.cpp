// SPDX-License-Identifier: GPL-3.0-or-later
// A Station driven with no window, as the station service and a remote face
// would drive it: connect to the built-in simulator, a tracker's `P` through
// the rotctld server, Slew's own tracking of a fixed direction with the
// reverse hold (trackers held off while it tracks, its tracking refused
// while a tracker steers), the operator's Stop holding trackers off until
// control is handed back, an alarm raised and cleared and written to the
// service's log in the banner's words, every rotor stopped before exit, the
// rules for a schedule's numbers and end and for the radio's hold, and the
// radio as the face's state says it.

#include "../common/simulatorpump.h"
#include "linkschemes.h"

#include "bridge/rotctldserver.h"
#include "face/stationface.h"
#include "session/rotatorsession.h"
#include "station/alarmmonitor.h"
#include "station/dopplerradio.h"
#include "station/schedulerunner.h"
#include "station/station.h"
#include "station/stationlog.h"
#include "tracking/passrunner.h"
#include "tracking/tracktarget.h"

#include <QSignalSpy>
#include <QTcpSocket>
#include <QTest>

#include <cstdio>

using slew::station::AlarmMonitor;
using slew::station::DopplerRadio;
using slew::station::Station;
using slew::station::StationOptions;

namespace {

const slew::sky::Site kPlace{55.7, 12.6, 10, {}, {}};

StationOptions onTheSimulator(const QString &uri)
{
    StationOptions options;
    options.autoReconnect = true;
    slew::model::RotatorProfile profile;
    profile.uri = uri;
    options.profile = profile;
    return options;
}

// A rotctld client (Gpredict's part): one line out, one answer back.
class Tracker {
public:
    explicit Tracker(quint16 port)
    {
        m_socket.connectToHost(QHostAddress::LocalHost, port);
    }
    bool connected() { return runEventLoopUntil([&] { return m_socket.state() == QAbstractSocket::ConnectedState; }, 5000); }
    // `lines`: how many lines the answer has (`p` gives two).
    QByteArray ask(const QByteArray &line, int lines = 1)
    {
        m_socket.write(line + '\n');
        QByteArray reply;
        runEventLoopUntil(
            [&] {
                reply += m_socket.readAll();
                return reply.count('\n') >= lines;
            },
            5000);
        return reply;
    }

private:
    QTcpSocket m_socket;
};

// Connects the station's rotor to its simulator, pumped on its manual
// clock, and waits for the probe and a position.
bool connectAndWait(Station &station, SimulatorPump &pump)
{
    slew::session::RotatorSession *rotor = station.session();
    pump.follow(rotor);
    station.connectRotators();
    return runEventLoopUntil([&] { return rotor->capabilities().probed && rotor->hasPosition(); }, 10000);
}

bool listening(slew::bridge::RotctldServer *server)
{
    QString error;
    const bool ok = server->listen(QHostAddress::LocalHost, 0, &error);
    if (!ok)
        qWarning("rotctld server: %s", qPrintable(error));
    return ok;
}

// What a StationLog wrote, read back from its file.
QString logText(std::FILE *file)
{
    std::fflush(file);
    const long size = std::ftell(file);
    QByteArray bytes(qsizetype(size), '\0');
    std::rewind(file);
    const size_t got = std::fread(bytes.data(), 1, size_t(size), file);
    std::fseek(file, 0, SEEK_END);
    return QString::fromUtf8(bytes.left(qsizetype(got)));
}

} // namespace

class StationTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void tracksAndHoldsTrackersOffWithNoWindow()
    {
        Station station(onTheSimulator(QStringLiteral("sim:?model=satnogs&clock=manual")));
        QVERIFY(station.isValid());
        slew::session::RotatorSession *rotor = station.session();
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));

        slew::bridge::RotctldServer *server = station.server();
        QVERIFY(listening(server));
        Tracker gpredict(server->port());
        QVERIFY(gpredict.connected());
        QCOMPARE(gpredict.ask("P 120 30"), QByteArray("RPRT 0\n"));
        QVERIFY(runEventLoopUntil([&] { return std::abs(rotor->azimuth() - 120) < 0.5 && std::abs(rotor->elevation() - 30) < 0.5; },
                                  20000));

        // While that tracker steers, Slew's own tracking is refused, saying who.
        const auto fixed = slew::tracking::TrackTarget::parseFixedOrCelestial(QStringLiteral("azel:200,40"), nullptr);
        QVERIFY(fixed);
        QCOMPARE(station.track(*fixed, 0.0).reason(), QStringLiteral("tracking needs the station's place"));
        station.setPlace(kPlace);
        const QString refused = station.track(*fixed, 0.0).reason();
        QVERIFY2(refused.startsWith(QStringLiteral("Remote tracker 127.0.0.1:")) && refused.contains(QStringLiteral("is steering")),
                 qPrintable(refused));
        QVERIFY(!station.passRunner()->isRunning());
    }

    void ownTrackingHoldsTrackersOff()
    {
        Station station(onTheSimulator(QStringLiteral("sim:?model=satnogs&clock=manual")));
        slew::session::RotatorSession *rotor = station.session();
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));
        slew::bridge::RotctldServer *server = station.server();
        QVERIFY(listening(server));

        station.setPlace(kPlace);
        QSignalSpy tracking(&station, &Station::trackingChanged);
        const auto fixed = slew::tracking::TrackTarget::parseFixedOrCelestial(QStringLiteral("azel:200,40"), nullptr);
        QCOMPARE(station.track(*fixed, 0.0).reason(), QString());
        QVERIFY(runEventLoopUntil([&] { return station.passRunner()->holdsRotator(); }, 10000));
        QCOMPARE(tracking.count(), 1);
        QVERIFY(tracking.last().at(0).toBool());
        QVERIFY(server->isRemoteHeld());
        QVERIFY(runEventLoopUntil([&] { return std::abs(rotor->azimuth() - 200) < 0.5 && std::abs(rotor->elevation() - 40) < 0.5; },
                                  30000));

        // A tracker's move is refused (Hamlib's -9) while Slew tracks; its
        // reads are still answered.
        Tracker gpredict(server->port());
        QVERIFY(gpredict.connected());
        QCOMPARE(gpredict.ask("P 10 10"), QByteArray("RPRT -9\n"));
        const QList<QByteArray> position = gpredict.ask("p", 2).split('\n');
        QCOMPARE(position.size(), 3);
        QVERIFY(std::abs(position[0].toDouble() - 200) < 1.0);

        // Tracking handed back: the tracker steers again.
        station.untrack(QStringLiteral("test"));
        QVERIFY(runEventLoopUntil([&] { return !server->isRemoteHeld(); }, 5000));
        QVERIFY(!tracking.last().at(0).toBool());
        QCOMPARE(gpredict.ask("P 10 10"), QByteArray("RPRT 0\n"));
    }

    void theOperatorsStopHoldsTrackersOffUntilHandedBack()
    {
        Station station(onTheSimulator(QStringLiteral("sim:?model=satnogs&clock=manual")));
        slew::session::RotatorSession *rotor = station.session();
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));
        slew::bridge::RotctldServer *server = station.server();
        QVERIFY(listening(server));
        Tracker gpredict(server->port());
        QVERIFY(gpredict.connected());
        QCOMPARE(gpredict.ask("P 90 45"), QByteArray("RPRT 0\n"));

        QSignalSpy sent(rotor, &slew::session::RotatorSession::bytesSent);
        QVERIFY(station.stop(QStringLiteral("the test")));
        QVERIFY(!sent.isEmpty()); // the stop went out at once
        QVERIFY(server->isRemoteHeld());
        QCOMPARE(gpredict.ask("P 90 45"), QByteArray("RPRT -9\n"));
        QVERIFY(gpredict.ask("S").startsWith("RPRT 0")); // a stop is always obeyed
        station.handControlBack();
        QCOMPARE(gpredict.ask("P 90 45"), QByteArray("RPRT 0\n"));
    }

    void aJamIsLoggedInTheBannersWords()
    {
        Station station(onTheSimulator(QStringLiteral("sim:?jam=az&jam_after=0.3&clock=manual")));
        std::FILE *file = std::tmpfile();
        QVERIFY(file);
        slew::station::StationLog log(&station, file);
        slew::session::RotatorSession *rotor = station.session();
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));

        AlarmMonitor *alarms = station.alarms();
        QSignalSpy raised(alarms, &AlarmMonitor::alarmRaised);
        QSignalSpy cleared(alarms, &AlarmMonitor::alarmCleared);
        QVERIFY(rotor->gotoPosition(90, 0));
        QVERIFY(runEventLoopUntil([&] { return alarms->anySevere(); }, 15000));
        // What the window's banner shows (AlarmBanner::showAlarms is given
        // activeAlarms()), the service's log says, word for word.
        const QStringList banner = alarms->activeAlarms();
        QVERIFY(!banner.isEmpty());
        QVERIFY(runEventLoopUntil([&] {
            const QString text = logText(file);
            return std::all_of(banner.begin(), banner.end(),
                               [&](const QString &a) { return text.contains(QStringLiteral("alarm: ") + a); });
        }, 5000));

        // A disconnect clears what can no longer be known; the log says so.
        station.disconnectRotators();
        QVERIFY(runEventLoopUntil([&] { return alarms->activeAlarms().isEmpty(); }, 5000));
        QVERIFY(!cleared.isEmpty());
        const QString text = logText(file);
        for (const QString &a : banner)
            QVERIFY2(text.contains(QStringLiteral("cleared: ") + a), qPrintable(text));
        std::fclose(file);
    }

    void everyRotorStopsBeforeExit()
    {
        Station station(onTheSimulator(QStringLiteral("sim:?model=satnogs&clock=manual")));
        slew::session::RotatorSession *rotor = station.session();
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));
        slew::bridge::RotctldServer *server = station.server();
        QVERIFY(listening(server));
        QVERIFY(rotor->gotoPosition(300, 60));

        QStringList sent;
        connect(rotor, &slew::session::RotatorSession::bytesSent, this,
                [&](const QByteArray &bytes) { sent << QString::fromLatin1(bytes).trimmed(); });
        QSignalSpy stopSent(&station, &Station::exitStopSent);
        QSignalSpy down(&station, &Station::shutDown);
        station.shutdown(QStringLiteral("test"));
        QVERIFY(!server->isListening()); // no tracker moves it again meanwhile
        QCOMPARE(stopSent.count(), 1);
        QCOMPARE(stopSent.first().at(0).toInt(), 0);
        QVERIFY(down.isEmpty() || sent.join(u' ').contains(QStringLiteral("SA")));
        QVERIFY(runEventLoopUntil([&] { return !down.isEmpty(); }, 5000));
        QVERIFY2(sent.join(u' ').contains(QStringLiteral("SA")), qPrintable(sent.join(u'|')));
        station.shutdown(QStringLiteral("again")); // said twice: nothing more
        QCOMPARE(stopSent.count(), 1);
    }

    // The Station's rules for a schedule, whichever face asks: its numbers
    // within the ranges every face takes, its end only its own (one target
    // tracked on its own is untrack's); and the radio's hold kept with no
    // radio set, refused only by a station with no radio part at all.
    void aSchedulesRulesAndTheRadiosHold()
    {
        Station station(onTheSimulator(QStringLiteral("sim:?model=satnogs&clock=manual")));
        SimulatorPump pump;
        QVERIFY(connectAndWait(station, pump));
        station.setPlace(kPlace);
        const auto fixed = slew::tracking::TrackTarget::parseFixedOrCelestial(QStringLiteral("azel:200,40"), nullptr);
        slew::station::ScheduleOptions options;
        options.hours = 0;
        QCOMPARE(station.runSchedule({*fixed}, options).reason(), QStringLiteral("a schedule's hours: 0 hours is outside 0.1..168 hours"));
        options = {};
        options.minElevationDeg = std::nan("");
        QVERIFY(station.runSchedule({*fixed}, options).reason().startsWith(QStringLiteral("a schedule's minimum elevation: ")));
        options = {};
        options.guardSeconds = -1;
        QVERIFY(station.runSchedule({*fixed}, options).reason().startsWith(QStringLiteral("a schedule's guard time: ")));
        QVERIFY(!station.scheduleRunner()->isRunning());

        QCOMPARE(station.stopSchedule(QStringLiteral("test")).reason(), QStringLiteral("no schedule is running"));
        QVERIFY(station.track(*fixed, 0).isDone());
        QCOMPARE(station.stopSchedule(QStringLiteral("test")).reason(), QStringLiteral("no schedule is running"));
        QVERIFY(station.passRunner()->isRunning());
        QVERIFY(station.runSchedule({*fixed}, slew::station::ScheduleOptions{}).isDone());
        QVERIFY(station.stopSchedule(QStringLiteral("test")).isDone());
        QVERIFY(!station.scheduleRunner()->isRunning());

        QVERIFY(station.radio()->linkUri().isEmpty());
        QVERIFY(station.holdRadio(true).isDone());
        QVERIFY(station.radio()->isControlHeld());
        QVERIFY(station.holdRadio(false).isDone());
        QVERIFY(!station.radio()->isControlHeld());

        StationOptions bad;
        bad.rotors = {1, 2};
        bad.sharedLineUri = QStringLiteral("nosuchscheme://x");
        Station none(bad);
        QCOMPARE(none.holdRadio(true).reason(), none.error());
    }

    // The radio as every face sees it: its link in the rotator's words (or
    // none), where it was read to be, and the operator's hold.
    void theRadioIsInTheFacesState()
    {
        Station station(onTheSimulator(QStringLiteral("sim:?model=satnogs&clock=manual")));
        slew::face::StationFace *face = station.face();
        const auto state = [face] { return face->state().value_or(slew::face::StationState{}); };
        QCOMPARE(state().radioLink, QStringLiteral("none"));
        QVERIFY(!state().radioReceiveHz);
        DopplerRadio *radio = station.radio();
        QSignalSpy said(face, &slew::face::StationFace::stateChanged);
        QString error;
        QVERIFY2(radio->setLink(QStringLiteral("sim:"), &error), qPrintable(error)); // Hamlib's dummy rig
        QCOMPARE(state().radioLink, QStringLiteral("disconnected"));
        QVERIFY(runEventLoopUntil([&] { return !said.isEmpty(); }, 5000)); // a new radio is news
        radio->connectRadio();
        QVERIFY(runEventLoopUntil([&] { return state().radioLink == u"connected"; }, 10000));
        // Where the radio was found, read as it opened.
        QVERIFY(runEventLoopUntil([&] { return state().radioReceiveHz.has_value(); }, 10000));
        QCOMPARE(state().radioReceiveHz, radio->frequencies().receiveHz);
        QVERIFY(*state().radioReceiveHz > 0);
        QVERIFY(!state().radioSteering);
        QVERIFY(station.holdRadio(true).isDone());
        QVERIFY(state().radioHeld);
        // Another radio (here none) starts with nothing known of it.
        QVERIFY(radio->setLink(QString(), &error));
        QCOMPARE(state().radioLink, QStringLiteral("none"));
        QVERIFY(!state().radioReceiveHz && !state().radioTransmitHz);
        QVERIFY(state().radioHeld); // the hold is the station's, kept for the next radio
    }

    void aBadSharedLineMakesNoRotors()
    {
        StationOptions options;
        options.rotors = {1, 2};
        options.sharedLineUri = QStringLiteral("nosuchscheme://x");
        Station station(options);
        QVERIFY(!station.isValid());
        QVERIFY(!station.error().isEmpty());
        QCOMPARE(station.rotorCount(), 0);
        QSignalSpy down(&station, &Station::shutDown);
        station.shutdown(QStringLiteral("test"));
        QCOMPARE(down.count(), 1);
    }
};

QTEST_GUILESS_MAIN(StationTest)
#include "tst_station.moc"
