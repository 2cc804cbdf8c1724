// SPDX-License-Identifier: GPL-3.0-or-later
// Doppler for the radio: the formulas, and the steering that keeps a radio
// on them (the lead, the threshold, the tuning step, the operator's dial).

#include "fakeradiolink.h"

#include "radio/doppler.h"
#include "radio/dopplersteering.h"
#include "sky/observation.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace slew::radio;

namespace {

constexpr double kC = slew::sky::kSpeedOfLightKmS;
constexpr double kMsPerDay = 86400000.0;

// A range-rate that sweeps from +7 km/s (receding... as the pass starts
// approaching: -7) to +7 over ten minutes, as a high LEO pass does.
std::optional<double> sweep(double julian)
{
    const double seconds = julian * 86400.0;
    return std::clamp(-7.0 + 14.0 * seconds / 600.0, -7.0, 7.0);
}

double julianAt(qint64 ms)
{
    return double(ms) / kMsPerDay;
}

// The radio and the steering on one simulated clock, from *ms up to `end`:
// the radio every `radioStepMs`, the steering every 20 ms, as the
// station's timer drives it.
void runRadioAndSteering(FakeRadioLink &radio, DopplerSteering &steering, qint64 *ms, qint64 end, qint64 radioStepMs)
{
    for (; *ms <= end; *ms += radioStepMs) {
        radio.advanceTo(*ms);
        if (*ms % 20 == 0)
            steering.step(julianAt(*ms), *ms);
    }
}

} // namespace

class DopplerTest : public QObject {
    Q_OBJECT
private slots:
    void theFormulas()
    {
        // Approaching at 7 km/s, a 435 MHz downlink is heard higher and a
        // 145.9 MHz uplink must be sent lower.
        QCOMPARE(downlinkOnGroundHz(435e6, -7.0), 435e6 * (1 + 7.0 / kC));
        QVERIFY(std::abs(downlinkOnGroundHz(435e6, -7.0) - 435e6 - 10157.03) < 0.01);
        QCOMPARE(uplinkToSendHz(145.9e6, -7.0), 145.9e6 / (1 + 7.0 / kC));
        QVERIFY(uplinkToSendHz(145.9e6, -7.0) < 145.9e6);
        // What the satellite hears of the uplink sent is its nominal uplink.
        QVERIFY(std::abs(downlinkOnGroundHz(uplinkToSendHz(145.9e6, 5.5), 5.5) - 145.9e6) < 1e-6);

        SatelliteFrequencies sat;
        sat.downlinkHz = 435e6;
        sat.uplinkHz = 145.9e6;
        sat.downlinkOffsetHz = -120;
        sat.uplinkOffsetHz = 40;
        RadioTuning both = tuningFor(sat, 3.0);
        QCOMPARE(both.receiveHz, (435e6 - 120) * (1 - 3.0 / kC));
        QCOMPARE(*both.transmitHz, (145.9e6 + 40) / (1 - 3.0 / kC));
        sat.correct = DopplerOn::UplinkOnly; // the downlink tuned by ear
        QCOMPARE(tuningFor(sat, 3.0).receiveHz, 435e6 - 120);
        QCOMPARE(*tuningFor(sat, 3.0).transmitHz, *both.transmitHz);
        sat.correct = DopplerOn::DownlinkOnly;
        QCOMPARE(*tuningFor(sat, 3.0).transmitHz, 145.9e6 + 40);
        sat.uplinkHz.reset();
        QVERIFY(!tuningFor(sat, 3.0).transmitHz);

        QCOMPARE(quantised(435010157.4, 1), 435010157.0);
        QCOMPARE(quantised(435010157.4, 10), 435010160.0);
        QCOMPARE(quantised(435010157.4, 0), 435010157.0);
    }

