// SPDX-License-Identifier: GPL-3.0-or-later
// RotatorSession against a scripted controller behind an in-process link
// (fakedevice.h), on the controller's stepped clock: matching, timeout and
// retry, unsolicited values, echo, limit refusal, link loss and
// reconnection. No fixed waits: every wait runs the event loop until a
// condition holds.

#include "../common/simulatorpump.h"
#include "fakedevice.h"
#include "session/movewatch.h"
#include "session/rotatorsession.h"

#include <QSignalSpy>
#include <QTcpServer>
#include <QTest>

// The TRY_* waits (simulatorpump.h) keep the loop, and so the fake's clock, running.

using namespace slew;
using session::RotatorSession;

class RotatorSessionTest : public QObject {
    Q_OBJECT
private slots:
    void init();
    void activeTargetEndsWithAnythingElseSent();
    void cleanup();

    void connectsProbesAndPolls();
    void oneLineAndTwoLinePositionReplies();
    void capabilitiesReflectWhatTheDeviceAnswers();
    void satnogsConfigAnswerWithoutPrefix();
    void configReadEasycomm3Form();
    void unansweredQueryIsRetriedThenFails();
    void unsolicitedValuesAreApplied();
    void echoedCommandsAreIgnored();
    void outOfRangeMovesSendNothing();
    void overlapTakesTheShortestLegalPath();
    void stopGoesOutEvenWhenTheQueueIsStuck();
    void stopIsFollowedByAZeroSpeedHold();
    void aMoveAfterStopCancelsTheHold();
    void dialectsWithoutSpeedCommandsOnlyRelease();
    void rawLinesAreLimitChecked();
    void positionGoesStaleWhenRepliesStop();
    void linkLossFailsWaitingRequestsAndReconnects();
    void badUriAndRefusedConnectionAreClearMessages();
    void alarmFailsTheRequestInFlight();
    void telemetryAndStatusSignals();
    void velocityJogAndSoftLimitStop();
    void singleAxisGoto();
    void reportEqualToTargetIsNotAnEchoFromANonEchoingDevice();
    void k3ngEasycomIsReadAndItsRefusalEndsTheMove();
    void noMoveGoesOutWhileNoPositionIsRead();

private:
    bool connectSession(RotatorSession &s, FakeDevice &d, protocol::Dialect dialect = protocol::Dialect::SatNogs);
    FakeDevice *device = nullptr;
    RotatorSession *session = nullptr;
};

void RotatorSessionTest::init()
{
    device = new FakeDevice;
    session = new RotatorSession;
    RotatorSession::Options o;
    o.replyTimeoutMs = 150;
    o.retries = 2;
    o.telemetryEvery = 2;
    session->setOptions(o);
}

void RotatorSessionTest::cleanup()
{
    delete session;
    delete device;
}

bool RotatorSessionTest::connectSession(RotatorSession &s, FakeDevice &d, protocol::Dialect dialect)
{
    model::RotatorProfile p;
    p.dialect = dialect;
    p.pollHz = 20;
    s.setProfile(p);
    QSignalSpy caps(&s, &RotatorSession::capabilitiesChanged);
    s.connectTo(d.uri());
    return runEventLoopUntil([&] { return s.capabilities().probed && s.isConnected(); }, 10000);
}

void RotatorSessionTest::connectsProbesAndPolls()
{
    QSignalSpy states(session, &RotatorSession::stateChanged);
    QSignalSpy positions(session, &RotatorSession::positionChanged);
    QVERIFY(connectSession(*session, *device));
    QCOMPARE(states.first().at(0).value<RotatorSession::State>(), RotatorSession::State::Connecting);
    TRY_VERIFY(positions.count() >= 3);
    QCOMPARE(positions.last().at(0).toDouble(), 10.0);
    QCOMPARE(positions.last().at(1).toDouble(), 20.0);
    QCOMPARE(positions.last().at(2).toBool(), false);
    QCOMPARE(session->version(), QStringLiteral("Fake-1.0"));
    // The probe asked each optional command once.
    QVERIFY(device->received.contains("VE"));
    QVERIFY(device->received.contains("GS"));
    QVERIFY(device->received.contains("CR 1"));
}

