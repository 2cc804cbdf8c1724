// SPDX-License-Identifier: GPL-3.0-or-later
// Stop works from every state: it never throws the window, sends SA SE on
// any open link, halts whatever is moving, and ends jogs and homing. The
// simulator runs on its manual clock, pumped by the fixture; the moment a
// motion is under way is caught as the session reports it, and the clock is
// held while Stop is pressed.

#include "windowfixture.h"

#include "rotor/jogpad.h"
#include "rotor/parkhomepanel.h"
#include "stopbutton.h"

#include <QLineEdit>
#include <QPushButton>
#include <QTest>

namespace {
const QRegularExpression kStopLine(QStringLiteral("^SA SE$"));
}

class TestStopEveryState : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }

    void disconnectedStopSaysWhyAndSendsNothing()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("stopButton")), Qt::LeftButton);
        QCOMPARE(f.sent.size(), 0);
        QVERIFY(f.find<QWidget>(QStringLiteral("eventLog"))->property("plainText").toString().contains(
            QStringLiteral("nothing to stop")));
    }

    void connectingStopIsSafe()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        f.window->connectTo(f.uri);
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("stopButton")), Qt::LeftButton);
        QVERIFY(f.connectAndWait()); // and the connection still comes up
    }

    void idleStopSendsStop()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.window->stopButton()->stopFor(QStringLiteral("the test")));
        QCOMPARE(f.sentCount(kStopLine), 1);
    }

    void stopHaltsAGoto()
    {
        WindowFixture f(QStringLiteral("sim:?max_speed=3&clock=manual"));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.session.gotoPosition(300, 80));
        QVERIFY(f.holdClockWhen([&] { return f.session.elevation() > 5; }));
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("stopButton")), Qt::LeftButton);
        f.releaseClock();
        QVERIFY(f.waitUntilStill());
        QVERIFY(f.session.elevation() < 75); // it stopped short of the target
    }

    void stopEndsAJogEvenWhileTheButtonIsHeld()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        auto *left = f.find<QPushButton>(QStringLiteral("jogUp"));
        QTest::mousePress(left, Qt::LeftButton);
        const double start = f.session.elevation();
        QVERIFY(f.holdClockWhen([&] { return f.session.elevation() > start + 1; }));
        QTest::keyClick(f.window.get(), Qt::Key_Escape);
        f.releaseClock();
        QVERIFY(!f.window->jogPad()->isHeld(slew::ui::JogPad::Up));
        QVERIFY(f.sentCount(kStopLine) >= 1);
        QVERIFY(f.waitUntilStill());
        QTest::mouseRelease(left, Qt::LeftButton);
    }

    void stopEndsHoming()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.session.gotoPosition(120, 40));
        QVERIFY(f.waitUntilAt(120, 40, 1.0));
        auto *panel = f.window->parkHomePanel();
        QVERIFY(panel->home());
        QVERIFY(panel->isHoming());
        QVERIFY(f.session.hasPosition());
        QVERIFY(f.holdClockWhen([&] { return f.session.azimuth() < 115; })); // heading for the switch
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("homeCancel")), Qt::LeftButton);
        f.releaseClock();
        QVERIFY(!panel->isHoming());
        QVERIFY(f.sentCount(kStopLine) >= 1);
        QVERIFY(f.waitUntilStill());
        QVERIFY(f.session.azimuth() > 1); // stopped before it got home
    }

    void spaceStopsUnlessTypingEscAlways()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        f.find<QWidget>(QStringLiteral("polarPlot"))->setFocus();
        QTest::keyClick(f.window.get(), Qt::Key_Space);
        QCOMPARE(f.sentCount(kStopLine), 1);
        auto *raw = f.find<QLineEdit>(QStringLiteral("rawCommand"));
        raw->setFocus();
        QTest::keyClick(raw, Qt::Key_Space); // a space in a text field is a space
        QCOMPARE(f.sentCount(kStopLine), 1);
        QCOMPARE(raw->text(), QStringLiteral(" "));
        QTest::keyClick(raw, Qt::Key_Escape);
        QCOMPARE(f.sentCount(kStopLine), 2);
    }
};

QTEST_MAIN(TestStopEveryState)
#include "tst_stopeverystate.moc"
