// SPDX-License-Identifier: GPL-3.0-or-later
// The station's schedule at work: a Station with the built-in rotator
// simulator, its clock rehearsing 2018-01-22 from 09:25:40 at 20 times, and
// three satellites by priority: FLOCK 2P-1 (its pass until 09:27:10 under
// way), PERSEUS-M1 (up at 09:29:11) and ENVISAT (up since 09:25:31, over
// both). ENVISAT's pass is dropped for FLOCK's, and said at once (its time
// has come); FLOCK's is followed to its LOS, then PERSEUS-M1's is waited
// for; a change of the list plans again without taking the pass in
// progress away; untrack ends it all. A preview plans as the run does.

#include "linkschemes.h"
#include "schedule/scheduletext.h"
#include "session/rotatorsession.h"
#include "sky/site.h"
#include "sky/elementsetformat.h"
#include "sky/utctime.h"
#include "records/passrecordstore.h"
#include "station/schedulepreviewer.h"
#include "station/schedulerunner.h"
#include "station/station.h"
#include "tracking/passrunner.h"
#include "tracking/stationclock.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using slew::schedule::DropReason;
using slew::schedule::ScheduledPass;
using slew::station::ScheduleRunner;
using slew::station::Station;
using slew::tracking::TrackTarget;

namespace {

TrackTarget satellite(const char *name)
{
    static const slew::sky::ElementSetFile sets =
        slew::sky::readElementSetFile(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    QString error;
    TrackTarget t;
    if (const slew::sky::ElementSet *found = slew::sky::findOneSatellite(sets.sets, QString::fromLatin1(name), &error))
        t.elements = *found;
    return t;
}

double at(const char *iso)
{
    return *slew::sky::julianFromIso(QString::fromLatin1(iso));
}

// The pass of `target` in the plan that covers `julian`.
const ScheduledPass *passOf(const slew::schedule::Schedule &plan, const QString &target, double julian)
{
    for (const ScheduledPass &p : plan.passes)
        if (p.target == target && p.startJulian <= julian + 1e-9 && p.endJulian >= julian)
            return &p;
    return nullptr;
}

} // namespace

class ScheduleRunnerTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        slew::registerLinkSchemes();
        qRegisterMetaType<slew::face::SchedulePreview>();
    }

    void followsTheTakenPassesAndSaysTheDroppedOnes()
    {
        Station station;
        slew::sky::Site place;
        QString error;
        QVERIFY(slew::sky::parseSite(QStringLiteral("JO65hq"), &place, &error));
        station.setPlace(place);
        station.clock()->rehearse(at("2018-01-22T09:25:40Z"), 20.0);
        station.session()->connectTo(QStringLiteral("sim:"));
        QTRY_VERIFY_WITH_TIMEOUT(station.session()->isConnected() && station.session()->hasPosition(), 10000);

        const TrackTarget flock = satellite("FLOCK 2P-1"), perseus = satellite("PERSEUS-M1"),
                          envisat = satellite("ENVISAT");
        QVERIFY(flock.elements.catalogueNumber && perseus.elements.catalogueNumber
                && envisat.elements.catalogueNumber);
        // The station's record of its passes, in a file of the test's.
        QTemporaryDir dir;
        QCOMPARE(station.openPassRecords(dir.filePath(QStringLiteral("passes.sqlite")), 90), QString());
        ScheduleRunner *runner = station.scheduleRunner();
        QSignalSpy lines(runner, &ScheduleRunner::logLine);
        QSignalSpy dropped(runner, &ScheduleRunner::passDropped);
        QCOMPARE(station.runSchedule({flock, perseus, envisat}, slew::station::ScheduleOptions{}).reason(), QString());
        QVERIFY(runner->isRunning());
        QTRY_VERIFY_WITH_TIMEOUT(!runner->schedule().passes.isEmpty(), 20000);
        auto said = [&] {
            QStringList all;
            for (const QList<QVariant> &args : std::as_const(lines))
                all << args.at(0).toString();
            return all.join(QLatin1Char('\n'));
        };

        // The plan: FLOCK's pass taken from now, ENVISAT's dropped for it,
        // PERSEUS-M1's taken after them.
        const slew::schedule::Schedule &plan = runner->schedule();
        const ScheduledPass *flockPass = passOf(plan, flock.name(), at("2018-01-22T09:26:00Z"));
        const ScheduledPass *envisatPass = passOf(plan, envisat.name(), at("2018-01-22T09:30:00Z"));
        const ScheduledPass *perseusPass = passOf(plan, perseus.name(), at("2018-01-22T09:30:00Z"));
        QVERIFY2(flockPass && envisatPass && perseusPass, qPrintable(said()));
        QVERIFY(flockPass->taken);
        QVERIFY(perseusPass->taken);
        QVERIFY(!envisatPass->taken);
        QCOMPARE(envisatPass->reason, DropReason::Overlap);
        QVERIFY2(envisatPass->why.startsWith(QStringLiteral("overlaps %1 (priority 1").arg(flock.name())),
                 qPrintable(envisatPass->why));
        QVERIFY2(said().contains(QStringLiteral("schedule: planned (started): ")), qPrintable(said()));
        QVERIFY(said().contains(QStringLiteral("schedule: targets by priority: 1. FLOCK 2P-1, 2. PERSEUS-M1, 3. ENVISAT")));
        // ENVISAT's pass began before the plan was made: said at once.
        QTRY_VERIFY(!dropped.isEmpty());
        QCOMPARE(dropped.first().at(0).value<ScheduledPass>().target, envisat.name());
        // ...and recorded as dropped, with why.
        const QList<slew::records::PassRecord> recorded = station.passRecords()->passes(envisat.name());
        QCOMPARE(recorded.size(), 1);
        QCOMPARE(recorded.first().outcome, slew::records::Outcome::Dropped);
        QVERIFY2(recorded.first().reason.startsWith(QStringLiteral("overlaps FLOCK 2P-1")),
                 qPrintable(recorded.first().reason));
        QCOMPARE(recorded.first().planned.norad, std::optional<int>(envisat.elements.catalogueNumber));

        // FLOCK's pass, followed to its LOS at 09:27:10; then PERSEUS-M1's
        // is the one waited for.
        QVERIFY(runner->current());
        QCOMPARE(runner->current()->target, flock.name());
        QTRY_COMPARE_WITH_TIMEOUT(station.passRunner()->tracker().state(), slew::tracking::Tracker::State::Tracking,
                                  20000);
        QCOMPARE(station.passRunner()->target().name(), flock.name());
        QTRY_VERIFY_WITH_TIMEOUT(runner->current() && runner->current()->target == perseus.name(), 30000);
        QTRY_COMPARE(station.passRunner()->target().name(), perseus.name());
        QVERIFY(station.passRunner()->isRunning());
        QVERIFY2(said().contains(QStringLiteral("schedule: next: ")), qPrintable(said()));

        // The list changes while PERSEUS-M1's pass is waited for (the rotator
        // not yet on it): planned again; untrack ends it all.
        lines.clear();
        runner->setTargets({perseus, flock});
        QTRY_VERIFY_WITH_TIMEOUT(said().contains(QStringLiteral("schedule: planned (the targets changed): ")), 20000);
        station.untrack(QStringLiteral("the test is over"));
        QVERIFY(!runner->isRunning());
        QVERIFY(!station.passRunner()->isRunning());
        QVERIFY(said().contains(QStringLiteral("schedule: ended: the test is over")));
    }

    // A preview is the plan a run would make, made by the same settings and
    // moving nothing; one at a time; named even before the station has a
    // place. A run asked again with other targets keeps its schedule going.
    void previewsThePlanARunMakes()
    {
        const QList<slew::sky::ElementSet> sets =
            slew::sky::readElementSetFile(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle")).sets;
        const QStringList names{QStringLiteral("FLOCK 2P-1"), QStringLiteral("perseus-m1"), QStringLiteral("27386"),
                                QStringLiteral("NO SUCH SATELLITE")};
        Station station;
        slew::station::SchedulePreviewer previewer(&station, sets);
        QSignalSpy previewed(&previewer, &slew::station::SchedulePreviewer::previewed);
        QSignalSpy refused(&previewer, &slew::station::SchedulePreviewer::refused);

        // No place: each target named, no plan, and why.
        previewer.preview(QStringLiteral("a"), names, {});
        QCOMPARE(previewed.size(), 1);
        auto named = previewed.takeFirst().at(1).value<slew::face::SchedulePreview>();
        QCOMPARE(named.notPlanned, QStringLiteral("a schedule needs the station's place"));
        QCOMPARE(named.targets.size(), 4);
        QCOMPARE(named.targets[1].name, QStringLiteral("PERSEUS-M1"));
        QCOMPARE(named.targets[2].name, QStringLiteral("ENVISAT"));
        QCOMPARE(named.targets[2].spec(), QStringLiteral("27386"));
        QCOMPARE(named.targets[3].problem, QStringLiteral("no satellite 'NO SUCH SATELLITE' among the station's element sets"));

        slew::sky::Site place;
        QString error;
        QVERIFY(slew::sky::parseSite(QStringLiteral("JO65hq"), &place, &error));
        station.setPlace(place);
        station.clock()->rehearse(at("2018-01-22T09:25:40Z"), 1.0);
        station.session()->connectTo(QStringLiteral("sim:"));
        QTRY_VERIFY_WITH_TIMEOUT(station.session()->isConnected() && station.session()->hasPosition(), 10000);
        // Two at once: the first let go, the second planned.
        previewer.preview(QStringLiteral("b"), names, {1, 0, 30});
        previewer.preview(QStringLiteral("c"), names, {});
        QCOMPARE(refused.size(), 1);
        QCOMPARE(refused.first().at(0).toString(), QStringLiteral("b"));
        QCOMPARE(refused.first().at(1).toString(), QStringLiteral("a newer preview was asked"));
        QTRY_COMPARE_WITH_TIMEOUT(previewed.size(), 1, 20000);
        QCOMPARE(previewed.first().at(0).toString(), QStringLiteral("c"));
        const auto preview = previewed.first().at(1).value<slew::face::SchedulePreview>();
        QVERIFY(preview.notPlanned.isEmpty());
        QCOMPARE(preview.schedule.targets, (QStringList{"FLOCK 2P-1", "PERSEUS-M1", "ENVISAT"}));
        // Bad numbers are refused, as a run's are.
        previewer.preview(QStringLiteral("d"), names, {500, 0, 30});
        QVERIFY(refused.last().at(1).toString().startsWith(QStringLiteral("a schedule's hours: ")));
        QVERIFY(!station.scheduleRunner()->isRunning()); // nothing run

        // The run's plan takes and drops what the preview did.
        ScheduleRunner *runner = station.scheduleRunner();
        QCOMPARE(station.runSchedule({satellite("FLOCK 2P-1"), satellite("PERSEUS-M1"), satellite("ENVISAT")},
                                     slew::station::ScheduleOptions{})
                     .reason(),
                 QString());
        QTRY_VERIFY_WITH_TIMEOUT(!runner->schedule().passes.isEmpty(), 20000);
        for (const char *iso : {"2018-01-22T09:26:00Z", "2018-01-22T09:30:00Z"}) {
            for (const QString &target : preview.schedule.targets) {
                const ScheduledPass *previewed = passOf(preview.schedule, target, at(iso));
                const ScheduledPass *run = passOf(runner->schedule(), target, at(iso));
                QCOMPARE(bool(previewed), bool(run));
                if (previewed)
                    QVERIFY2(previewed->taken == run->taken, qPrintable(target + QLatin1Char(' ') + QLatin1String(iso)));
            }
        }
        // Asked again with the list in another order: the same schedule,
        // planned again, not ended and begun anew.
        QSignalSpy lines(runner, &ScheduleRunner::logLine);
        QCOMPARE(station.runSchedule({satellite("PERSEUS-M1"), satellite("FLOCK 2P-1")}, slew::station::ScheduleOptions{})
                     .reason(),
                 QString());
        const auto planned = [&lines] {
            return std::any_of(lines.begin(), lines.end(), [](const QList<QVariant> &line) {
                return line.at(0).toString().startsWith(QStringLiteral("schedule: planned (the targets changed): "));
            });
        };
        QTRY_VERIFY_WITH_TIMEOUT(planned(), 20000);
        for (const QList<QVariant> &line : std::as_const(lines))
            QVERIFY2(!line.at(0).toString().startsWith(QStringLiteral("schedule: ended")), qPrintable(line.at(0).toString()));
        // Other numbers: a new schedule.
        QCOMPARE(station.runSchedule({satellite("PERSEUS-M1")}, slew::station::ScheduleOptions{0, 12, 30}).reason(), QString());
        QVERIFY(lines.size() >= 2);
        bool ended = false;
        for (const QList<QVariant> &line : std::as_const(lines))
            ended |= line.at(0).toString().startsWith(QStringLiteral("schedule: ended: "));
        QVERIFY(ended);
        station.untrack(QStringLiteral("the test is over"));
    }

    void refusedWithoutAPlace()
    {
        Station station;
        QCOMPARE(station.runSchedule({satellite("FLOCK 2P-1")}, slew::station::ScheduleOptions{}).reason(),
                 QStringLiteral("a schedule needs the station's place"));
        QVERIFY(!station.scheduleRunner()->isRunning());
    }
};

QTEST_GUILESS_MAIN(ScheduleRunnerTest)
#include "tst_schedulerunner.moc"