void RotatorSessionTest::oneLineAndTwoLinePositionReplies()
{
    device->oneLinePosition = false;
    QSignalSpy positions(session, &RotatorSession::positionChanged);
    QVERIFY(connectSession(*session, *device));
    device->az = 123.4;
    TRY_COMPARE(session->azimuth(), 123.4);
    device->oneLinePosition = true;
    device->el = 56.7;
    TRY_COMPARE(session->elevation(), 56.7);
    // Each reply, in either form, gives one position update, not two.
    positions.clear();
    TRY_VERIFY(positions.count() >= 4);
    for (const auto &args : positions)
        QCOMPARE(args.at(1).toDouble(), 56.7);
}

void RotatorSessionTest::capabilitiesReflectWhatTheDeviceAnswers()
{
    device->script = [](const QByteArray &line) -> QByteArray {
        if (line == "GS" || line == "GE" || line.startsWith("IP") || line.startsWith("CR"))
            return "\n"; // answers nothing useful
        return {};
    };
    QVERIFY(connectSession(*session, *device, protocol::Dialect::SatNogs));
    const auto caps = session->capabilities();
    QVERIFY(caps.positionFeedback);
    QVERIFY(caps.version);
    QVERIFY(!caps.status);
    QVERIFY(!caps.errors);
    QVERIFY(!caps.inputs);
    QVERIFY(!caps.config);
    QVERIFY(!caps.encoders); // SatNOGS has no \?ENC: not even asked
    QVERIFY(!device->received.contains("\\?ENC"));
    QVERIFY(caps.velocity && caps.park && caps.reset);
    // What it lacks is not polled.
    device->received.clear();
    TRY_VERIFY(device->count("AZ EL") >= 5);
    QCOMPARE(device->count("GS"), 0);
}

void RotatorSessionTest::satnogsConfigAnswerWithoutPrefix()
{
    QVERIFY(connectSession(*session, *device, protocol::Dialect::SatNogs));
    QSignalSpy values(session, &RotatorSession::configValueReceived);
    session->setPolling(false); // polls read CR10/CR11 too
    TRY_COMPARE(session->queuedRequests(), 0);
    values.clear();
    QVERIFY(session->readConfig(3));
    TRY_VERIFY(!values.isEmpty());
    QCOMPARE(values.first().at(0).toInt(), 3);
    QCOMPARE(values.first().at(1).toString(), QStringLiteral("0.80"));
    QVERIFY(device->received.contains("CR 3"));
}

void RotatorSessionTest::configReadEasycomm3Form()
{
    QVERIFY(connectSession(*session, *device, protocol::Dialect::Easycomm3));
    session->setPolling(false);
    TRY_COMPARE(session->queuedRequests(), 0);
    QSignalSpy values(session, &RotatorSession::configValueReceived);
    QVERIFY(session->writeConfig(1, "2.5"));
    QVERIFY(session->readConfig(1));
    TRY_VERIFY(!values.isEmpty());
    QCOMPARE(values.first().at(0).toInt(), 1);
    QVERIFY(device->received.contains("CW1,2.5"));
    QVERIFY(device->received.contains("CR1"));
    // Bad values are refused before anything is sent.
    QSignalSpy refused(session, &RotatorSession::commandRefused);
    QVERIFY(!session->writeConfig(1, "a b"));
    QVERIFY(!session->writeConfig(1, ""));
    QVERIFY(!session->writeConfig(7, "999")); // park outside the azimuth range
    QCOMPARE(refused.count(), 3);
    QVERIFY(!device->received.contains("CW7,999"));
}

