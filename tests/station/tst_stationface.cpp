// SPDX-License-Identifier: GPL-3.0-or-later
// One script of an operator's intents through the station's face
// (face/stationface.h), once as the window's face of a station in this
// process and once as a remote window's face of the same kind of station
// on a real Mosquitto (TLS, accounts, its access list): the same outcomes,
// refusals in the same words, and the same state seen after each step:
// go-to, track, a schedule run and ended, a schedule previewed, the radio
// held and handed back, stop, park. Both stations run the built-in simulator on its manual clock.

#include "../common/mosquittobroker.h"
#include "../common/settledoutcome.h"
#include "../common/simulatorpump.h"
#include "linkschemes.h"

#include "face/stationface.h"
#include "remote/brokeraddress.h"
#include "remote/remotestation.h"
#include "session/rotatorsession.h"
#include "sky/elementsetsources.h"
#include "station/localstationface.h"
#include "station/remoteoperation.h"
#include "station/station.h"

#include <QStandardPaths>
#include <QUrl>
#include <QTest>

#include <cmath>
#include <memory>

using slew::face::Outcome;
using slew::face::StationFace;
using slew::station::Station;

namespace {

// The station's element-set cache holds the test's satellites: what a
// name or a catalogue number finds, as on a station that has fetched them.
bool loadTestElements(Station &station)
{
    slew::sky::ElementSetSources *sets = station.elementSets();
    sets->setUrls({QUrl::fromLocalFile(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"))});
    bool loaded = false;
    QObject::connect(sets, &slew::sky::ElementSetSources::loaded, sets, [&loaded] { loaded = true; },
                     Qt::SingleShotConnection);
    sets->loadFromCache(true);
    return runEventLoopUntil([&] { return loaded; }, 20000) && !sets->sets().isEmpty();
}

Station *newSimulatedStation(QObject *parent)
{
    slew::station::StationOptions options;
    slew::model::RotatorProfile profile;
    profile.uri = QStringLiteral("sim:?model=satnogs&clock=manual&start_az=10&start_el=10");
    options.profile = profile;
    auto *station = new Station(options, parent);
    station->setPlace(slew::sky::Site{55.7, 12.6, 10, {}, {}});
    return station;
}

bool near(const std::optional<QPointF> &p, double az, double el)
{
    return p && std::abs(p->x() - az) < 0.5 && std::abs(p->y() - el) < 0.5;
}

// What a face saw, step by step: each intent's outcome, and the state
// the step waits for.
struct Transcript {
    QStringList lines;
    void add(const QString &step, const Outcome &o)
    {
        lines << QStringLiteral("%1: %2").arg(step, o.isDone() ? QStringLiteral("done") : QStringLiteral("refused: ") + o.reason());
    }
};

// The script, through any face. False (with the transcript so far) when
// a state it waits for does not come.
bool runScript(StationFace &face, Transcript &t)
{
    const auto state = [&face] { return face.state().value_or(slew::face::StationState{}); };
    if (!runEventLoopUntil([&] { return state().link == u"connected" && state().position; }, 20000)) {
        t.lines << QStringLiteral("never connected");
        return false;
    }
    const QString gate = face.previewPointing(999, 30).refusal;
    t.lines << QStringLiteral("preview 999,30: ") + gate;
    t.add(QStringLiteral("go to 999,30"), settledOutcome(face, face.gotoPosition(999, 30)));
    t.add(QStringLiteral("go to 40,20"), settledOutcome(face, face.gotoPosition(40, 20)));
    if (!runEventLoopUntil([&] { return near(state().position, 40, 20); }, 30000)) {
        t.lines << QStringLiteral("never arrived at 40,20");
        return false;
    }
    t.lines << QStringLiteral("target %1,%2").arg(state().target.value_or(QPointF()).x()).arg(state().target.value_or(QPointF()).y());
    t.add(QStringLiteral("track a satellite no one has"), settledOutcome(face, face.track(QStringLiteral("NO SUCH SATELLITE"), 0)));
    t.add(QStringLiteral("track azel:200,40"), settledOutcome(face, face.track(QStringLiteral("azel:200,40"), 0)));
    if (!runEventLoopUntil([&] { return state().tracking == u"tracking" && near(state().position, 200, 40); }, 30000)) {
        t.lines << QStringLiteral("never tracked: ") + state().tracking;
        return false;
    }
    t.lines << QStringLiteral("tracking %1").arg(state().trackingTarget);
    t.add(QStringLiteral("untrack"), settledOutcome(face, face.untrack()));
    if (!runEventLoopUntil([&] { return state().tracking == u"off"; }, 15000)) {
        t.lines << QStringLiteral("never stopped tracking: ") + state().tracking;
        return false;
    }
    t.add(QStringLiteral("untrack again"), settledOutcome(face, face.untrack()));

    // A schedule edited: two satellites of the element-set cache, one by
    // its name and one by its catalogue number, with the operator's
    // numbers; seen as the face says the schedule changed; ended.
    std::optional<slew::face::StationSchedule> said;
    const auto follow = QObject::connect(&face, &StationFace::scheduleChanged, &face,
                                         [&said](const slew::face::StationSchedule &s) { said = s; });
    t.add(QStringLiteral("schedule FLOCK 2P-1, NO SUCH SATELLITE"),
          settledOutcome(face, face.runSchedule({QStringLiteral("FLOCK 2P-1"), QStringLiteral("NO SUCH SATELLITE")}, {})));
    t.add(QStringLiteral("schedule FLOCK 2P-1, 40039"),
          settledOutcome(face, face.runSchedule({QStringLiteral("FLOCK 2P-1"), QStringLiteral("40039")}, {12, 5, 60})));
    if (!runEventLoopUntil([&] { return said && said->running && said->planned; }, 20000)) {
        t.lines << QStringLiteral("the schedule was never said to be planned");
        return false;
    }
    const slew::schedule::ScheduleSettings &plan = face.schedule().value_or(*said).schedule.settings;
    t.lines << QStringLiteral("schedule of %1: %2 h, above %3°, %4 s apart")
                   .arg(said->schedule.targets.join(QStringLiteral(", ")))
                   .arg(plan.hours, 0, 'f', 1)
                   .arg(plan.minElevationDeg, 0, 'f', 1)
                   .arg(plan.guardSeconds, 0, 'f', 0);
    t.add(QStringLiteral("unschedule"), settledOutcome(face, face.stopSchedule()));
    if (!runEventLoopUntil([&] { return said && !said->running && face.schedule() && !face.schedule()->running; }, 15000)) {
        t.lines << QStringLiteral("the schedule was never said to end");
        return false;
    }
    QObject::disconnect(follow);
    t.add(QStringLiteral("unschedule again"), settledOutcome(face, face.stopSchedule()));

    // A schedule previewed, nothing run: each name as the station found it
    // (the AMSAT name, one it has not, the sun), and a plan of those found.
    std::optional<slew::face::SchedulePreview> preview;
    const auto previewed = QObject::connect(&face, &StationFace::schedulePreviewed, &face,
                                            [&preview](const QString &, const slew::face::SchedulePreview &p) { preview = p; });
    const Outcome asked = face.previewSchedule({QStringLiteral("ao-91"), QStringLiteral("NO SUCH SATELLITE"), QStringLiteral("sun")},
                                               {12, 0, 30});
    t.lines << QStringLiteral("preview asked: %1").arg(asked.isAwaiting() ? u"awaiting" : u"not awaiting");
    t.add(QStringLiteral("preview"), settledOutcome(face, asked, 30000));
    QObject::disconnect(previewed);
    if (!preview) {
        t.lines << QStringLiteral("no preview came");
        return false;
    }
    for (const slew::face::NamedTarget &n : preview->targets)
        t.lines << QStringLiteral("  %1 -> %2").arg(n.asked, n.isFound() ? QStringLiteral("%1 (%2)").arg(n.name).arg(n.norad) : n.problem);
    t.lines << QStringLiteral("  planned %1 over %2 h, %3")
                   .arg(preview->schedule.targets.join(QStringLiteral(", ")))
                   .arg(preview->schedule.settings.hours, 0, 'f', 1)
                   .arg(preview->schedule.passes.isEmpty() ? u"no pass" : u"passes");
    t.lines << QStringLiteral("  still not running: %1").arg(face.schedule() && !face.schedule()->running ? u"yes" : u"no");

    // The radio's dial taken and handed back to Doppler steering, the
    // state's hold following. (These stations have no radio set: the hold
    // is kept for one set later.)
    t.lines << QStringLiteral("radio %1, %2").arg(state().radioLink, state().radioHeld ? u"held" : u"not held");
    t.add(QStringLiteral("hold the radio"), settledOutcome(face, face.holdRadio(true)));
    if (!runEventLoopUntil([&] { return state().radioHeld; }, 15000)) {
        t.lines << QStringLiteral("the radio was never said to be held");
        return false;
    }
    t.lines << QStringLiteral("radio %1, held").arg(state().radioLink);
    t.add(QStringLiteral("hand the radio back"), settledOutcome(face, face.holdRadio(false)));
    if (!runEventLoopUntil([&] { return !state().radioHeld; }, 15000)) {
        t.lines << QStringLiteral("the radio was never said to be handed back");
        return false;
    }
    t.add(QStringLiteral("go to 100,30"), settledOutcome(face, face.gotoPosition(100, 30)));
    if (!runEventLoopUntil([&] { return near(state().position, 100, 30); }, 30000)) {
        t.lines << QStringLiteral("never arrived at 100,30");
        return false;
    }
    // (The simulator is paced far faster than real time here: that a Stop
    // stops a move short is the remote window's test, on the wall clock.)
    t.add(QStringLiteral("stop"), settledOutcome(face, face.stop(QStringLiteral("the script"))));
    if (!runEventLoopUntil([&] { return !state().moving; }, 15000)) {
        t.lines << QStringLiteral("never came to rest");
        return false;
    }
    t.add(QStringLiteral("park"), settledOutcome(face, face.park()));
    return true;
}

} // namespace

class StationFaceTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        slew::registerLinkSchemes();
        QString error;
        QVERIFY2(m_broker.start(&error), qPrintable(error)); // mosquitto is in the package list
    }

    void oneScriptThroughBothFaces()
    {
        QObject owner;
        SimulatorPump pump;

        // The station in this process, through the window's face.
        Station *here = newSimulatedStation(&owner);
        QVERIFY(loadTestElements(*here));
        pump.follow(here->session());
        here->connectRotators();
        slew::station::LocalStationFace local(here);
        QVERIFY(local.isLocal());
        Transcript localSaw;
        const bool localRan = runScript(local, localSaw);
        QVERIFY2(localRan, qPrintable(localSaw.lines.join(u'\n')));

        // The same kind of station on the broker, through a remote window's face.
        Station *there = newSimulatedStation(&owner);
        QVERIFY(loadTestElements(*there));
        pump.follow(there->session());
        there->connectRotators();
        QString error;
        const auto stationAddress = slew::remote::parseBrokerAddress(m_broker.url(QStringLiteral("station-mast")), &error);
        QVERIFY2(stationAddress, qPrintable(error));
        slew::station::RemoteOptions options;
        options.broker = *stationAddress;
        options.password = MosquittoBroker::password(QStringLiteral("station-mast"));
        options.stationName = QStringLiteral("mast");
        QVERIFY2(there->startRemote(options, &error), qPrintable(error));
        const auto operatorAddress = slew::remote::parseBrokerAddress(m_broker.url(QStringLiteral("operator"), QStringLiteral("mast")), &error);
        QVERIFY2(operatorAddress, qPrintable(error));
        slew::remote::MqttSettings settings;
        settings.broker = *operatorAddress;
        settings.password = MosquittoBroker::password(QStringLiteral("operator"));
        slew::remote::RemoteStation remote(settings, QStringLiteral("mast"));
        QVERIFY2(remote.open(&error), qPrintable(error));
        QVERIFY(!remote.isLocal());
        TRY_VERIFY_WITH_TIMEOUT(remote.isLive(), 20000);
        Transcript remoteSaw;
        const bool remoteRan = runScript(remote, remoteSaw);
        QVERIFY2(remoteRan, qPrintable(remoteSaw.lines.join(u'\n')));

        QCOMPARE(remoteSaw.lines, localSaw.lines);
        // The script saw refusals, not only successes: the gate's, the
        // name's, an untrack with nothing tracked, the schedule's name and
        // an unschedule with no schedule.
        QCOMPARE(localSaw.lines.filter(QStringLiteral("refused: ")).size(), 5);
        QVERIFY2(localSaw.lines.at(1).endsWith(localSaw.lines.at(0).section(QStringLiteral(": "), 1)),
                 qPrintable(localSaw.lines.join(u'\n')));
    }

    void aRemoteIntentWithNoBrokerIsRefusedAtOnce()
    {
        slew::remote::MqttSettings settings;
        QString error;
        settings.broker = *slew::remote::parseBrokerAddress(m_broker.url(QStringLiteral("operator"), QStringLiteral("mast")), &error);
        slew::remote::RemoteStation remote(settings, QStringLiteral("mast"));
        const Outcome sent = remote.gotoPosition(40, 20); // never opened
        QVERIFY(sent.isRefused());
        QCOMPARE(sent.reason(), QStringLiteral("not connected to the broker"));
    }

private:
    MosquittoBroker m_broker;
};

QTEST_GUILESS_MAIN(StationFaceTest)
#include "tst_stationface.moc"
