// SPDX-License-Identifier: GPL-3.0-or-later
// One window class for every station: the same script of an operator's
// steps through the station window of a station in this process and
// through the station window of the same kind of station on a real
// Mosquitto (TLS, accounts). The steps go through the window's own widgets
// (the go-to panel, the presets, Stop, the Schedule page, the radio's
// hold, Park) and, for tracking by one target, which each door still shows
// its own way, through the window's face. What each step
// shows (messages, the readout, the tracking line) must read the same.

#include "../common/mosquittobroker.h"
#include "../common/settledoutcome.h"
#include "windowfixture.h"

#include "rotor/gotopanel.h"
#include "rotor/parkhomepanel.h"
#include "rotor/positionreadout.h"
#include "rotor/presetpanel.h"
#include "stationwindow.h"
#include "stopbutton.h"
#include "tracking/schedulepanel.h"
#include "tracking/trackingline.h"

#include "face/stationface.h"
#include "remote/brokeraddress.h"
#include "remote/remotestation.h"
#include "session/rotatorsession.h"
#include "station/remoteoperation.h"
#include "station/station.h"

#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>

#include <cmath>

using slew::face::Outcome;
using slew::face::StationFace;
using slew::ui::StationWindow;

namespace {

// Azimuths a turn apart are one bearing: a park at 0° may be reached at 360°.
bool near(const std::optional<QPointF> &p, double az, double el)
{
    if (!p)
        return false;
    const double turn = std::fmod(std::abs(p->x() - az), 360.0);
    return std::min(turn, 360.0 - turn) < 0.5 && std::abs(p->y() - el) < 0.5;
}

QString said(const Outcome &o)
{
    return o.isDone() ? QStringLiteral("done") : QStringLiteral("refused: ") + o.reason();
}

QString label(StationWindow &w, const char *name)
{
    const auto *l = w.findChild<QLabel *>(QString::fromLatin1(name));
    return l ? l->text() : QStringLiteral("(no %1)").arg(QString::fromLatin1(name));
}

// The script, through a window. What it saw, line by line; a line that
// says "never" when a state it waits for did not come.
QStringList runScript(StationWindow &w)
{
    QStringList t;
    StationFace &face = *w.face();
    const auto state = [&face] { return face.state().value_or(slew::face::StationState{}); };
    const auto waitFor = [&](const char *what, const std::function<bool()> &pred) {
        if (!runEventLoopUntil(pred, 30000))
            t << QStringLiteral("never %1").arg(QString::fromLatin1(what));
        return !t.last().startsWith(u"never");
    };
    t << QStringLiteral("start");
    if (!waitFor("connected", [&] { return face.isLive() && state().link == u"connected" && state().position; }))
        return t;

    // Out of the travel: the Go button stays off and the gate says why.
    w.gotoPanel()->setFields(999, 30);
    t << QStringLiteral("go offered at 999,30: %1").arg(w.gotoPanel()->findChild<QPushButton *>(QStringLiteral("gotoButton"))->isEnabled());
    t << QStringLiteral("go at 999,30 sent: %1").arg(w.gotoPanel()->go());
    t << QStringLiteral("go-to says: ") + label(w, "gotoMessage");

    w.gotoPanel()->setFields(40, 20);
    t << QStringLiteral("go at 40,20 sent: %1").arg(w.gotoPanel()->go());
    if (!waitFor("at 40,20", [&] { return near(state().position, 40, 20) && !state().moving; }))
        return t;
    // The readout shows where the station says the antenna is (the last
    // figures of a reading taken a moment apart may differ in the tenth).
    const bool readoutFollows = runEventLoopUntil(
        [&] {
            const QPointF p = state().position.value_or(QPointF());
            return label(w, "readoutAzimuth").trimmed() == QStringLiteral("%1°").arg(slew::ui::shownTenths(p.x()), 0, 'f', 1)
                   && label(w, "readoutElevation").trimmed() == QStringLiteral("%1°").arg(slew::ui::shownTenths(p.y()), 0, 'f', 1);
        },
        10000);
    t << QStringLiteral("readout shows the position: %1").arg(readoutFollows);
    t << QStringLiteral("store 'Mast': %1, %2").arg(w.presetPanel()->storeCurrent(QStringLiteral("Mast"))).arg(label(w, "presetMessage"));

    w.gotoPanel()->setFields(100, 30);
    t << QStringLiteral("go at 100,30 sent: %1").arg(w.gotoPanel()->go());
    if (!waitFor("at 100,30", [&] { return near(state().position, 100, 30) && !state().moving; }))
        return t;
    w.stopButton()->click();
    if (!waitFor("at rest after Stop", [&] { return !state().moving; }))
        return t;
    t << QStringLiteral("stopped");

    t << QStringLiteral("recall 'Mast': %1, %2").arg(w.presetPanel()->recall(0)).arg(label(w, "presetMessage"));
    if (!waitFor("back at 'Mast'", [&] { return near(state().position, 40, 20) && !state().moving; }))
        return t;

    t << QStringLiteral("track an unknown name: ") + said(settledOutcome(face, face.track(QStringLiteral("NO SUCH SATELLITE"), 0)));
    t << QStringLiteral("track azel:200,40: ") + said(settledOutcome(face, face.track(QStringLiteral("azel:200,40"), 0)));
    if (!waitFor("tracking", [&] { return w.trackingLine()->text().startsWith(u"Tracking"); }))
        return t;
    // Up to the times, which are the clock's.
    t << QStringLiteral("tracking line: ") + w.trackingLine()->text().section(QStringLiteral(" until "), 0, 0);
    t << QStringLiteral("untrack: ") + said(settledOutcome(face, face.untrack()));
    if (!waitFor("tracking ended", [&] { return w.trackingLine()->text() == u"Not tracking"; }))
        return t;

    // The Schedule page, through its own widgets: targets added by name
    // (one the station cannot find, refused in its words), the station's
    // preview, Run and Stop.
    slew::ui::SchedulePanel *schedule = w.schedulePanel();
    auto *add = schedule->findChild<QLineEdit *>(QStringLiteral("scheduleAdd"));
    for (const char *name : {"Sun", "NO SUCH SATELLITE", "moon"}) {
        QSignalSpy added(schedule, &slew::ui::SchedulePanel::targetAdded);
        QSignalSpy refused(schedule, &slew::ui::SchedulePanel::targetRefused);
        add->setText(QString::fromLatin1(name));
        schedule->findChild<QPushButton *>(QStringLiteral("scheduleAddButton"))->click();
        if (!waitFor("the station's word on a target", [&] { return !added.isEmpty() || !refused.isEmpty(); }))
            return t;
        t << QStringLiteral("add %1: %2").arg(QString::fromLatin1(name),
                                              added.isEmpty() ? refused.first().first().toString()
                                                              : QStringLiteral("listed as ") + added.first().first().toString());
    }
    if (!waitFor("a preview", [&] { return schedule->isPreviewing(); }))
        return t;
    t << QStringLiteral("schedule: %1, targets %2")
             .arg(schedule->stateText().section(u':', 0, 0), schedule->targetSpecs().join(QStringLiteral(", ")));
    auto *run = schedule->findChild<QPushButton *>(QStringLiteral("scheduleRun"));
    run->click();
    if (!waitFor("the schedule running", [&] {
            return face.schedule() && face.schedule()->running && face.schedule()->planned
                   && schedule->stateText().startsWith(u"Running: ") && run->text() == u"Stop schedule";
        }))
        return t;
    t << QStringLiteral("schedule: running %1").arg(face.schedule()->schedule.targets.join(QStringLiteral(", ")));
    run->click();
    if (!waitFor("the schedule ended", [&] {
            return face.schedule() && !face.schedule()->running && run->text() == u"Run schedule" && schedule->isPreviewing();
        }))
        return t;
    t << QStringLiteral("schedule: %1").arg(schedule->stateText().section(u':', 0, 0));

    // The radio's dial taken and handed back, by the button every station
    // window has, the line following. (No radio is set: the hold is kept.)
    auto *hold = w.findChild<QPushButton *>(QStringLiteral("radioHold"));
    t << QStringLiteral("radio: %1; %2").arg(label(w, "radioState"), hold->text());
    hold->click();
    if (!waitFor("the radio held", [&] { return state().radioHeld && hold->text() == u"Resume radio control"; }))
        return t;
    t << QStringLiteral("radio: %1").arg(label(w, "radioState"));
    hold->click();
    if (!waitFor("the radio handed back", [&] { return !state().radioHeld && hold->text() == u"Stop radio control"; }))
        return t;
    t << QStringLiteral("radio: %1").arg(label(w, "radioState"));

    t << QStringLiteral("park sent: %1, %2").arg(w.parkHomePanel()->park()).arg(label(w, "homeMessage"));
    if (!waitFor("parked", [&] { return state().park && near(state().position, state().park->x(), state().park->y()) && !state().moving; })) {
        const QPointF p = state().position.value_or(QPointF());
        fprintf(stderr, "ALARMS %s\n", qPrintable(state().alarms.join(QStringLiteral("; "))));
        t.last() += QStringLiteral(" (%1; at %2,%3, moving %4; alarms: %5)")
                        .arg(label(w, "homeMessage"))
                        .arg(p.x())
                        .arg(p.y())
                        .arg(state().moving)
                        .arg(state().alarms.join(QStringLiteral("; ")));
        return t;
    }
    t << QStringLiteral("end");
    return t;
}

} // namespace

class StationWindowTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        WindowFixture::prepareApplication();
        QString error;
        QVERIFY2(m_broker.start(&error), qPrintable(error)); // mosquitto is in the package list
    }

    void oneScriptThroughBothWindows()
    {
        // The station in this process, in its window.
        WindowFixture here(QString::fromLatin1(WindowFixture::fastSimOnItsClock));

        // The same kind of station on the broker, in the same window class.
        slew::station::StationOptions options;
        slew::model::RotatorProfile profile;
        profile.uri = QString::fromLatin1(WindowFixture::fastSimOnItsClock);
        options.profile = profile;
        slew::station::Station there(options);
        SimulatorPump pump; // one pump a simulator
        pump.follow(there.session());
        there.connectRotators();
        QString error;
        const auto stationAddress = slew::remote::parseBrokerAddress(m_broker.url(QStringLiteral("station-mast")), &error);
        QVERIFY2(stationAddress, qPrintable(error));
        slew::station::RemoteOptions remoteOptions;
        remoteOptions.broker = *stationAddress;
        remoteOptions.password = MosquittoBroker::password(QStringLiteral("station-mast"));
        remoteOptions.stationName = QStringLiteral("mast");
        QVERIFY2(there.startRemote(remoteOptions, &error), qPrintable(error));
        const auto operatorAddress =
            slew::remote::parseBrokerAddress(m_broker.url(QStringLiteral("operator"), QStringLiteral("mast")), &error);
        QVERIFY2(operatorAddress, qPrintable(error));
        slew::remote::MqttSettings settings;
        settings.broker = *operatorAddress;
        settings.password = MosquittoBroker::password(QStringLiteral("operator"));
        auto *remote = new slew::remote::RemoteStation(settings, QStringLiteral("mast"));
        QVERIFY2(remote->open(&error), qPrintable(error));
        // Both windows made before either stores a preset: each starts
        // with the presets the settings held then.
        StationWindow away(remote);
        remote->setParent(&away);
        QVERIFY(here.window->face()->isLocal());
        QVERIFY(!away.face()->isLocal());
        QCOMPARE(away.remoteStation(), remote);
        QVERIFY(!away.station() && !away.connectionBar() && !away.configEditor()); // the local door is shut

        const slew::sky::Site site{55.7, 12.6, 10, {}, {}};
        here.station.setPlace(site);
        there.setPlace(site);
        QVERIFY(here.connectAndWait());
        const QStringList local = runScript(*here.window);
        QVERIFY2(local.last() == u"end", qPrintable(local.join(u'\n')));
        const QStringList remoteSaw = runScript(away);
        QVERIFY2(remoteSaw.last() == u"end", qPrintable(remoteSaw.join(u'\n')));
        for (qsizetype i = 0; i < std::max(local.size(), remoteSaw.size()); ++i) {
            const QString a = local.value(i), b = remoteSaw.value(i);
            QVERIFY2(a == b, qPrintable(QStringLiteral("step %1\nhere:      %2\nfrom afar: %3").arg(i).arg(a, b)));
        }
        // The script saw refusals as well as moves: the gate's, the track's
        // and the schedule's, each in the station's words.
        QVERIFY2(local.filter(QStringLiteral("refused: ")).size() == 1 && local.contains(QStringLiteral("go at 999,30 sent: 0"))
                     && local.contains(QStringLiteral("add NO SUCH SATELLITE: no satellite 'NO SUCH SATELLITE' among the "
                                                      "station's element sets")),
                 qPrintable(local.join(u'\n')));
    }

private:
    MosquittoBroker m_broker;
};

QTEST_MAIN(StationWindowTest)
#include "tst_stationwindow.moc"