void RotatorSessionTest::unansweredQueryIsRetriedThenFails()
{
    QVERIFY(connectSession(*session, *device));
    session->setPolling(false);
    TRY_COMPARE(session->queuedRequests(), 0);

    // Two lost answers, then an answer: the retry gets it.
    device->received.clear();
    device->ignoreNext = 2;
    QSignalSpy values(session, &RotatorSession::configValueReceived);
    QVERIFY(session->readConfig(2));
    TRY_COMPARE(values.count(), 1);
    QCOMPARE(device->count("CR 2"), 3);

    // Never answered: fails after 1 + retries attempts, with the reason.
    device->received.clear();
    device->silent = true;
    QSignalSpy failed(session, &RotatorSession::requestFailed);
    QVERIFY(session->readConfig(4));
    QVERIFY(failed.wait(3000));
    QCOMPARE(device->count("CR 4"), 3);
    QCOMPARE(failed.first().at(0).toString(), QStringLiteral("CR 4"));
    QVERIFY(failed.first().at(1).toString().contains("no answer"));
}

void RotatorSessionTest::unsolicitedValuesAreApplied()
{
    QVERIFY(connectSession(*session, *device, protocol::Dialect::Easycomm3));
    session->setPolling(false);
    TRY_COMPARE(session->queuedRequests(), 0);
    QSignalSpy positions(session, &RotatorSession::positionChanged);
    QSignalSpy status(session, &RotatorSession::statusChanged);
    QSignalSpy commanded(session, &RotatorSession::commandedChanged);
    device->push("AZ33.25\nEL44.50\nGS1030\nCR10,33.25\n");
    TRY_COMPARE(session->azimuth(), 33.25);
    TRY_COMPARE(session->elevation(), 44.5);
    TRY_VERIFY(!status.isEmpty());
    QCOMPARE(session->status().azimuth(), quint8(6));
    QCOMPARE(session->status().elevation(), quint8(4));
    TRY_VERIFY(!commanded.isEmpty());
    QCOMPARE(commanded.last().at(0).toDouble(), 33.25);
}

void RotatorSessionTest::echoedCommandsAreIgnored()
{
    device->echo = true;
    QVERIFY(connectSession(*session, *device));
    TRY_COMPARE(session->azimuth(), 10.0);
    const int echoesBefore = session->echoesIgnored();
    QVERIFY(echoesBefore > 0); // every query came back before its answer
    device->silent = true; // only the echo comes back now
    QSignalSpy positions(session, &RotatorSession::positionChanged);
    QVERIFY(session->gotoPosition(50, 10));
    TRY_VERIFY(device->received.contains("AZ50.0 EL10.0"));
    TRY_VERIFY(session->echoesIgnored() > echoesBefore);
    // The echoed set command did not pass for a position report.
    for (const auto &args : positions)
        QCOMPARE(args.at(0).toDouble(), 10.0);
    QCOMPARE(session->azimuth(), 10.0);
}

void RotatorSessionTest::outOfRangeMovesSendNothing()
{
    QVERIFY(connectSession(*session, *device));
    QSignalSpy refused(session, &RotatorSession::commandRefused);
    QSignalSpy sent(session, &RotatorSession::bytesSent);
    session->setPolling(false);
    TRY_COMPARE(session->queuedRequests(), 0);
    sent.clear();
    QVERIFY(!session->gotoPosition(400, 10)); // 0..360
    QVERIFY(!session->gotoPosition(10, 95));  // 0..90
    QVERIFY(!session->gotoPosition(10, -1));
    QVERIFY(!session->gotoPosition(qQNaN(), 10));
    QCOMPARE(refused.count(), 4);
    QVERIFY(refused.first().at(0).toString().contains("outside"));
    QCOMPARE(sent.count(), 0);
    QVERIFY(session->gotoPosition(359.9, 89.9));
    TRY_COMPARE(sent.count(), 1); // after the SatNOGS line's turn-around

    QCOMPARE(sent.first().at(0).toByteArray(), QByteArray("AZ359.9 EL89.9\n"));
}

