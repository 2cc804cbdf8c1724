// SPDX-License-Identifier: GPL-3.0-or-later
// The station's record of a pass, with no window: a Station on the built-in
// simulator tracks FLOCK 2P-1 through the end of a pass rehearsed at 20
// times, its radio (the built-in simulated one) tuned for Doppler, and the
// record has the pass's times, the plan's worst, samples a few a second
// and the tracker's and the radio's own figures, outcome tracked. A Stop
// mid-pass finishes the record as interrupted, saying why, and a station
// whose records are not open records nothing.
//
// The station clock is a rehearsal clock, which keeps the wall clock's
// pace times 20 (the simulator is paced to it): a pass tracked by the
// station cannot run on the simulator's manual clock, whose time only the
// test moves. The tracker's own figures are checked on the manual clock in
// tests/tracking.

#include "linkschemes.h"
#include "radio/radioplan.h"
#include "records/passrecordstore.h"
#include "session/rotatorsession.h"
#include "sky/site.h"
#include "sky/elementsetformat.h"
#include "sky/utctime.h"
#include "station/dopplerradio.h"
#include "station/passrecorder.h"
#include "station/station.h"
#include "tracking/passrunner.h"
#include "tracking/stationclock.h"
#include "tracking/tracktarget.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using slew::records::Outcome;
using slew::records::PassRecordStore;
using slew::station::Station;
using slew::tracking::Tracker;

