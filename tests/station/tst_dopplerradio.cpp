// SPDX-License-Identifier: GPL-3.0-or-later
// The station's radio between passes: a Station with the built-in rotator
// simulator waits for FLOCK 2P-1's pass, its radio on Hamlib's real rigctld
// (dummy rig). Before AOS the radio is read once, to know where it was
// found, and is otherwise left alone: a radio on a CAT bus must not be
// read back to back while nothing is tuned.

#include "../common/hamlibprocess.h"
#include "linkschemes.h"
#include "radio/radiolink.h"
#include "session/rotatorsession.h"
#include "sky/station.h"
#include "sky/tle.h"
#include "sky/utctime.h"
#include "radio/dopplersteering.h"
#include "station/dopplerradio.h"
#include "station/station.h"
#include "tracking/passrunner.h"
#include "tracking/stationclock.h"
#include "tracking/tracktarget.h"

#include <QSignalSpy>
#include <QTest>

using slew::radio::RadioLink;
using slew::station::DopplerRadio;
using slew::station::Station;

namespace {

// FLOCK 2P-1 from the test element sets.
slew::sky::Tle flock()
{
    QString error;
    static const slew::sky::TleFile sets =
        slew::sky::readTleFile(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
    const slew::sky::Tle *found = slew::sky::findOneTle(sets.sets, QStringLiteral("FLOCK 2P-1"), &error);
    return found ? *found : slew::sky::Tle{};
}

// The station at JO65hq on the built-in rotator simulator, its clock from
// `iso` at `rate`, tracking FLOCK 2P-1 until the tracker is in `state`.
bool trackFlock(Station &station, const QString &iso, double rate, slew::tracking::Tracker::State state)
{
    slew::sky::Station place;
    QString error;
    if (!slew::sky::parseStation(QStringLiteral("JO65hq"), &place, &error))
        return false;
    station.setPlace(place);
    station.clock()->rehearse(*slew::sky::julianFromIso(iso), rate);
    station.session()->connectTo(QStringLiteral("sim:"));
    if (!QTest::qWaitFor([&] { return station.session()->isConnected(); }, 10000))
        return false;
    slew::tracking::TrackTarget target;
    target.elements = flock();
    if (target.elements.catalogueNumber == 0 || !station.track(target, 0.0).isEmpty())
        return false;
    return QTest::qWaitFor([&] { return station.passRunner()->tracker().state() == state; }, 20000);
}

} // namespace

class DopplerRadioTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void leavesTheRadioAloneBeforeAos()
    {
        QProcess rigctld;
        const quint16 port = startHamlibDaemon(rigctld, "rigctld", {"-m", "1"});
        QVERIFY(port);

        Station station;
        // Five minutes before AOS (09:17:51), in real time.
        QVERIFY(trackFlock(station, QStringLiteral("2018-01-22T09:12:51Z"), 1.0, slew::tracking::Tracker::State::Waiting));
        QString error;
        DopplerRadio *radio = station.radio();
        QVERIFY2(radio->setLink(QStringLiteral("rigctld://127.0.0.1:%1").arg(port), &error), qPrintable(error));
        slew::radio::RadioPlan plan;
        plan.frequencies.downlinkHz = 435.85e6;
        plan.frequencies.uplinkHz = 145.95e6;
        plan.noradId = flock().catalogueNumber;
        radio->setPlan(plan);
        QSignalSpy sent(radio->link(), &RadioLink::commandSent);
        QSignalSpy read(radio->link(), &RadioLink::frequenciesRead);
        radio->connectRadio();
        QTRY_COMPARE_WITH_TIMEOUT(radio->link()->state(), RadioLink::State::Open, 15000);
        // Where the radio was found is read once...
        QTRY_COMPARE_WITH_TIMEOUT(read.count(), 1, 10000);
        // ...and nothing is asked after it: a command of the test's, given
        // now, is the next on the wire. (Read again on each answer, the
        // radio was read back to back until AOS, some 3,000 times a second.)
        radio->link()->setMode(QStringLiteral("USB"), 0);
        auto texts = [&] {
            QStringList all;
            for (const QList<QVariant> &args : std::as_const(sent))
                all << args.at(0).toString();
            return all;
        };
        QTRY_VERIFY_WITH_TIMEOUT(texts().contains(QStringLiteral("+M USB 0")), 10000);
        const QStringList before = texts().mid(0, texts().indexOf(QStringLiteral("+M USB 0")));
        // The opening's read and the one of where the radio was found.
        QVERIFY2(before.count(QStringLiteral("+f")) == 2, qPrintable(before.join(", ")));
        QVERIFY(!radio->isSteering());
        rigctld.terminate();
        QTRY_COMPARE(rigctld.state(), QProcess::NotRunning);
    }

    void tunesAPassAlreadyUpWithoutTakingItsOwnFrequenciesForTheDial()
    {
        // As in the window: the pass is up, the radio (sim:, libhamlib in
        // process) connected, and only then the frequencies applied.
        Station station;
        QVERIFY(trackFlock(station, QStringLiteral("2018-01-22T09:19:00Z"), 5.0, slew::tracking::Tracker::State::Tracking));
        QString error;
        DopplerRadio *radio = station.radio();
        QVERIFY2(radio->setLink(QStringLiteral("sim:"), &error), qPrintable(error));
        QSignalSpy read(radio->link(), &RadioLink::frequenciesRead);
        radio->connectRadio();
        QTRY_COMPARE_WITH_TIMEOUT(radio->link()->state(), RadioLink::State::Open, 15000);
        QTRY_COMPARE_WITH_TIMEOUT(read.count(), 1, 10000);
        QSignalSpy followed(radio->steering(), &slew::radio::DopplerSteering::dialFollowed);
        QSignalSpy lines(radio, &DopplerRadio::logLine);
        slew::radio::RadioPlan plan;
        plan.frequencies.downlinkHz = 435.85e6;
        plan.frequencies.uplinkHz = 145.95e6;
        plan.frequencies.uplinkFollows = slew::radio::UplinkFollowsDial::OppositeWay;
        plan.receiveMode = QStringLiteral("USB");
        plan.transmitMode = QStringLiteral("LSB");
        plan.noradId = flock().catalogueNumber;
        radio->setPlan(plan);
        QVERIFY(radio->isSteering());
        // Until a hundred frequencies have been sent, nothing the radio
        // reads back is taken for a turn of the dial.
        QTRY_VERIFY_WITH_TIMEOUT(radio->steering()->commandsSent() > 100, 30000);
        QStringList said;
        for (const QList<QVariant> &args : std::as_const(lines))
            said << args.at(0).toString();
        QVERIFY2(followed.isEmpty(), qPrintable(said.join('\n')));
        QVERIFY2(radio->figures().worstHz < 500, qPrintable(QString::number(radio->figures().worstHz)));
    }
};

QTEST_GUILESS_MAIN(DopplerRadioTest)
#include "tst_dopplerradio.moc"