void RotatorSessionTest::activeTargetEndsWithAnythingElseSent()
{
    QVERIFY(connectSession(*session, *device));
    QVERIFY(!session->activeTarget());
    auto goThere = [&] {
        QVERIFY(session->gotoPosition(100, 40));
        QVERIFY(session->activeTarget());
        QCOMPARE(session->activeTarget()->azimuth, 100.0);
        QCOMPARE(session->activeTarget()->elevation, 40.0);
    };
    goThere();
    QVERIFY(session->gotoAxis(session::Axis::Elevation, 20)); // one axis: the other keeps its target
    QCOMPARE(session->activeTarget()->azimuth, 100.0);
    QCOMPARE(session->activeTarget()->elevation, 20.0);
    QVERIFY(session->stop(QStringLiteral("the test"), session::Axes::Azimuth));
    QVERIFY(!session->activeTarget());
    goThere();
    QVERIFY(session->moveAxis(session::Axis::Azimuth, 2.0));
    QVERIFY(!session->activeTarget());
    goThere();
    QVERIFY(session->sendRaw("SA"));
    QVERIFY(!session->activeTarget());
    goThere();
    QVERIFY(session->park());
    QVERIFY(!session->activeTarget());
    goThere();
    QVERIFY(session->home());
    QVERIFY(!session->activeTarget());
    // What the plot shows as the target is where homing goes: the lower
    // limits, not the last go-to.
    QCOMPARE(session->targetAzimuth(), session->profile().limits.azMin);
    QCOMPARE(session->targetElevation(), session->profile().limits.elMin);
    goThere();
    session->disconnectFromRotator();
    QVERIFY(!session->activeTarget());
}

void RotatorSessionTest::overlapTakesTheShortestLegalPath()
{
    model::RotatorProfile p;
    p.dialect = protocol::Dialect::SatNogs;
    p.limits.azMax = 450;
    p.limits.elMax = 180;
    session->setProfile(p);
    device->az = 350;
    session->connectTo(device->uri());
    TRY_COMPARE(session->azimuth(), 350.0);
    QSignalSpy targets(session, &RotatorSession::targetChanged);
    QVERIFY(session->gotoPosition(10, 30)); // 20° on through the overlap, not 340° back
    QCOMPARE(targets.last().at(0).toDouble(), 370.0);
    TRY_VERIFY(device->received.contains("AZ370.0 EL30.0"));
    TRY_COMPARE(session->azimuth(), 370.0);
    QVERIFY(session->gotoPosition(200, 30)); // only one legal position
    QCOMPARE(targets.last().at(0).toDouble(), 200.0);
    QVERIFY(session->gotoPosition(100, 170)); // el up to 180 in this profile
}

void RotatorSessionTest::stopGoesOutEvenWhenTheQueueIsStuck()
{
    QVERIFY(connectSession(*session, *device));
    device->silent = true;
    QVERIFY(session->readConfig(1));
    QVERIFY(session->readConfig(2));
    QVERIFY(session->queuedRequests() >= 2);
    QVERIFY(session->stop(QStringLiteral("the test")));
    TRY_VERIFY(device->received.contains("SA SE"));
    QVERIFY(session->queuedRequests() >= 1); // it did not wait for them
    QVERIFY(session->stop(QStringLiteral("the test"), session::Axes::Azimuth));
    TRY_VERIFY(device->received.contains("SA"));
}

void RotatorSessionTest::stopIsFollowedByAZeroSpeedHold()
{
    QVERIFY(connectSession(*session, *device));
    QSignalSpy held(session, &RotatorSession::stopHoldSent);
    QVERIFY(session->stop(QStringLiteral("the test")));
    TRY_VERIFY(device->received.contains("SA SE"));
    QVERIFY(session->stopHoldPending());
    QVERIFY(!device->received.contains("VL0000 VU0000")); // not at once: a worm gear stops faster on its own
    QVERIFY(held.wait(2000));
    TRY_VERIFY(device->received.contains("VL0000 VU0000")); // SatNOGS writes four digits
    QVERIFY(!session->stopHoldPending());
    // One axis, one hold.
    QVERIFY(session->stop(QStringLiteral("the test"), session::Axes::Elevation));
    QVERIFY(held.wait(2000));
    TRY_VERIFY(device->received.contains("VU0000"));
}

