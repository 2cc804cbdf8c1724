// SPDX-License-Identifier: GPL-3.0-or-later
// Stop means stop, end to end: Slew's session drives a real slew-sim process
// at full slew speed over TCP or its pseudo-terminal, presses Stop, and the
// antenna must come to rest close to where it was.
//
// - Self-locking drive (the default G-5500 class): two positions read a
//   second apart, the first a second after Stop, differ by under 0.05°, and
//   the antenna rests within 2° of where Stop was pressed.
// - Free-running drive, Easycomm III: Slew's zero-speed hold brakes it, so it
//   is at rest within 2 s of Stop.
//
// slew-sim runs on the wall clock, so the test waits for positions that
// arrive after a given time (a predicate on the event loop), never sleeps.

#include "../sim/slewsimprocess.h"
#include "linkschemes.h"
#include "session/rotatorsession.h"

#include <QElapsedTimer>
#include <QPointF>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace slew;
using session::RotatorSession;

namespace {

// The latest fresh position and when it came.
struct PositionWatch {
    QPointF last;
    qint64 atMs = -1;
    QElapsedTimer clock;

    explicit PositionWatch(RotatorSession &s)
    {
        clock.start();
        QObject::connect(&s, &RotatorSession::positionChanged, &s, [this](double az, double el, bool stale) {
            if (stale)
                return;
            last = QPointF(az, el);
            atMs = clock.elapsed();
        });
    }

    // The first fresh position that arrives at or after time ms.
    std::optional<QPointF> readAtOrAfter(qint64 ms, int timeoutMs = 10000)
    {
        if (!QTest::qWaitFor([&] { return atMs >= ms; }, int(ms - clock.elapsed()) + timeoutMs))
            return std::nullopt;
        return last;
    }
};

QString describe(const QPointF &p)
{
    return QStringLiteral("%1/%2").arg(p.x(), 0, 'f', 2).arg(p.y(), 0, 'f', 2);
}

} // namespace

class StopFromFullSpeedTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { registerLinkSchemes(); }

    void stopHoldsWithinTwoDegrees_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::addColumn<bool>("overPty");
        QTest::addColumn<QString>("drive");
        QTest::addColumn<int>("restWithinMs");
        QTest::addColumn<double>("maxTravel");
        for (const char *d : {"easycomm3", "easycomm2"}) {
            QTest::addRow("%s tcp", d) << QString::fromLatin1(d) << false << QStringLiteral("worm") << 1000 << 2.0;
            QTest::addRow("%s pty", d) << QString::fromLatin1(d) << true << QStringLiteral("worm") << 1000 << 2.0;
        }
        QTest::addRow("gs232b tcp") << QStringLiteral("gs232b") << false << QStringLiteral("worm") << 1000 << 2.0;
        // A free drive coasts on SA / SE; the hold that follows brakes it.
        // How far it runs depends on the driver's braking ramp, not on Slew.
        QTest::addRow("easycomm3 tcp free drive") << QStringLiteral("easycomm3") << false << QStringLiteral("free")
                                                  << 2000 << 30.0;
        QTest::addRow("easycomm3 pty free drive") << QStringLiteral("easycomm3") << true << QStringLiteral("free")
                                                  << 2000 << 30.0;
    }

    void stopHoldsWithinTwoDegrees()
    {
        QFETCH(QString, dialect);
        QFETCH(bool, overPty);
        QFETCH(QString, drive);
        QFETCH(int, restWithinMs);
        QFETCH(double, maxTravel);

        QTemporaryDir dir;
        const QString pty = dir.filePath(QStringLiteral("ttyStop"));
        QStringList args{"--dialect", dialect, "--drive", drive};
        args += overPty ? QStringList{"--pty", pty, "--baud", "19200"} : QStringList{"--listen", "127.0.0.1:0"};
        SlewSimProcess sim;
        QVERIFY2(sim.start(args), qPrintable(sim.error()));

        RotatorSession s;
        model::RotatorProfile profile;
        profile.dialect = *protocol::dialectFromName(dialect);
        profile.uri = overPty ? QStringLiteral("serial:%1?baud=19200").arg(pty)
                              : QStringLiteral("tcp://127.0.0.1:%1").arg(sim.port());
        s.setProfile(profile);
        PositionWatch watch(s);
        s.connectTo(profile.uri);
        QVERIFY(QTest::qWaitFor([&] { return s.isConnected() && s.hasPosition(); }, 15000));

        // Both axes well into a long slew, at the speed cap.
        QVERIFY(s.gotoPosition(300, 80));
        QVERIFY2(QTest::qWaitFor([&] { return watch.last.x() > 15.0 && watch.last.y() > 6.0; }, 15000),
                 qPrintable(describe(watch.last)));
        const QPointF pressed = watch.last;
        QVERIFY(s.stop());
        const qint64 stoppedAt = watch.clock.elapsed();

        const auto first = watch.readAtOrAfter(stoppedAt + restWithinMs);
        QVERIFY(first);
        const auto second = watch.readAtOrAfter(watch.atMs + 1000);
        QVERIFY(second);
        const QString trace = QStringLiteral("pressed at %1, then %2, then %3")
                                  .arg(describe(pressed), describe(*first), describe(*second));
        qInfo("%s: %s", QTest::currentDataTag(), qPrintable(trace));
        // At rest: a second apart, the same place (GS-232 reports whole degrees).
        QVERIFY2(std::abs(second->x() - first->x()) < 0.05 && std::abs(second->y() - first->y()) < 0.05,
                 qPrintable(trace));
        // And near where Stop was pressed.
        QVERIFY2(std::abs(first->x() - pressed.x()) < maxTravel && std::abs(first->y() - pressed.y()) < maxTravel,
                 qPrintable(trace));
        QCOMPARE(sim.stop(), 0);
    }
};

QTEST_GUILESS_MAIN(StopFromFullSpeedTest)
#include "tst_stopfromfullspeed.moc"
