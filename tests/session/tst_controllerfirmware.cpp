// SPDX-License-Identifier: GPL-3.0-or-later
// RotatorSession and MoveWatch against scripted controllers that answer as
// the firmware stations run does (docs/protocol.md, "Controllers in the
// field"): the SatNOGS firmware's status without a moving bit, its missing
// CR10/CR11, its RS485 turn-around and its stepper pauses; K3NG's stop
// within its own tolerance and its refusal of PARK. The bytes are the ones
// those firmware put on the wire; the fake's clock is stepped (fakedevice.h).

#include "../common/simulatorpump.h"
#include "fakedevice.h"
#include "session/movewatch.h"
#include "session/rotatorsession.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using namespace slew;
using session::MoveWatch;
using session::RotatorSession;

namespace {

// The SatNOGS board v2.2 as it answers: one decimal, `GS4` ("pointing") for
// a whole move and `GS1` at rest, `n,value` for a register, and a register
// number read by its first digit (CR10 is register 1). Its steppers turn at
// 6°/s and stand still while it answers, so now and then two readings in a
// row are equal in the middle of a move.
struct SatnogsBoard {
    explicit SatnogsBoard(FakeDevice &d) : device(d) {}
    FakeDevice &device;
    double targetAz = 0.0, targetEl = 0.0;
    double lastSeconds = 0.0;
    int pauseReplies = 0;   // position replies still to come with the steppers paused
    bool pausedOnce = false;
    struct Heard {
        double seconds;
        bool reply; // else a line from the host
        QByteArray text;
    };
    QList<Heard> wire; // in the order they happened, on the fake's clock

    static constexpr double kDegreesPerSecond = 6.0;

    void advance()
    {
        const double now = device.now();
        const double step = kDegreesPerSecond * (now - lastSeconds);
        lastSeconds = now;
        if (pauseReplies > 0)
            return;
        auto toward = [step](double &at, double to) { at += std::clamp(to - at, -step, step); };
        toward(device.az, targetAz);
        toward(device.el, targetEl);
    }
    bool moving() const { return device.az != targetAz || device.el != targetEl; }

    QByteArray answer(const QByteArray &line)
    {
        wire << Heard{device.now(), false, line};
        advance();
        QByteArray reply;
        if (line == "AZ EL") {
            // Half way, the steppers pause for two replies: equal readings mid-move.
            if (!pausedOnce && moving() && device.az > 20.0) {
                pausedOnce = true;
                pauseReplies = 2;
            }
            if (pauseReplies > 0)
                --pauseReplies;
            reply = "AZ" + QByteArray::number(device.az, 'f', 1) + " EL" + QByteArray::number(device.el, 'f', 1);
        } else if (line == "GS") {
            reply = moving() ? "GS4" : "GS1";
        } else if (line == "GE") {
            reply = "GE1";
        } else if (line == "VE") {
            reply = "VESatNOGS-v2.2";
        } else if (line.startsWith("CR ")) {
            const QByteArray digit = line.mid(3, 1); // it reads one digit
            const QByteArray values[] = {"0", "8.00", "0.00", "0.00", "0.00", "0.00", "0.00", "0.00", "0.00", "0"};
            reply = digit + ',' + values[digit.toInt()];
        } else if (line.startsWith("IP")) {
            reply = line + ",25.00";
        } else if (line.startsWith("AZ") && line.contains(" EL")) {
            const QList<QByteArray> parts = line.split(' ');
            targetAz = parts[0].mid(2).toDouble();
            targetEl = parts[1].mid(2).toDouble();
            return "\n"; // no answer; the fake wants a non-empty one to not answer by default
        } else if (line == "PARK") {
            targetAz = 0.0;
            targetEl = 0.0;
            return "\n";
        } else if (line == "SA SE") {
            targetAz = device.az;
            targetEl = device.el;
            return "\n";
        } else {
            return "\n";
        }
        wire << Heard{device.now(), true, reply};
        return reply + '\n';
    }
};

} // namespace

class ControllerFirmwareTest : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();

    void satnogsPointingStatusDoesNotEndAMove();
    void satnogsMissingRegistersAreNotPolled();
    void satnogsLineGetsItsTurnaround();
    void satnogsIsPolledNoFasterThanItKeepsUp();
    void parkRegistersAreReadBeforeAnyPark();
    void k3ngStopWithinItsToleranceIsArrival();
    void k3ngsEasycomParksWithAGoto();
    void refusedParkSaysWhereAGotoGoes();
    void k3ngHamlibOptionEndsItsReplyWithASpace();