void RotatorSessionTest::aMoveAfterStopCancelsTheHold()
{
    QVERIFY(connectSession(*session, *device));
    QSignalSpy held(session, &RotatorSession::stopHoldSent);
    QVERIFY(session->stop(QStringLiteral("the test")));
    QVERIFY(session->gotoPosition(40, 20)); // the operator's next move wins
    QVERIFY(!session->stopHoldPending());
    TRY_VERIFY(device->received.contains("AZ40.0 EL20.0"));
    // A simulated second on, well past when the hold would have gone.
    const double movedAt = device->now();
    runEventLoopUntil([&] { return device->now() > movedAt + 1.0 || held.count() > 0; }, 10000);
    QCOMPARE(held.count(), 0);
    QVERIFY(!device->received.contains("VL0000 VU0000"));
}

void RotatorSessionTest::dialectsWithoutSpeedCommandsOnlyRelease()
{
    QVERIFY(connectSession(*session, *device, protocol::Dialect::Easycomm2));
    QVERIFY(session->stop(QStringLiteral("the test")));
    QVERIFY(!session->stopHoldPending());
    TRY_VERIFY(device->received.contains("SA SE"));
}

void RotatorSessionTest::rawLinesAreLimitChecked()
{
    QVERIFY(connectSession(*session, *device));
    QSignalSpy refused(session, &RotatorSession::commandRefused);
    QVERIFY(!session->sendRaw("AZ400.0 EL10.0"));
    QVERIFY(!session->sendRaw("EL99"));
    QVERIFY(!session->sendRaw(QString(300, 'A')));
    QVERIFY(!session->sendRaw("   "));
    QCOMPARE(refused.count(), 4);
    QVERIFY(session->sendRaw("VE"));
    TRY_COMPARE(device->count("VE"), 2); // the probe's and ours
    QVERIFY(!device->received.contains("AZ400.0 EL10.0"));
}

void RotatorSessionTest::positionGoesStaleWhenRepliesStop()
{
    QVERIFY(connectSession(*session, *device));
    TRY_VERIFY(session->hasPosition());
    QVERIFY(!session->positionStale());
    QSignalSpy positions(session, &RotatorSession::positionChanged);
    device->silent = true;
    TRY_VERIFY_WITH_TIMEOUT(!positions.isEmpty() && positions.last().at(2).toBool(), 5000);
    QVERIFY(session->positionStale());
    device->silent = false;
    TRY_VERIFY_WITH_TIMEOUT(!session->positionStale(), 5000);
}

void RotatorSessionTest::linkLossFailsWaitingRequestsAndReconnects()
{
    auto o = session->options();
    o.autoReconnect = true;
    session->setOptions(o);
    QVERIFY(connectSession(*session, *device));
    device->silent = true;
    QVERIFY(session->readConfig(5));
    QSignalSpy failed(session, &RotatorSession::requestFailed);
    QSignalSpy states(session, &RotatorSession::stateChanged);
    QSignalSpy positions(session, &RotatorSession::positionChanged);
    device->dropClient();
    TRY_COMPARE(session->state(), RotatorSession::State::Reconnecting);
    // The waiting read failed with the reason, not silently.
    TRY_VERIFY(!failed.isEmpty());
    QVERIFY(failed.first().at(1).toString().contains("closed"));
    QVERIFY(!positions.isEmpty() && positions.last().at(2).toBool()); // stale
    device->silent = false;
    TRY_VERIFY_WITH_TIMEOUT(session->isConnected(), 10000);
    TRY_VERIFY_WITH_TIMEOUT(!session->positionStale(), 5000);
}