namespace {

slew::sky::ElementSet satellite(const QString &name)
{
    QString error;
    static const slew::sky::ElementSetFile sets =
        slew::sky::readElementSetFile(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    const slew::sky::ElementSet *found = slew::sky::findOneSatellite(sets.sets, name, &error);
    return found ? *found : slew::sky::ElementSet{};
}

// The station at JO65hq on the built-in rotator simulator (450°/180°), its
// clock from `iso` at 20 times, tracking a satellite until the tracker
// tracks: FLOCK 2P-1 (AOS 09:15:45, TCA 09:21:28 at 56.4°, LOS 09:27:10), or
// SJ-6D, low and short (AOS 09:03:54, 1.3° at 09:05:57, LOS 09:07:59).
bool track(Station &station, const QString &iso, const QString &name = QStringLiteral("FLOCK 2P-1"),
           int renumberTo = 0)
{
    slew::sky::Site place;
    QString error;
    if (!slew::sky::parseSite(QStringLiteral("JO65hq"), &place, &error))
        return false;
    station.setPlace(place);
    station.clock()->rehearse(*slew::sky::julianFromIso(iso), 20.0);
    slew::model::RotatorProfile profile = station.session()->profile();
    profile.limits = slew::model::RotatorLimits{0, 450, 0, 180};
    station.session()->setProfile(profile);
    station.session()->connectTo(QStringLiteral("sim:?az_max=450&el_max=180"));
    if (!QTest::qWaitFor([&] { return station.session()->isConnected(); }, 10000))
        return false;
    slew::tracking::TrackTarget target;
    target.elements = satellite(name);
    if (renumberTo > 0 && target.elements.catalogueNumber > 0)
        target.elements.catalogueNumber = renumberTo;
    if (target.elements.catalogueNumber == 0 || station.track(target, 0.0).isRefused())
        return false;
    return QTest::qWaitFor([&] { return station.passRunner()->tracker().state() == Tracker::State::Tracking; }, 20000);
}

} // namespace

class PassRecorderTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void recordsAPassWithTheTrackersFigures()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("passes.sqlite"));
        Station station;
        QCOMPARE(station.openPassRecords(path, 90), QString());
        // The radio: Hamlib's dummy rig in process, on the downlink only.
        slew::station::DopplerRadio *radio = station.radio();
        QString error;
        QVERIFY2(radio->setLink(QStringLiteral("sim:"), &error), qPrintable(error));
        slew::radio::RadioPlan plan;
        plan.frequencies.downlinkHz = 435.85e6;
        radio->setPlan(plan);
        radio->connectRadio();
        QSignalSpy recording(station.passRecorder(), &slew::station::PassRecorder::recording);
        QSignalSpy said(station.passRecorder(), &slew::station::PassRecorder::logLine);

        // A whole pass, short, with time to be at the AOS point first: 17 s
        // of the test's time.
        // SJ-6D with a nine-digit number, as the catalogue is moving to.
        QVERIFY(track(station, QStringLiteral("2018-01-22T09:02:30Z"), QStringLiteral("SJ-6D"), 270033591));
        QVERIFY(station.passRecorder()->currentRecord());
        const qint64 id = *station.passRecorder()->currentRecord();
        QCOMPARE(recording.count(), 1);
        QCOMPARE(station.passRecords()->pass(id)->outcome, Outcome::InProgress);
        QVERIFY(QTest::qWaitFor([&] { return station.passRunner()->tracker().state() == Tracker::State::Done; }, 30000));
        QCOMPARE(recording.count(), 2);
        QVERIFY(!station.passRecorder()->currentRecord());

        const slew::records::PassRecord r = *station.passRecords()->pass(id);
        const slew::tracking::TrackingFigures &f = station.passRunner()->tracker().figures();
        qInfo("pass %lld: %d samples; RMS %.3f°, worst %.2f°, %d commands; Doppler RMS %.1f Hz, worst %.1f Hz", id,
              r.samples, r.figures.rmsDeg.value_or(-1), r.figures.worstDeg.value_or(-1), r.figures.commands.value_or(-1),
              r.figures.dopplerRmsHz.value_or(-1), r.figures.dopplerWorstHz.value_or(-1));
        QCOMPARE(r.outcome, Outcome::Tracked);
        QVERIFY(r.reason.isEmpty());
        QCOMPARE(r.planned.target, QStringLiteral("SJ-6D"));
        QCOMPARE(r.planned.norad, 270033591);
        QVERIFY(r.planned.rehearsal);
        // The log says it was rehearsed, where it says the record began and ended.
        QStringList lines;
        for (const QList<QVariant> &line : said)
            lines << line.at(0).toString();
        QVERIFY2(lines.contains(QStringLiteral("records: pass %1 (SJ-6D) in progress (rehearsal)").arg(id)),
                 qPrintable(lines.join(u'\n')));
        QVERIFY2(lines.contains(QStringLiteral("records: pass %1 (SJ-6D) tracked, %2 samples (rehearsal)").arg(id).arg(r.samples)),
                 qPrintable(lines.join(u'\n')));
        // The pass's own times, as predicted.
        const slew::sky::Pass &pass = *station.passRunner()->pass();
        QVERIFY(std::abs(r.planned.aos.toMSecsSinceEpoch() - slew::sky::utcFromJulian(pass.aos.julian).toMSecsSinceEpoch()) <= 1);
        QVERIFY(std::abs(r.planned.tca.toMSecsSinceEpoch() - slew::sky::utcFromJulian(pass.tca.julian).toMSecsSinceEpoch()) <= 1);
        QVERIFY(std::abs(r.planned.los.toMSecsSinceEpoch() - slew::sky::utcFromJulian(pass.los.julian).toMSecsSinceEpoch()) <= 1);
        QCOMPARE(r.planned.aos.toString(Qt::ISODate).left(16), QStringLiteral("2018-01-22T09:03"));
        QCOMPARE(r.planned.los.toString(Qt::ISODate).left(16), QStringLiteral("2018-01-22T09:07"));
        QVERIFY(std::abs(*r.planned.maxElevationDeg - 1.3) < 0.1);
        QCOMPARE(*r.planned.plannedWorstDeg, station.passRunner()->tracker().plan().predictedWorstDeg);
        // The tracker's figures, as it gave them at LOS.
        QCOMPARE(*r.figures.rmsDeg, f.rmsDeg);
        QCOMPARE(*r.figures.worstDeg, f.worstDeg);
        QCOMPARE(*r.figures.commands, f.commands);
        QVERIFY(f.commands > 10);
        // And the radio's.
        QVERIFY(r.figures.dopplerRmsHz && r.figures.dopplerWorstHz);
        QCOMPARE(*r.figures.dopplerRmsHz, radio->figures().rmsHz);
        QCOMPARE(*r.figures.dopplerWorstHz, radio->figures().worstHz);

        // Samples at most two a second of the pass, over its 245 s.
        const QList<slew::records::PassSample> samples = station.passRecords()->samples(id);
        QCOMPARE(samples.size(), r.samples);
        QVERIFY2(samples.size() > 60 && samples.size() <= 491, qPrintable(QString::number(samples.size())));
        for (qsizetype i = 1; i < samples.size(); ++i)
            QVERIFY(samples[i].unixMs - samples[i - 1].unixMs >= slew::station::PassRecorder::kSampleSpacingMs);
        // The tracker sees LOS at its next tick: 200 ms, 4 s of a pass at 20 times.
        QVERIFY(samples.last().unixMs <= r.planned.los.toMSecsSinceEpoch() + 5000);
        // Each sample: the target on the pass, and the error as the tracker
        // measured it, within its worst once past its settling time (the
        // figures leave the first seconds out; the samples keep them).
        const qint64 settled = samples.first().unixMs + qint64(Tracker::kSettleSeconds * 1000) + 1000;
        for (const slew::records::PassSample &s : samples) {
            QVERIFY(s.targetElDeg > -1 && s.targetElDeg < 1.5);
            if (s.unixMs > settled)
                QVERIFY2(s.errorDeg <= f.worstDeg + 1e-9, qPrintable(QString::number(s.errorDeg)));
        }
    }

    void aPassJoinedPastItsTopKeepsItsOwnHighest()
    {
        // FLOCK 2P-1 joined at 09:23:00, after its 56.4° top at 09:21:28:
        // the record has the pass's AOS and highest point, not those of the
        // part tracked (which starts at 09:23 and climbs no higher than
        // where it is joined).
        QTemporaryDir dir;
        Station station;
        QCOMPARE(station.openPassRecords(dir.filePath(QStringLiteral("passes.sqlite")), 90), QString());
        QVERIFY(track(station, QStringLiteral("2018-01-22T09:23:00Z")));
        QVERIFY(station.passRecorder()->currentRecord());
        const slew::records::PassRecord r = *station.passRecords()->pass(*station.passRecorder()->currentRecord());
        QVERIFY(r.planned.maxElevationDeg);
        QVERIFY2(std::abs(*r.planned.maxElevationDeg - 56.4) < 0.1, qPrintable(QString::number(*r.planned.maxElevationDeg)));
        QCOMPARE(r.planned.aos.toString(Qt::ISODate).left(16), QStringLiteral("2018-01-22T09:15"));
        QCOMPARE(r.planned.tca.toString(Qt::ISODate).left(16), QStringLiteral("2018-01-22T09:21"));
        station.untrack(QStringLiteral("test"));
    }

    void aStopMidPassIsRecordedAsInterrupted()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("passes.sqlite"));
        Station station;
        QCOMPARE(station.openPassRecords(path, 90), QString());
        QVERIFY(track(station, QStringLiteral("2018-01-22T09:20:00Z")));
        const qint64 id = *station.passRecorder()->currentRecord();
        QVERIFY(QTest::qWaitFor([&] { return station.passRunner()->tracker().figures().samples > 5; }, 10000));
        QVERIFY(station.stop(QStringLiteral("the test")));
        const slew::records::PassRecord r = *station.passRecords()->pass(id);
        QCOMPARE(r.outcome, Outcome::Interrupted);
        QCOMPARE(r.reason, QStringLiteral("stopped"));
        QVERIFY(r.samples > 0);
        QVERIFY(r.ended.isValid() && r.ended < r.planned.los);
        // No Doppler figures: no radio tuned this pass.
        QVERIFY(!r.figures.dopplerRmsHz);
    }

    void nothingIsRecordedWhenTheRecordsAreNotOpen()
    {
        Station station;
        QVERIFY(!station.passRecords()->isOpen());
        QVERIFY(track(station, QStringLiteral("2018-01-22T09:20:00Z")));
        QVERIFY(!station.passRecorder()->currentRecord());
        station.untrack(QStringLiteral("done"));
    }

    void aFileAnotherSlewRecordsIntoIsOnlyRead()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("passes.sqlite"));
        Station service, window;
        QCOMPARE(service.openPassRecords(path, 90), QString());
        const QString said = window.openPassRecords(path, 90, /*readWhenTaken=*/true);
        QVERIFY2(said.contains(path) && said.contains(QStringLiteral("records none")), qPrintable(said));
        QVERIFY(window.passRecords()->isOpen());
        QVERIFY(!window.passRecords()->canRecord());
        Station third;
        QVERIFY(!third.openPassRecords(path, 90).isEmpty());
        QVERIFY(!third.passRecords()->isOpen());
    }
};

QTEST_GUILESS_MAIN(PassRecorderTest)
#include "tst_passrecorder.moc"