private:
    bool connectAs(protocol::Dialect dialect, protocol::Firmware firmware = protocol::Firmware::Generic);
    bool connectToK3ngEasycom(); // at 59.1, 24.8
    FakeDevice *device = nullptr;
    RotatorSession *session = nullptr;
    std::unique_ptr<SatnogsBoard> board;
};

void ControllerFirmwareTest::init()
{
    device = new FakeDevice;
    device->az = 0.0;
    device->el = 0.0;
    session = new RotatorSession;
    RotatorSession::Options o;
    o.replyTimeoutMs = 150;
    o.retries = 2;
    o.telemetryEvery = 2;
    session->setOptions(o);
    board = std::make_unique<SatnogsBoard>(*device);
}

void ControllerFirmwareTest::cleanup()
{
    delete session;
    delete device;
    board.reset();
}

bool ControllerFirmwareTest::connectAs(protocol::Dialect dialect, protocol::Firmware firmware)
{
    model::RotatorProfile p;
    p.dialect = dialect;
    p.firmware = firmware;
    p.pollHz = 20; // 50 ms, as fast as a profile asks
    session->setProfile(p);
    session->connectTo(device->uri());
    return runEventLoopUntil([&] { return session->capabilities().probed && session->hasPosition(); }, 10000);
}

void ControllerFirmwareTest::satnogsPointingStatusDoesNotEndAMove()
{
    device->script = [this](const QByteArray &line) { return board->answer(line); };
    QVERIFY(connectAs(protocol::Dialect::SatNogs));
    MoveWatch watch(session);
    QSignalSpy ended(&watch, &MoveWatch::ended);
    QVERIFY(session->gotoPosition(49.0, 14.0));
    watch.watch(QPointF(49.0, 14.0));
    TRY_COMPARE_WITH_TIMEOUT(ended.count(), 1, 30000);
    // The stepper pause (two equal readings under GS4) came and went; the
    // move ended where the board did, not 6.70° short as a status bit said.
    QVERIFY(board->pausedOnce);
    QCOMPARE(ended.first().at(0).value<MoveWatch::Outcome>(), MoveWatch::Outcome::Arrived);
    QCOMPARE(device->az, 49.0);
    QCOMPARE(device->el, 14.0);
    QVERIFY2(ended.first().at(2).toDouble() < 0.05, qPrintable(QString::number(ended.first().at(2).toDouble())));
}

void ControllerFirmwareTest::satnogsMissingRegistersAreNotPolled()
{
    device->script = [this](const QByteArray &line) { return board->answer(line); };
    QSignalSpy commanded(session, &RotatorSession::commandedChanged);
    QVERIFY(connectAs(protocol::Dialect::SatNogs));
    const double until = device->now() + 3.0;
    TRY_VERIFY(device->now() >= until);
    // Telemetry went on (GS, GE, IP), and CR10/CR11, which this firmware
    // reads as register 1, were never asked: no line time spent on them,
    // and no commanded position made of a gain.
    QVERIFY(device->count("GS") >= 3);
    QCOMPARE(device->count("CR 10"), 0);
    QCOMPARE(device->count("CR 11"), 0);
    QCOMPARE(commanded.count(), 0);
}

void ControllerFirmwareTest::satnogsLineGetsItsTurnaround()
{
    device->script = [this](const QByteArray &line) { return board->answer(line); };
    QVERIFY(connectAs(protocol::Dialect::SatNogs));
    QVERIFY(session->gotoPosition(30.0, 10.0)); // a command among the polls
    const double until = device->now() + 2.0;
    TRY_VERIFY(device->now() >= until);
    QVERIFY(session->stop(QStringLiteral("the test"), session::Axes::Both));
    TRY_VERIFY(device->received.contains("SA SE"));
    // No line reached the board within 10 ms of its last reply: on RS485 it
    // would have been lost under the end of that reply.
    int checked = 0;
    const SatnogsBoard::Heard *lastReply = nullptr;
    for (const SatnogsBoard::Heard &h : std::as_const(board->wire)) {
        if (h.reply) {
            lastReply = &h;
            continue;
        }
        if (!lastReply)
            continue;
        ++checked;
        QVERIFY2(h.seconds - lastReply->seconds >= 0.010 - 1e-9,
                 qPrintable(QStringLiteral("'%1' %2 ms after the reply '%3'")
                                .arg(QString::fromLatin1(h.text))
                                .arg((h.seconds - lastReply->seconds) * 1000.0)
                                .arg(QString::fromLatin1(lastReply->text))));
    }
    QVERIFY(checked >= 20);
}