void RotatorSessionTest::badUriAndRefusedConnectionAreClearMessages()
{
    QSignalSpy errors(session, &RotatorSession::errorOccurred);
    session->connectTo("bogus://x");
    QCOMPARE(session->state(), RotatorSession::State::Disconnected);
    QVERIFY(errors.last().at(0).toString().contains("bogus://x"));
    QVERIFY(errors.last().at(0).toString().contains("unknown link kind"));

    session->connectTo("tcp://127.0.0.1");
    QVERIFY(errors.last().at(0).toString().contains("no port"));
    session->connectTo("serial:?baud=fast");
    QVERIFY(errors.last().at(0).toString().contains("no serial port"));
    session->connectTo("serial:/dev/ttyS0?baud=fast");
    QVERIFY(errors.last().at(0).toString().contains("baud rate 'fast'"));
    // A dialect or firmware the URI names that Slew does not know: refused
    // before anything opens, with the names it knows.
    session->connectTo("serial:/dev/ttyS0?dialect=yaesu");
    QCOMPARE(session->state(), RotatorSession::State::Disconnected);
    QVERIFY2(errors.last().at(0).toString().startsWith("serial:/dev/ttyS0?dialect=yaesu: unknown dialect 'yaesu' (known: "),
             qPrintable(errors.last().at(0).toString()));
    session->connectTo("tcp://127.0.0.1:4533?dialect=gs232b&firmware=grbl");
    QVERIFY2(errors.last().at(0).toString().contains("unknown firmware 'grbl' (known: generic, k3ng, satnogs)"),
             qPrintable(errors.last().at(0).toString()));
    session->connectTo("serial:/dev/ttyS0?dialect=satnogs&firmware=k3ng");
    QVERIFY2(errors.last().at(0).toString().endsWith("k3ng speaks easycomm2, gs232a or gs232b, not satnogs"),
             qPrintable(errors.last().at(0).toString()));

    // A real socket here: the message is the TCP link's. The port was free
    // a moment ago and nobody listens on it now.
    quint16 port = 0;
    {
        QTcpServer taken;
        QVERIFY(taken.listen(QHostAddress::LocalHost, 0));
        port = taken.serverPort();
    }
    errors.clear();
    const QString uri = QStringLiteral("tcp://127.0.0.1:%1").arg(port);
    session->connectTo(uri);
    TRY_COMPARE(session->state(), RotatorSession::State::Disconnected);
    QVERIFY(!errors.isEmpty());
    QVERIFY(errors.last().at(0).toString().contains(uri));
    QVERIFY(errors.last().at(0).toString().contains("refused", Qt::CaseInsensitive));
}

void RotatorSessionTest::alarmFailsTheRequestInFlight()
{
    device->script = [](const QByteArray &line) -> QByteArray {
        return line == "CR 9" ? QByteArray("ALUNKNOWN_REGISTER_9\n") : QByteArray();
    };
    QVERIFY(connectSession(*session, *device));
    QSignalSpy alarms(session, &RotatorSession::alarmReceived);
    QSignalSpy failed(session, &RotatorSession::requestFailed);
    QVERIFY(session->readConfig(9));
    TRY_COMPARE(alarms.count(), 1);
    QCOMPARE(alarms.first().at(0).toString(), QStringLiteral("UNKNOWN_REGISTER_9"));
    TRY_COMPARE(failed.count(), 1);
    QCOMPARE(device->count("CR 9"), 1); // an alarm is an answer: no retry
}

void RotatorSessionTest::telemetryAndStatusSignals()
{
    device->script = [](const QByteArray &line) -> QByteArray {
        if (line == "GE")
            return "GE10\n"; // sensor | motor
        if (line == "IP7")
            return "IP7,-2.5\n";
        return {};
    };
    QVERIFY(connectSession(*session, *device));
    QSignalSpy telemetry(session, &RotatorSession::telemetryChanged);
    TRY_COMPARE(session->errorFlags(), 10);
    QCOMPARE(session::describeErrorFlags(10), QStringLiteral("sensor error, motor error"));
    TRY_COMPARE(session->telemetry().azVelocity, -2.5);
    TRY_COMPARE(session->telemetry().temperature, 1.5);
    QVERIFY(!telemetry.isEmpty());
}