    void followsAPassWithinTheThreshold()
    {
        FakeRadioLink radio;
        DopplerSteering steering(&radio);
        DopplerSteering::Settings settings;
        settings.followDial = false;
        steering.setSettings(settings);
        SatelliteFrequencies sat;
        sat.downlinkHz = 435e6;
        sat.uplinkHz = 145.9e6;
        steering.begin(sat, sweep);
        double worst = 0;
        int perSecond = 0, busiest = 0;
        for (qint64 ms = 0; ms <= 600000; ms += 10) {
            radio.advanceTo(ms);
            if (ms % 20 == 0) {
                const int before = steering.commandsSent();
                steering.step(julianAt(ms), ms);
                perSecond += steering.commandsSent() - before;
            }
            if (ms % 1000 == 0) {
                busiest = std::max(busiest, perSecond);
                perSecond = 0;
            }
            const RadioTuning truth = tuningFor(sat, *sweep(julianAt(ms)));
            worst = std::max({worst, std::abs(*radio.receive - truth.receiveHz), std::abs(*radio.transmit - *truth.transmitHz)});
        }
        // Off by at most the threshold and a step's rounding, plus what the
        // Doppler moves in one step of the steering (23 Hz/s here: 0.5 Hz).
        QVERIFY2(worst <= 2.0 + 0.5 + 0.5, qPrintable(QString::number(worst)));
        QVERIFY2(busiest <= 20, qPrintable(QString::number(busiest)));
    }

    void leadsByTheRadiosLatency()
    {
        FakeRadioLink radio;
        radio.latency = 300;
        DopplerSteering steering(&radio);
        DopplerSteering::Settings settings;
        settings.followDial = false;
        steering.setSettings(settings);
        SatelliteFrequencies sat;
        sat.downlinkHz = 435e6;
        steering.begin(sat, sweep);
        double worstLed = 0;
        for (qint64 ms = 0; ms <= 60000; ms += 10) {
            radio.advanceTo(ms);
            steering.step(julianAt(ms), ms);
            if (ms > 1000)
                worstLed = std::max(worstLed, std::abs(*radio.receive - tuningFor(sat, *sweep(julianAt(ms))).receiveHz));
        }
        QVERIFY2(worstLed <= 3.5, qPrintable(QString::number(worstLed)));

        // Without the lead the radio is always 300 ms behind: 7 Hz here.
        FakeRadioLink late;
        late.latency = 300;
        DopplerSteering unled(&late);
        settings.leadMs = 0;
        unled.setSettings(settings);
        unled.begin(sat, sweep);
        double worstLate = 0;
        for (qint64 ms = 0; ms <= 60000; ms += 10) {
            late.advanceTo(ms);
            unled.step(julianAt(ms), ms);
            if (ms > 1000)
                worstLate = std::max(worstLate, std::abs(*late.receive - tuningFor(sat, *sweep(julianAt(ms))).receiveHz));
        }
        QVERIFY2(worstLate > worstLed + 3, qPrintable(QStringLiteral("%1 against %2").arg(worstLate).arg(worstLed)));
    }

    void keepsToTheRadiosStep()
    {
        FakeRadioLink radio;
        radio.step = 10;
        DopplerSteering steering(&radio);
        SatelliteFrequencies sat;
        sat.downlinkHz = 435e6;
        steering.begin(sat, sweep);
        for (qint64 ms = 0; ms <= 20000; ms += 20) {
            radio.advanceTo(ms);
            steering.step(julianAt(ms), ms);
        }
        QVERIFY(!radio.sent.isEmpty());
        for (const QString &command : radio.sent)
            QVERIFY2(command.endsWith(u'0'), qPrintable(command));
        QVERIFY(!steering.dialTurning()); // its own rounded commands read back are not a dial
    }