void ControllerFirmwareTest::satnogsIsPolledNoFasterThanItKeepsUp()
{
    device->script = [this](const QByteArray &line) { return board->answer(line); };
    QVERIFY(connectAs(protocol::Dialect::SatNogs));
    QVERIFY(session->gotoPosition(90.0, 45.0)); // moving: the full rate
    int lines = 0, positionQueries = 0;
    connect(device, &FakeDevice::lineReceived, this, [&](const QByteArray &line) {
        ++lines;
        positionQueries += line == "AZ EL";
    });
    const double until = device->now() + 6.0;
    TRY_VERIFY(device->now() >= until);
    // The profile asks for 20 polls a second, and telemetry every other
    // one (about 100 lines a second); the firmware gets a position five
    // times a second and its nine lines of telemetry every three seconds.
    QVERIFY2(positionQueries >= 6 * 5 - 2 && positionQueries <= 6 * 5 + 1, qPrintable(QString::number(positionQueries)));
    QVERIFY2(lines <= 6 * 8 + 9, qPrintable(QString::number(lines)));
    QVERIFY(device->count("GS") >= 1);
}

void ControllerFirmwareTest::parkRegistersAreReadBeforeAnyPark()
{
    device->script = [this](const QByteArray &line) { return board->answer(line); };
    device->az = 48.8;
    device->el = 13.8;
    board->targetAz = 48.8;
    board->targetEl = 13.8;
    QVERIFY(connectAs(protocol::Dialect::SatNogs));
    // The probe is over only once CR7/CR8 are in: a client that parks as
    // soon as it may (slewctl park) knows where the park goes.
    QVERIFY(session->parkKnown());
    QCOMPARE(session->parkAzimuth(), 0.0);
    QCOMPARE(session->parkElevation(), 0.0);
    MoveWatch watch(session);
    QSignalSpy ended(&watch, &MoveWatch::ended);
    QVERIFY(session->park());
    watch.watch(QPointF(session->parkAzimuth(), session->parkElevation()));
    TRY_VERIFY(device->received.contains("PARK"));
    const qsizetype parkAt = device->received.indexOf("PARK");
    QVERIFY(parkAt > device->received.indexOf("CR 7") && parkAt > device->received.indexOf("CR 8"));
    QVERIFY(device->received.indexOf("CR 7") >= 0 && device->received.indexOf("CR 8") >= 0);
    // And the wait ends at the park, not on the way (GS4 all along).
    TRY_COMPARE_WITH_TIMEOUT(ended.count(), 1, 30000);
    QCOMPARE(ended.first().at(0).value<MoveWatch::Outcome>(), MoveWatch::Outcome::Arrived);
    QCOMPARE(device->az, 0.0);
    QCOMPARE(device->el, 0.0);
}

bool ControllerFirmwareTest::connectToK3ngEasycom()
{
    device->az = 59.1;
    device->el = 24.8;
    device->script = [this](const QByteArray &line) { return k3ngEasycom(*device, line, 2.3); };
    return connectAs(protocol::Dialect::Easycomm2, protocol::Firmware::K3ng);
}

