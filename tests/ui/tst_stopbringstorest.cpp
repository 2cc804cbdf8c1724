// SPDX-License-Identifier: GPL-3.0-or-later
// The window's Stop brings the antenna to rest, from every way it can be
// moving: a go-to, a held jog button, homing, parking and a tracker steering
// through rotctld. On the default simulator (a G-5500 class rotator with a
// self-locking worm gear) it is at rest within a second and 2° of where Stop
// was pressed; on a free-running drive, which coasts on SA / SE, the zero
// speed Slew sends after it brakes the drive to rest within 2 s. Times are
// the simulator's: it runs on its manual clock, pumped from the event loop.

#include "windowfixture.h"

#include "bridge/rotctldserver.h"
#include "rotor/rotctldpanel.h"

#include <QPushButton>
#include <QSignalSpy>
#include <QTcpSocket>
#include <QTest>

namespace {

enum class Motion { Slew, Jog, Homing, Parking, Tracker };

} // namespace

Q_DECLARE_METATYPE(Motion)

class StopBringsToRestTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }

    void stopFromEveryMotion_data()
    {
        QTest::addColumn<QString>("uri");
        QTest::addColumn<int>("restWithinMs");
        QTest::addColumn<double>("maxTravel");
        QTest::addColumn<Motion>("motion");
        const struct {
            const char *name;
            Motion motion;
        } motions[] = {{"slewing", Motion::Slew},   {"jogging", Motion::Jog},     {"homing", Motion::Homing},
                       {"parking", Motion::Parking}, {"tracker", Motion::Tracker}};
        for (const auto &m : motions) {
            QTest::addRow("worm gear, %s", m.name)
                << QStringLiteral("sim:?clock=manual&park_az=200&park_el=60&start_az=100&start_el=30") << 1000 << 2.0 << m.motion;
        }
        // How far a coasting drive runs before the hold brakes it is the
        // drive's business; that it comes to rest in time is Slew's.
        for (const auto &m : motions) {
            QTest::addRow("free drive, %s", m.name)
                << QStringLiteral("sim:?clock=manual&drive=free&park_az=200&park_el=60&start_az=100&start_el=30") << 2000 << 360.0
                << m.motion;
        }
    }

    void stopFromEveryMotion()
    {
        QFETCH(QString, uri);
        QFETCH(int, restWithinMs);
        QFETCH(double, maxTravel);
        QFETCH(Motion, motion);

        WindowFixture f(uri);
        QVERIFY(f.connectAndWait());
        const QPointF start = f.lastPosition();
        QTcpSocket tracker;
        auto *jogRight = f.find<QPushButton>(QStringLiteral("jogRight"));
        switch (motion) {
        case Motion::Slew: QVERIFY(f.session.gotoPosition(300, 80)); break;
        case Motion::Jog: QTest::mousePress(jogRight, Qt::LeftButton); break;
        case Motion::Homing: QTest::mouseClick(f.find<QPushButton>(QStringLiteral("homeButton")), Qt::LeftButton); break;
        case Motion::Parking: QTest::mouseClick(f.find<QPushButton>(QStringLiteral("parkButton")), Qt::LeftButton); break;
        case Motion::Tracker: {
            QVERIFY(f.window->rotctldPanel()->startListening(QStringLiteral("127.0.0.1"), 0));
            tracker.connectToHost(QHostAddress::LocalHost, f.window->rotctldServer()->port());
            QTRY_COMPARE(tracker.state(), QAbstractSocket::ConnectedState);
            QSignalSpy answered(&tracker, &QTcpSocket::readyRead);
            tracker.write("P 250 70\n");
            QVERIFY(answered.wait(5000));
            QCOMPARE(tracker.readAll(), QByteArray("RPRT 0\n"));
            break;
        }
        }
        // Well under way: at full speed on at least one axis. The simulated
        // clock is held there while Stop is pressed.
        QVERIFY2(f.holdClockWhen([&] { return std::abs(f.lastPosition().x() - start.x()) > 8.0; }),
                 qPrintable(QStringLiteral("still at %1").arg(f.lastPosition().x())));
        const QPointF pressed = f.lastPosition();
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("stopButton")), Qt::LeftButton);
        f.releaseClock();
        const WindowFixture::AfterStop after = f.watchAfterStop(pressed, restWithinMs);
        if (motion == Motion::Jog)
            QTest::mouseRelease(jogRight, Qt::LeftButton);
        qInfo("%s: %s", QTest::currentDataTag(), qPrintable(after.describe()));
        QVERIFY2(after.atRest(), qPrintable(after.describe()));
        QVERIFY2(after.travel() < maxTravel, qPrintable(after.describe()));
    }
};

QTEST_MAIN(StopBringsToRestTest)
#include "tst_stopbringstorest.moc"