    void followsTheDialWithoutJumpingBack()
    {
        // A linear, inverting transponder (as most are): the operator turns
        // the downlink up 2 kHz; the uplink goes 2 kHz down with it.
        FakeRadioLink radio;
        radio.latency = 100;
        DopplerSteering steering(&radio);
        SatelliteFrequencies sat;
        sat.downlinkHz = 435.150e6;
        sat.uplinkHz = 145.950e6;
        sat.uplinkFollows = UplinkFollowsDial::OppositeWay;
        steering.begin(sat, sweep);
        QSignalSpy followed(&steering, &DopplerSteering::dialFollowed);
        qint64 ms = 0;
        auto runUntil = [&](qint64 end) { runRadioAndSteering(radio, steering, &ms, end, 10); };
        runUntil(30000);
        QVERIFY(!steering.dialTurning()); // Slew's own commands, read back late, are not a turn
        QCOMPARE(followed.count(), 0);

        const double before = *radio.receive;
        const double turnedTo = before + 2000;
        radio.turnDialTo(turnedTo);
        const int sentBefore = int(radio.sent.size());
        runUntil(31000); // the hand rests on it for a second
        QCOMPARE(followed.count(), 1);
        const double offset = followed.first().at(0).toDouble();
        // 2 kHz as heard, less the Doppler over that second and the half
        // step the command held was ahead: within 15 Hz.
        QVERIFY2(std::abs(offset - 2000) < 15.0, qPrintable(QString::number(offset)));
        // Nothing sent the old frequency back over the turn.
        for (qsizetype i = sentBefore; i < radio.sent.size(); ++i) {
            if (radio.sent[i].startsWith(u'F'))
                QVERIFY2(std::abs(radio.sent[i].mid(2).toDouble() - before) > 1000, qPrintable(radio.sent[i]));
        }
        QVERIFY(std::abs(*radio.receive - turnedTo) < 100); // where the operator left it, not back
        QVERIFY(std::abs(steering.satellite().downlinkHz - (435.150e6 + offset)) < 1e-3);
        QVERIFY(std::abs(*steering.satellite().uplinkHz - (145.950e6 - offset)) < 1e-3);

        // Correcting goes on from the operator's point.
        runUntil(60000);
        const RadioTuning truth = tuningFor(steering.satellite(), *sweep(julianAt(ms)));
        QVERIFY(std::abs(*radio.receive - truth.receiveHz) < 5);
        QVERIFY(std::abs(*radio.transmit - *truth.transmitHz) < 5);
        QCOMPARE(followed.count(), 1);
    }

    void aDialTurnIsNoDopplerError()
    {
        // The operator retunes 14 kHz up the passband of an inverting
        // transponder, on a radio that takes 100 ms for a command: until it
        // has taken the uplink of the new point it holds the old one, which
        // was right for the old point. The pass's error stays the Doppler's;
        // the turn is a figure of its own.
        FakeRadioLink radio;
        radio.latency = 100;
        DopplerSteering steering(&radio);
        SatelliteFrequencies sat;
        sat.downlinkHz = 435.850e6;
        sat.uplinkHz = 145.950e6;
        sat.uplinkFollows = UplinkFollowsDial::OppositeWay;
        steering.begin(sat, sweep);
        QSignalSpy measured(&steering, &DopplerSteering::measured);
        qint64 ms = 0;
        auto runUntil = [&](qint64 end) { runRadioAndSteering(radio, steering, &ms, end, 10); };
        runUntil(30000);
        // In two clicks, a latency apart: a command of Slew's on its way
        // when the first lands may overwrite it (CAT has no lock), as on a
        // real radio; the second stays.
        const double turnedTo = *radio.receive + 14000;
        radio.turnDialTo(turnedTo - 7000);
        runUntil(30150);
        radio.turnDialTo(turnedTo);
        runUntil(60000);

        const DopplerFigures figures = steering.figures();
        QVERIFY(figures.samples > 1000);
        QVERIFY2(figures.worstHz < 50, qPrintable(describeFigures(figures)));
        QVERIFY2(std::abs(figures.dialOffsetHz - 14000) < 15, qPrintable(describeFigures(figures)));
        QCOMPARE(steering.dialOffsetHz(), figures.dialOffsetHz);
        for (const QList<QVariant> &round : std::as_const(measured)) {
            for (const QVariant &error : round) {
                if (std::isfinite(error.toDouble()))
                    QVERIFY2(std::abs(error.toDouble()) < 50, qPrintable(error.toString()));
            }
        }
        QVERIFY2(describeFigures(figures).contains(QStringLiteral("; dial offset +14 0")),
                 qPrintable(describeFigures(figures)));
        // The radio ends where the operator put it, the uplink 14 kHz down.
        const RadioTuning truth = tuningFor(steering.satellite(), *sweep(julianAt(ms)));
        QVERIFY(std::abs(*radio.receive - truth.receiveHz) < 5);
        QVERIFY(std::abs(*steering.satellite().uplinkHz - (145.950e6 - figures.dialOffsetHz)) < 1e-3);
        // Not turned: no offset said.
        QVERIFY(!describeFigures(DopplerFigures{}).contains(QStringLiteral("dial")));
    }