void ControllerFirmwareTest::k3ngStopWithinItsToleranceIsArrival()
{
    QVERIFY(connectToK3ngEasycom());
    MoveWatch watch(session);
    QSignalSpy ended(&watch, &MoveWatch::ended);
    QVERIFY(session->gotoPosition(94.0, 25.0));
    watch.watch(QPointF(94.0, 25.0));
    TRY_COMPARE(ended.count(), 1);
    QCOMPARE(ended.first().at(0).value<MoveWatch::Outcome>(), MoveWatch::Outcome::Arrived);
    QCOMPARE(device->az, 91.7);
    // The same stop on a controller not known to be K3NG's is short of it.
    QCOMPARE(session->firmwareTraits().azToleranceDeg, 3.0);
    model::RotatorProfile generic = session->profile();
    generic.firmware = protocol::Firmware::Generic;
    session->setProfile(generic);
    ended.clear();
    QVERIFY(session->gotoPosition(40.0, 25.0));
    watch.watch(QPointF(40.0, 25.0));
    TRY_COMPARE(ended.count(), 1);
    QCOMPARE(ended.first().at(0).value<MoveWatch::Outcome>(), MoveWatch::Outcome::StoppedShort);
    // Nor is it where the profile says this controller was built to stop
    // within 1°; and a controller the profile says stops within 3° has
    // arrived, whatever its firmware.
    model::RotatorProfile tight = session->profile();
    tight.firmware = protocol::Firmware::K3ng;
    tight.stopToleranceAzDeg = 1.0;
    session->setProfile(tight);
    QCOMPARE(session->azStopToleranceDeg(), 1.0);
    ended.clear();
    QVERIFY(session->gotoPosition(90.0, 25.0));
    watch.watch(QPointF(90.0, 25.0));
    TRY_COMPARE(ended.count(), 1);
    QCOMPARE(ended.first().at(0).value<MoveWatch::Outcome>(), MoveWatch::Outcome::StoppedShort);
    model::RotatorProfile loose = session->profile();
    loose.firmware = protocol::Firmware::Generic;
    loose.stopToleranceAzDeg = 3.0;
    session->setProfile(loose);
    ended.clear();
    QVERIFY(session->gotoPosition(40.0, 25.0));
    watch.watch(QPointF(40.0, 25.0));
    TRY_COMPARE(ended.count(), 1);
    QCOMPARE(ended.first().at(0).value<MoveWatch::Outcome>(), MoveWatch::Outcome::Arrived);
}

void ControllerFirmwareTest::k3ngsEasycomParksWithAGoto()
{
    // K3NG's Easycom has no PARK: named, it is parked as a GS-232 controller
    // is, with a go-to to the profile's park position, and PARK never goes.
    QVERIFY(connectToK3ngEasycom());
    MoveWatch watch(session);
    QSignalSpy ended(&watch, &MoveWatch::ended);
    QVERIFY(session->park());
    watch.watch(QPointF(0.0, 90.0));
    TRY_COMPARE(ended.count(), 1);
    QCOMPARE(ended.first().at(0).value<MoveWatch::Outcome>(), MoveWatch::Outcome::Arrived);
    QVERIFY(device->received.contains("AZ0.0 EL90.0"));
    QVERIFY(!device->received.contains("PARK"));
}

void ControllerFirmwareTest::refusedParkSaysWhereAGotoGoes()
{
    // The same controller not known to be K3NG's: PARK goes, its `?` ends
    // the wait at once, and says what would park it.
    QVERIFY(connectToK3ngEasycom());
    model::RotatorProfile generic = session->profile();
    generic.firmware = protocol::Firmware::Generic;
    session->setProfile(generic);
    MoveWatch watch(session);
    QSignalSpy ended(&watch, &MoveWatch::ended);
    QVERIFY(session->park());
    watch.watch(std::nullopt);
    TRY_COMPARE(ended.count(), 1);
    QCOMPARE(ended.first().at(0).value<MoveWatch::Outcome>(), MoveWatch::Outcome::Refused);
    QVERIFY2(watch.refusal().contains("refused 'PARK'")
                 && watch.refusal().contains("a go-to to the profile's park position, az 0.0 el 90.0"),
             qPrintable(watch.refusal()));
}

void ControllerFirmwareTest::k3ngHamlibOptionEndsItsReplyWithASpace()
{
    // K3NG's OPTION_HAMLIB_EASYCOM_AZ_EL_COMMAND_HACK: `AZ EL` answered
    // `AZ59.5 EL25.0 `, ended by a space and nothing after it. Each token
    // ends at its space, so the position is read without a line end, poll
    // after poll.
    device->az = 59.5;
    device->el = 25.0;
    device->script = [this](const QByteArray &line) -> QByteArray {
        if (line == "AZ EL")
            return "AZ" + QByteArray::number(device->az, 'f', 1) + " EL" + QByteArray::number(device->el, 'f', 1) + ' ';
        return k3ngEasycom(*device, line);
    };
    QVERIFY(connectAs(protocol::Dialect::Easycomm2, protocol::Firmware::K3ng));
    QCOMPARE(session->azimuth(), 59.5);
    QCOMPARE(session->elevation(), 25.0);
    device->az = 61.0;
    TRY_COMPARE(session->azimuth(), 61.0);
    QCOMPARE(session->unreadableReplies(), qint64(0));
    QCOMPARE(session->capabilities().positionFeedback, true);
}

QTEST_GUILESS_MAIN(ControllerFirmwareTest)
#include "tst_controllerfirmware.moc"