void RotatorSessionTest::velocityJogAndSoftLimitStop()
{
    model::RotatorProfile p;
    p.dialect = protocol::Dialect::SatNogs;
    p.limits.azMax = 180; // tighter than the controller's own
    session->setProfile(p);
    device->az = 170;
    session->connectTo(device->uri());
    TRY_COMPARE(session->azimuth(), 170.0);
    QSignalSpy errors(session, &RotatorSession::errorOccurred);
    QVERIFY(session->moveAxis(session::Axis::Azimuth, 5.0));
    TRY_VERIFY(device->received.contains("VR5000"));
    QVERIFY(session->moveAxis(session::Axis::Elevation, -1.5));
    TRY_VERIFY(device->received.contains("VD1500"));
    // The axis runs past the profile's limit: the session stops it.
    device->az = 180.5;
    TRY_VERIFY(device->received.contains("SA"));
    QVERIFY(!errors.isEmpty());
    // At the limit, a further move that way is refused; the other way is fine.
    QVERIFY(!session->moveAxis(session::Axis::Azimuth, 1.0));
    QVERIFY(session->moveAxis(session::Axis::Azimuth, -1.0));
    TRY_VERIFY(device->received.contains("VL1000"));
    // Easycomm II has no velocity: ML/MR instead.
    p.dialect = protocol::Dialect::Easycomm2;
    session->setProfile(p);
    QVERIFY(session->moveAxis(session::Axis::Azimuth, -3.0));
    TRY_VERIFY(device->received.contains("ML"));
}

void RotatorSessionTest::singleAxisGoto()
{
    QVERIFY(connectSession(*session, *device));
    QSignalSpy targets(session, &RotatorSession::targetChanged);
    QVERIFY(session->gotoAxis(session::Axis::Azimuth, 50));
    TRY_VERIFY(device->received.contains("AZ50.0"));
    QVERIFY(session->gotoAxis(session::Axis::Elevation, 30));
    TRY_VERIFY(device->received.contains("EL30.0"));
    QCOMPARE(targets.last().at(0).toDouble(), 50.0);
    QCOMPARE(targets.last().at(1).toDouble(), 30.0);
    QVERIFY(!session->gotoAxis(session::Axis::Elevation, 91)); // limits hold for one axis too
    QVERIFY(!device->received.contains("EL91.0"));
    // GS-232 commands both axes at once: the other keeps its current position.
    model::RotatorProfile p = session->profile();
    p.dialect = protocol::Dialect::Gs232B;
    session->setProfile(p);
    QSignalSpy sent(session, &RotatorSession::bytesSent);
    QVERIFY(session->gotoAxis(session::Axis::Azimuth, 120));
    QCOMPARE(sent.last().at(0).toByteArray(), QByteArray("W120 020\r"));
}

void RotatorSessionTest::reportEqualToTargetIsNotAnEchoFromANonEchoingDevice()
{
    QVERIFY(connectSession(*session, *device));
    TRY_COMPARE(session->azimuth(), 10.0);
    QSignalSpy positions(session, &RotatorSession::positionChanged);
    QVERIFY(session->gotoPosition(10, 20)); // where it already is
    // The very next replies carry exactly the target; they count as positions.
    TRY_VERIFY_WITH_TIMEOUT(positions.count() >= 3, 900);
    QCOMPARE(session->echoesIgnored(), 0);
}

void RotatorSessionTest::k3ngEasycomIsReadAndItsRefusalEndsTheMove()
{
    device->az = 59.1;
    device->el = 24.8;
    device->script = [this](const QByteArray &line) { return k3ngEasycom(*device, line); };
    QSignalSpy logged(session, &RotatorSession::errorOccurred);
    QVERIFY(connectSession(*session, *device, protocol::Dialect::Easycomm2));
    TRY_VERIFY(session->hasPosition());
    QCOMPARE(session->azimuth(), 59.1);
    QCOMPARE(session->elevation(), 24.8);
    // What it lacks answered `?` at once: known absent, and not polled.
    const auto caps = session->capabilities();
    QVERIFY(caps.positionFeedback && caps.version);
    QVERIFY(!caps.inputs);
    QCOMPARE(device->count("IP0"), 1);
    // Its refusal of PARK ends the wait for the park at once, with the reason.
    session::MoveWatch watch(session);
    QSignalSpy ended(&watch, &session::MoveWatch::ended);
    QSignalSpy refused(session, &RotatorSession::controllerRefusedMove);
    QVERIFY(session->park());
    watch.watch(std::nullopt);
    TRY_COMPARE(ended.count(), 1);
    QCOMPARE(ended.first().at(0).value<session::MoveWatch::Outcome>(), session::MoveWatch::Outcome::Refused);
    QCOMPARE(refused.count(), 1);
    QVERIFY2(watch.refusal().contains("refused 'PARK'") && watch.refusal().contains("'?'"), qPrintable(watch.refusal()));
    // A go-to it takes is answered by its separators only: no refusal, no
    // unreadable reply, and polls after it read the new position.
    logged.clear();
    QVERIFY(session->gotoPosition(94.0, 25.0));
    TRY_COMPARE(session->azimuth(), 94.0);
    QCOMPARE(session->elevation(), 25.0);
    QCOMPARE(refused.count(), 1);
    for (const auto &args : logged)
        QVERIFY2(!args.at(0).toString().contains("unreadable"), qPrintable(args.at(0).toString()));
    QCOMPARE(session->unreadableReplies(), qint64(0));
}