    void theRadiosFrequencyBeforeAosIsNoDial()
    {
        // At AOS the radio is on another frequency (where the operator left
        // it). The first round asks for a reading and sends the first
        // frequency; the answer comes back after, and shows what the radio
        // held when asked: not a turn of the dial.
        FakeRadioLink radio;
        radio.latency = 40;
        radio.answerLater = true;
        radio.receive = 145.0e6;
        DopplerSteering steering(&radio);
        SatelliteFrequencies sat;
        sat.downlinkHz = 435.85e6;
        steering.begin(sat, sweep);
        QSignalSpy followed(&steering, &DopplerSteering::dialFollowed);
        for (qint64 ms = 0; ms <= 5000; ms += 20) {
            radio.advanceTo(ms);
            steering.step(julianAt(ms), ms);
            radio.answerReads();
        }
        QCOMPARE(followed.count(), 0);
        QVERIFY(!steering.dialTurning());
        QVERIFY(std::abs(*radio.receive - 435.85e6) < 20000);
        QVERIFY(steering.figures().worstHz < 50);
    }

    void beginningAgainTakesNoEarlierFrequencyForTheDial()
    {
        // Begun again on an open link (the window's Apply during a pass):
        // the radio still takes, and reads back, frequencies of the first
        // begin() for a latency after it. They are Slew's own, not a turn.
        FakeRadioLink radio;
        radio.latency = 300;
        DopplerSteering steering(&radio);
        SatelliteFrequencies sat;
        sat.downlinkHz = 435.85e6;
        sat.uplinkHz = 145.95e6;
        steering.begin(sat, sweep);
        QSignalSpy followed(&steering, &DopplerSteering::dialFollowed);
        qint64 ms = 0;
        auto runUntil = [&](qint64 end) { runRadioAndSteering(radio, steering, &ms, end, 20); };
        runUntil(20000);
        for (int again = 0; again < 20; ++again) {
            steering.begin(sat, sweep);
            runUntil(ms + 70 + 37 * again); // at every phase of the commands on their way
        }
        runUntil(ms + 5000);
        QCOMPARE(followed.count(), 0);
        QVERIFY(!steering.dialTurning());
        const RadioTuning truth = tuningFor(sat, *sweep(julianAt(ms)));
        QVERIFY(std::abs(*radio.receive - truth.receiveHz) < 20);
    }

    void aReadThatFailsDoesNotStopTheReceiveSide()
    {
        // A read the radio never answers (a timeout on the bus) holds the
        // next receive frequency back for a while, not for the rest of the pass.
        FakeRadioLink radio;
        radio.latency = 40;
        DopplerSteering steering(&radio);
        SatelliteFrequencies sat;
        sat.downlinkHz = 435.85e6;
        steering.begin(sat, sweep);
        qint64 ms = 0;
        auto runUntil = [&](qint64 end) { runRadioAndSteering(radio, steering, &ms, end, 20); };
        runUntil(5000);
        radio.failReads = true;
        runUntil(5100); // a read asked, and lost
        radio.failReads = false;
        const qsizetype sentBefore = radio.sent.size();
        runUntil(15000);
        QVERIFY(radio.sent.size() > sentBefore + 20);
        const RadioTuning truth = tuningFor(sat, *sweep(julianAt(ms)));
        QVERIFY2(std::abs(*radio.receive - truth.receiveHz) < 20,
                 qPrintable(QString::number(*radio.receive - truth.receiveHz)));
    }

    void sendsNothingWhileTheDialTurns()
    {
        FakeRadioLink radio;
        DopplerSteering steering(&radio);
        SatelliteFrequencies sat;
        sat.downlinkHz = 435e6;
        steering.begin(sat, sweep);
        qint64 ms = 0;
        for (; ms <= 5000; ms += 20) {
            radio.advanceTo(ms);
            steering.step(julianAt(ms), ms);
        }
        // Turning on and on, a click every 100 ms: held off all along.
        const qsizetype sentBefore = radio.sent.size();
        for (int click = 0; click < 30; ++click) {
            radio.turnDialTo(*radio.receive + 50);
            for (int i = 0; i < 5; ++i, ms += 20) {
                radio.advanceTo(ms);
                steering.step(julianAt(ms), ms);
            }
        }
        QCOMPARE(radio.sent.size(), sentBefore);
        QVERIFY(steering.dialTurning());
    }
};

QTEST_GUILESS_MAIN(DopplerTest)
#include "tst_doppler.moc"
