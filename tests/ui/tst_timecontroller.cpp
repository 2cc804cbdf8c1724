// SPDX-License-Identifier: GPL-3.0-or-later
// Sky → Time controller…: rehearsing in the window. The station clock
// started at a chosen UTC time puts the Tracking tab's passes after that
// time; it runs at the rate chosen, the built-in simulator with it; a change
// while tracking plans again; and while the clock is not real time the
// window says so, in the status bar and the title, until it is again.
// The start is taken as typed; a pause holds the clock (and a tracker's
// pass goes on from where it was), a step moves it on, the slider moves it
// along the next hours, and a chosen pass is rehearsed from two minutes
// before its AOS.
//
// The rates are measured against wall readings taken around each clock
// reading, so the checks hold however busy the machine is.

#include "windowfixture.h"

#include "rotor/connectionbar.h"
#include "sim/simulator.h"
#include "sim/simulatorscheme.h"
#include "sky/skyvector.h"
#include "sky/elementsetsources.h"
#include "sky/utctime.h"
#include "tracking/timecontroller.h"
#include "widgets/utctimefield.h"
#include "tracking/trackingpanel.h"

#include <QAction>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>
#include <QSlider>
#include <QTimer>

#include <cmath>

using slew::ui::TimeController;
using slew::ui::TrackingPanel;

namespace {

const QString kAllSets = QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle");

void atJo65hq(TrackingPanel *panel)
{
    slew::sky::Site station;
    QString error;
    QVERIFY(slew::sky::parseSite(QStringLiteral("JO65hq"), &station, &error));
    panel->station()->setPlace(station);
}

// The pass table is planned off the window's thread: wait for it.
bool passesPlanned(const TrackingPanel *panel)
{
    return WindowFixture::waitFor([panel] { return !panel->isPlanning(); }, 10000);
}

// Sky → Time controller…, as the operator opens it.
TimeController *openTimeController(WindowFixture &f)
{
    auto *action = f.find<QAction>(QStringLiteral("actionTimeController"));
    if (!action)
        return nullptr;
    action->trigger();
    return f.window->timeController();
}

// Types `text` over what the start field holds, as an operator does.
void typeStart(TimeController *time, const QString &text)
{
    QWidget *field = time->startField();
    QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(field, text);
}

// Start here, with this time and rate typed in the fields.
void startRehearsal(TimeController *time, const QString &iso, int rate)
{
    typeStart(time, iso);
    time->rateField()->setValue(rate);
    QTest::mouseClick(time->startButton(), Qt::LeftButton);
}

double secondsBetween(double laterJulian, double earlierJulian)
{
    return (laterJulian - earlierJulian) * slew::sky::kSecondsPerDay;
}

double julian(const QString &iso)
{
    return *slew::sky::julianFromIso(iso);
}

// A wall clock runs on wall time: let some pass on the event loop.
bool letWallTimePass(int ms)
{
    QTimer timer;
    timer.setSingleShot(true);
    QSignalSpy done(&timer, &QTimer::timeout);
    timer.start(ms);
    return done.wait(ms + 10000);
}

// Whether `clock` runs `rate` times faster than the wall: station time over
// a stretch lies between rate times the wall time inside the two readings
// and rate times the wall time around them.
bool runsAt(const slew::tracking::StationClock *clock, double rate, QString *seen)
{
    QElapsedTimer wall;
    wall.start();
    const auto wallNow = [&] { return double(wall.nsecsElapsed()) / 1e9; };
    const double w0 = wallNow();
    const double first = clock->nowJulian();
    const double w1 = wallNow();
    if (!letWallTimePass(200))
        return false;
    const double w2 = wallNow();
    const double second = clock->nowJulian();
    const double w3 = wallNow();
    const double station = (second - first) * slew::sky::kSecondsPerDay;
    *seen = QStringLiteral("%1 station s in %2..%3 wall s").arg(station).arg(w2 - w1).arg(w3 - w0);
    const double slack = 0.001; // a Julian date in a double resolves ~40 µs
    return station >= rate * (w2 - w1) - slack && station <= rate * (w3 - w0) + slack;
}

double simulatorTimeScale(WindowFixture &f)
{
    slew::sim::Simulator *sim = slew::sim::simulatorBehind(f.session.link());
    return sim ? sim->clock().timeScale() : -1.0;
}

} // namespace

class TimeControllerTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }

    void aRehearsalPlansThePassesAfterTheChosenTime()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.loadElementSets(kAllSets));
        TrackingPanel *panel = f.window->trackingPanel();
        atJo65hq(panel);
        QVERIFY(panel->selectTarget(QStringLiteral("FLOCK 2P-1")));
        QVERIFY(passesPlanned(panel));

        TimeController *time = openTimeController(f);
        QVERIFY(time);
        QVERIFY(time->isVisible());
        QVERIFY(!time->isModal()); // the window goes on working beside it
        startRehearsal(time, QStringLiteral("2018-01-22T07:42:45Z"), 1);
        QVERIFY(passesPlanned(panel));
        // The pass eleven seconds after the chosen time, as `slew --passes` gives it.
        QTableWidget *table = panel->passTable();
        QVERIFY(table->rowCount() > 0);
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("01-22 07:42:56"));
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("7.1°"));
        QVERIFY2(panel->countdown()->text().startsWith(QStringLiteral("AOS in 0:00:1")),
                 qPrintable(panel->countdown()->text()));

        // Started again at noon: the table starts there, and spans the day after.
        const double noon = *slew::sky::julianFromIso(QStringLiteral("2018-01-22T12:00:00Z"));
        startRehearsal(time, QStringLiteral("2018-01-22T12:00:00Z"), 1);
        QVERIFY(passesPlanned(panel));
        const QList<slew::sky::Pass> passes = panel->passes();
        QVERIFY(!passes.isEmpty());
        QVERIFY(passes.first().los.julian > noon);
        QVERIFY(passes.first().aos.julian > noon - 20.0 / (24 * 60)); // at most one under way
        for (const slew::sky::Pass &p : passes)
            QVERIFY(p.aos.julian < noon + 1.0);
        QVERIFY(table->item(0, 0)->text() != QStringLiteral("01-22 07:42:56"));

        // Real time: none of the rehearsal's passes is listed.
        QTest::mouseClick(time->realTimeButton(), Qt::LeftButton);
        QVERIFY(passesPlanned(panel));
        for (const slew::sky::Pass &p : panel->passes())
            QVERIFY(p.los.julian > slew::sky::julianNow());
    }

    void theWindowSaysRehearsalUntilRealTime()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        auto *marker = f.find<QLabel>(QStringLiteral("rehearsalMarker"));
        QVERIFY(marker);
        QVERIFY(marker->isHidden());
        QVERIFY(!f.window->windowTitle().contains(QStringLiteral("REHEARSAL")));

        TimeController *time = openTimeController(f);
        QVERIFY(time);
        startRehearsal(time, QStringLiteral("2026-11-25T14:03:10Z"), 5);
        QVERIFY(marker->isVisible());
        QVERIFY2(marker->text().startsWith(QStringLiteral("REHEARSAL: station clock 2026-11-25 14:03:1")),
                 qPrintable(marker->text()));
        QVERIFY2(marker->text().endsWith(QStringLiteral(" UTC ×5")), qPrintable(marker->text()));
        QVERIFY2(f.window->windowTitle().startsWith(QStringLiteral("REHEARSAL ×5 — Slew")),
                 qPrintable(f.window->windowTitle()));
        // It keeps time: five station seconds a second.
        const QString first = marker->text();
        TRY_VERIFY(marker->text() != first);

        // The title the window gives itself as the link comes up is marked
        // too, and the mark stays with the Time controller closed.
        QVERIFY(f.connectAndWait());
        QVERIFY2(f.window->windowTitle().startsWith(QStringLiteral("REHEARSAL ×5 — Slew — sim:")),
                 qPrintable(f.window->windowTitle()));
        time->close();
        QVERIFY(!time->isVisible());
        QVERIFY(marker->isVisible());
        // Another rate: the title says it.
        time->showController();
        time->rateField()->setValue(8);
        QVERIFY2(f.window->windowTitle().startsWith(QStringLiteral("REHEARSAL ×8 — Slew — sim:")),
                 qPrintable(f.window->windowTitle()));
        QVERIFY2(marker->text().endsWith(QStringLiteral(" UTC ×8")), qPrintable(marker->text()));

        // Real time: both gone.
        QTest::mouseClick(time->realTimeButton(), Qt::LeftButton);
        QVERIFY(marker->isHidden());
        QCOMPARE(f.window->windowTitle(), QStringLiteral("Slew — %1").arg(f.session.uri()));
    }

    void theStationClockRunsAtTheRateChosen()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        TimeController *time = openTimeController(f);
        QVERIFY(time);
        const slew::tracking::StationClock *clock = time->clock();
        QVERIFY(!clock->isRehearsal());
        startRehearsal(time, QStringLiteral("2026-11-25T12:00:00Z"), 5);
        QVERIFY(clock->isRehearsal());
        QString seen;
        QVERIFY2(runsAt(clock, 5.0, &seen), qPrintable(seen));
        QVERIFY2(!runsAt(clock, 1.0, &seen), qPrintable(seen));

        // A new rate while rehearsing: on at once, from the time the clock reads.
        QElapsedTimer wall;
        wall.start();
        const double before = clock->nowJulian();
        time->rateField()->setValue(10);
        const double after = clock->nowJulian();
        const double moved = (after - before) * slew::sky::kSecondsPerDay;
        QVERIFY2(moved >= -0.001 && moved <= 10.0 * double(wall.nsecsElapsed()) / 1e9 + 0.001,
                 qPrintable(QString::number(moved)));
        QVERIFY2(runsAt(clock, 10.0, &seen), qPrintable(seen));
        QVERIFY2(time->stateLine()->text().contains(QStringLiteral("runs ×10")), qPrintable(time->stateLine()->text()));
    }

    void theSimulatorKeepsPaceWithTheClock()
    {
        WindowFixture f(QStringLiteral("sim:")); // the simulator on the wall clock, as an operator runs it
        QVERIFY(f.connectAndWait());
        QCOMPARE(simulatorTimeScale(f), 1.0);
        TimeController *time = openTimeController(f);
        QVERIFY(time);
        startRehearsal(time, QStringLiteral("2026-11-25T12:00:00Z"), 5);
        QCOMPARE(simulatorTimeScale(f), 5.0);
        QVERIFY2(time->stateLine()->text().contains(QStringLiteral("The simulator runs at the same rate")),
                 qPrintable(time->stateLine()->text()));
        // The same link, at another rate: no reconnect.
        slew::transport::Link *link = f.session.link();
        time->rateField()->setValue(8);
        QCOMPARE(f.session.link(), link);
        QCOMPARE(simulatorTimeScale(f), 8.0);

        // A simulator connected during a rehearsal takes the rate as it connects.
        f.window->connectionBar()->disconnectFromRotator();
        TRY_VERIFY(!f.session.isConnected());
        QVERIFY(f.connectAndWait());
        QVERIFY(f.session.link() != link);
        QCOMPARE(simulatorTimeScale(f), 8.0);

        // Real time: the simulator too.
        QTest::mouseClick(time->realTimeButton(), Qt::LeftButton);
        QCOMPARE(simulatorTimeScale(f), 1.0);
        QVERIFY2(time->stateLine()->text().startsWith(QStringLiteral("Real time")),
                 qPrintable(time->stateLine()->text()));
    }

    void aSimulatorOnItsOwnClockKeepsItsPace()
    {
        // A manual clock (the tests') moves only when stepped: it is not
        // scaled, and the Time controller says the rotator keeps its pace.
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        TimeController *time = openTimeController(f);
        QVERIFY(time);
        startRehearsal(time, QStringLiteral("2026-11-25T12:00:00Z"), 5);
        QCOMPARE(simulatorTimeScale(f), 1.0);
        QVERIFY2(time->stateLine()->text().contains(QStringLiteral("keeps its own pace")),
                 qPrintable(time->stateLine()->text()));
    }

    void aChangeWhileTrackingPlansAgain()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        TrackingPanel *panel = f.window->trackingPanel();
        atJo65hq(panel);
        TimeController *time = openTimeController(f);
        QVERIFY(time);
        startRehearsal(time, QStringLiteral("2026-11-23T18:00:00Z"), 1);
        QVERIFY(panel->selectTarget(QStringLiteral("azel:200,30")));
        QVERIFY(passesPlanned(panel));
        QTest::mouseClick(panel->trackButton(), Qt::LeftButton);
        TRY_VERIFY(panel->runner()->isActive());

        QSignalSpy messages(panel, &TrackingPanel::message);
        startRehearsal(time, QStringLiteral("2026-11-25T06:00:00Z"), 2);
        bool plannedAgain = false;
        for (const QList<QVariant> &m : messages)
            plannedAgain = plannedAgain || m.at(0).toString().contains(QStringLiteral("planning again: the station clock"));
        QVERIFY(plannedAgain);
        QVERIFY(panel->runner()->isRunning());
        TRY_VERIFY(panel->runner()->isActive());
        // The table is of the new day too.
        QVERIFY(passesPlanned(panel));
        QVERIFY(!panel->passes().isEmpty());
        QVERIFY(panel->passes().first().los.julian > *slew::sky::julianFromIso(QStringLiteral("2026-11-25T06:00:00Z")));
        QTest::mouseClick(panel->stopTrackingButton(), Qt::LeftButton);
        QVERIFY(!panel->runner()->isRunning());
    }

    void theStartIsTakenAsTyped()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        TimeController *time = openTimeController(f);
        QVERIFY(time);
        const slew::tracking::StationClock *clock = time->clock();
        // What operators typed, and what a date field made of it (15:59:24).
        startRehearsal(time, QStringLiteral("2026-12-05 15:24:00"), 1);
        QVERIFY(clock->isRehearsal());
        const double fromTyped = secondsBetween(clock->nowJulian(), julian(QStringLiteral("2026-12-05T15:24:00Z")));
        QVERIFY2(fromTyped >= 0.0 && fromTyped < 5.0, qPrintable(QString::number(fromTyped)));
        // The instant as the window shows it, with its zone, and ISO 8601.
        startRehearsal(time, QStringLiteral("2026-12-06 08:00:30 UTC"), 1);
        QVERIFY(secondsBetween(clock->nowJulian(), julian(QStringLiteral("2026-12-06T08:00:30Z"))) < 5.0);
        startRehearsal(time, QStringLiteral("2026-12-07T09:10:11Z"), 1);
        QVERIFY(secondsBetween(clock->nowJulian(), julian(QStringLiteral("2026-12-07T09:10:11Z"))) < 5.0);
        QVERIFY(!time->problemLine()->isVisible());

        // Not a time: said where, and the clock is unchanged.
        const double before = clock->nowJulian();
        startRehearsal(time, QStringLiteral("2026-13-05 15:24"), 1);
        QVERIFY(time->problemLine()->isVisible());
        QCOMPARE(time->problemLine()->text(),
                 QStringLiteral("Start at: \"2026-13-05 15:24\" is not a UTC date and time: type it as "
                                "2026-12-05 15:24:00. The station clock is unchanged."));
        QVERIFY(secondsBetween(clock->nowJulian(), before) < 5.0);
        QVERIFY(clock->nowJulian() >= before);
        // Correcting it clears the message; Enter in the field starts there.
        typeStart(time, QStringLiteral("2026-12-08 10:00:00"));
        QVERIFY(!time->problemLine()->isVisible());
        QTest::keyClick(time->startField(), Qt::Key_Return);
        QVERIFY(secondsBetween(clock->nowJulian(), julian(QStringLiteral("2026-12-08T10:00:00Z"))) < 5.0);
        // Enter in another field presses no button (Start here would jump back).
        QTest::mouseClick(time->pauseButton(), Qt::LeftButton);
        time->stepField()->setValue(60);
        QTest::mouseClick(time->stepButton(), Qt::LeftButton);
        const double stepped = clock->nowJulian();
        QTest::keyClick(time->stepField(), Qt::Key_Return);
        QVERIFY(clock->isPaused());
        QCOMPARE(clock->nowJulian(), stepped);
    }

    void aPauseHoldsTheClockAndAStepMovesItOn()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        TrackingPanel *panel = f.window->trackingPanel();
        atJo65hq(panel);
        TimeController *time = openTimeController(f);
        QVERIFY(time);
        const slew::tracking::StationClock *clock = time->clock();
        QVERIFY(!time->stepButton()->isEnabled()); // only a paused clock steps
        startRehearsal(time, QStringLiteral("2026-11-23T18:00:00Z"), 5);
        QVERIFY(panel->selectTarget(QStringLiteral("azel:200,30")));
        QVERIFY(passesPlanned(panel));
        QTest::mouseClick(panel->trackButton(), Qt::LeftButton);
        TRY_VERIFY(panel->runner()->isActive());

        // Paused: the instant holds, and the tracker goes on with its pass.
        QSignalSpy messages(panel, &TrackingPanel::message);
        QTest::mouseClick(time->pauseButton(), Qt::LeftButton);
        QVERIFY(clock->isPaused());
        QCOMPARE(time->pauseButton()->text(), QStringLiteral("Resume"));
        QVERIFY2(time->stateLine()->text().startsWith(QStringLiteral("Rehearsal, paused: the station clock holds 2026-11-23 18:0")),
                 qPrintable(time->stateLine()->text()));
        const double held = clock->nowJulian();
        QVERIFY(letWallTimePass(300));
        QCOMPARE(clock->nowJulian(), held);
        QVERIFY(panel->runner()->isActive());

        // A step: forward by the amount chosen, still paused.
        QVERIFY(time->stepButton()->isEnabled());
        time->stepField()->setValue(30);
        QTest::mouseClick(time->stepButton(), Qt::LeftButton);
        QVERIFY(std::abs(secondsBetween(clock->nowJulian(), held) - 30.0) < 0.001);
        QVERIFY(clock->isPaused());

        // Resumed: on from there at the rate it had.
        QTest::mouseClick(time->pauseButton(), Qt::LeftButton);
        QVERIFY(!clock->isPaused());
        QCOMPARE(time->pauseButton()->text(), QStringLiteral("Pause"));
        QVERIFY(!time->stepButton()->isEnabled());
        QString seen;
        QVERIFY2(runsAt(clock, 5.0, &seen), qPrintable(seen));
        QVERIFY(secondsBetween(clock->nowJulian(), held) >= 30.0);
        // None of it made the tracker plan again.
        for (const QList<QVariant> &m : messages)
            QVERIFY2(!m.at(0).toString().contains(QStringLiteral("planning again")), qPrintable(m.at(0).toString()));
        QVERIFY(panel->runner()->isActive());
        QTest::mouseClick(panel->stopTrackingButton(), Qt::LeftButton);
    }

    void pausingRealTimeHoldsNowAsARehearsal()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        TimeController *time = openTimeController(f);
        QVERIFY(time);
        auto *marker = f.find<QLabel>(QStringLiteral("rehearsalMarker"));
        QVERIFY(marker && marker->isHidden());
        QTest::mouseClick(time->pauseButton(), Qt::LeftButton);
        QVERIFY(time->clock()->isPaused());
        QVERIFY(std::abs(secondsBetween(time->clock()->nowJulian(), slew::sky::julianNow())) < 2.0);
        // The window says so at once: the clock is no longer real time.
        QVERIFY(marker->isVisible());
        QVERIFY2(marker->text().endsWith(QStringLiteral(" UTC ×1, paused")), qPrintable(marker->text()));
        QVERIFY(time->realTimeButton()->isEnabled());
        QTest::mouseClick(time->realTimeButton(), Qt::LeftButton);
        QVERIFY(!time->clock()->isPaused());
        QVERIFY(marker->isHidden());
    }

    void theSliderMovesTheClockAlongTheNextHours()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        TimeController *time = openTimeController(f);
        QVERIFY(time);
        const slew::tracking::StationClock *clock = time->clock();
        startRehearsal(time, QStringLiteral("2026-12-05 15:24:00"), 1);
        QTest::mouseClick(time->pauseButton(), Qt::LeftButton);
        QCOMPARE(time->slider()->value(), 0);
        QCOMPARE(time->slider()->maximum(), TimeController::kSliderMinutes);
        QSignalSpy changed(clock, &slew::tracking::StationClock::changed);
        // Half an hour on, from the keyboard: a jump that everyone plans by again.
        QTest::keyClick(time->slider(), Qt::Key_PageUp);
        QCOMPARE(changed.count(), 1);
        QVERIFY(clock->isPaused());
        QVERIFY(std::abs(secondsBetween(clock->nowJulian(), julian(QStringLiteral("2026-12-05T15:54:00Z")))) < 0.001);
        QCOMPARE(time->sliderLine()->text(), QStringLiteral("+0:30 2026-12-05 15:54 UTC"));
        // Stepped on while paused, the slider follows the clock.
        time->stepField()->setValue(3600);
        QTest::mouseClick(time->stepButton(), Qt::LeftButton);
        QCOMPARE(time->slider()->value(), 90);
        QCOMPARE(time->sliderLine()->text(), QStringLiteral("+1:30 2026-12-05 16:54 UTC"));
    }

    void aChosenPassIsRehearsedFromTwoMinutesBeforeItsAos()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.loadElementSets(kAllSets));
        TrackingPanel *panel = f.window->trackingPanel();
        atJo65hq(panel);
        QVERIFY(panel->selectTarget(QStringLiteral("FLOCK 2P-1")));
        TimeController *time = f.window->timeController();
        time->rateField()->setValue(2);
        // FLOCK 2P-1's pass of 2018-01-22 07:42:56 (the first test's).
        const double aos = julian(QStringLiteral("2018-01-22T07:42:56Z"));
        time->rehearsePass(aos);
        const slew::tracking::StationClock *clock = time->clock();
        QVERIFY(clock->isRehearsal());
        QCOMPARE(clock->rate(), 2.0);
        const double lead = secondsBetween(aos, clock->nowJulian());
        QVERIFY2(lead > 110.0 && lead <= 120.0, qPrintable(QString::number(lead)));
        QCOMPARE(time->startField()->text(), QStringLiteral("2018-01-22 07:40:56"));
        QVERIFY(passesPlanned(panel));
        // Two minutes, less what has passed since.
        QVERIFY2(QRegularExpression(QStringLiteral("^AOS in 0:0(1:[0-5]\\d|2:00)$")).match(panel->countdown()->text()).hasMatch(),
                 qPrintable(panel->countdown()->text()));

        // The Tracking tab's button does it for the pass chosen in its table
        // (its AOS read first: the table is planned again once the clock moves).
        QVERIFY(!panel->rehearseButton()->isEnabled() || !panel->passTable()->selectedItems().isEmpty());
        panel->passTable()->selectRow(2);
        QVERIFY(panel->rehearseButton()->isEnabled());
        const double third = panel->passes().at(2).aos.julian;
        QTest::mouseClick(panel->rehearseButton(), Qt::LeftButton);
        const double leadThird = secondsBetween(third, clock->nowJulian());
        QVERIFY2(leadThird > 110.0 && leadThird <= 120.0, qPrintable(QString::number(leadThird)));
    }
};

QTEST_MAIN(TimeControllerTest)
#include "tst_timecontroller.moc"