void RotatorSessionTest::noMoveGoesOutWhileNoPositionIsRead()
{
    // The wrong dialect: a GS-232B answer on an Easycomm link reads as nothing.
    bool wrongDialect = true;
    device->script = [&](const QByteArray &line) -> QByteArray {
        if (line == "AZ EL" && wrongDialect)
            return "AZ=059EL=025\n";
        return {};
    };
    QSignalSpy logged(session, &RotatorSession::errorOccurred);
    QSignalSpy movesRefused(session, &RotatorSession::moveRefused);
    QVERIFY(connectSession(*session, *device, protocol::Dialect::Easycomm2));
    QVERIFY(!session->hasPosition());
    QVERIFY(!session->capabilities().positionFeedback);
    const int heard = int(device->received.size());
    // Every kind of move is refused with the reason; nothing goes out.
    const QString why = QStringLiteral("no position read from the controller: check the dialect (easycomm2)");
    for (const session::CommandResult &r :
         {session->gotoPosition(90, 30), session->gotoAxis(session::Axis::Azimuth, 90),
          session->gotoUnwrapped(90, 30), session->moveAxis(session::Axis::Elevation, 2.0), session->park(),
          session->moveBy(5, 0), session->sendRaw("AZ90.0 EL30.0"), session->sendRaw("MR"),
          session->sendRaw("VL500")}) {
        QVERIFY(!r);
        QVERIFY2(r.refusal == why || r.refusal.contains("present position"), qPrintable(r.refusal));
    }
    QVERIFY(movesRefused.count() >= 8);
    // A query and a stop still go: they are how to find out, and Stop always works.
    QVERIFY(session->sendRaw("VE"));
    QVERIFY(session->stop(QStringLiteral("the test"), session::Axes::Both));
    TRY_VERIFY(device->received.contains("SA SE"));
    for (const QByteArray &line : device->received.mid(heard))
        QVERIFY2(line == "AZ EL" || line == "VE" || line == "SA SE" || line.startsWith("CR") || line.startsWith("IP")
                     || line == "GS" || line == "GE" || line.isEmpty(),
                 line.constData());
    // It is asked again, less often each time, and each failure is said;
    // in between it is not asked at all (three tries a time: the probe's,
    // the first poll's, then one a retry).
    const auto retries = [&] {
        QStringList said;
        for (const auto &args : logged) {
            if (args.at(0).toString().startsWith("still no position read"))
                said << args.at(0).toString();
        }
        return said;
    };
    TRY_VERIFY_WITH_TIMEOUT(retries().size() >= 2, 20000);
    QVERIFY2(retries().at(0).endsWith("asking again in 2 s") && retries().at(1).endsWith("asking again in 4 s"),
             qPrintable(retries().join('\n')));
    QVERIFY2(retries().at(0).contains("no answer within"), qPrintable(retries().at(0)));
    QCOMPARE(device->count("AZ EL"), 3 * 3);
    // The controller answers at last: the position is read, and moves go.
    wrongDialect = false;
    TRY_VERIFY_WITH_TIMEOUT(session->hasPosition(), 30000);
    QVERIFY(session->capabilities().positionFeedback);
    QVERIFY(session->gotoPosition(90, 30));
    TRY_VERIFY(device->received.contains("AZ90.0 EL30.0"));
}

QTEST_GUILESS_MAIN(RotatorSessionTest)
#include "tst_rotatorsession.moc"
