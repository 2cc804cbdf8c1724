// SPDX-License-Identifier: GPL-3.0-or-later
// LinkTimer keeps the time of a link whose clock is stepped, and the wall
// clock otherwise. The stepped link here is a unit-test fake: a clock and
// nothing else.

#include "session/linktimer.h"
#include "transport/link.h"

#include <QBuffer>
#include <QSignalSpy>
#include <QTest>

using slew::session::LinkTimer;

namespace {

class SteppedClockLink : public slew::transport::Link {
public:
    SteppedClockLink() : Link(QStringLiteral("test:")) {}
    QIODevice *device() override { return &m_buffer; }
    void open() override {}
    void close() override {}
    bool isOpen() const override { return true; }
    std::optional<double> clockSeconds() const override { return m_now; }
    bool clockIsStepped() const override { return true; }

    void step(double seconds)
    {
        m_now += seconds;
        emit clockStepped(m_now);
    }

private:
    QBuffer m_buffer;
    double m_now = 0.0;
};

} // namespace

class LinkTimerTest : public QObject {
    Q_OBJECT
private slots:
    void singleShotFiresWhenTheLinkClockPassesTheDeadline()
    {
        SteppedClockLink link;
        LinkTimer t;
        t.setSingleShot(true);
        t.followClockOf(&link);
        QSignalSpy fired(&t, &LinkTimer::timeout);
        t.start(500);
        link.step(0.499);
        // Every queued check runs; the link's clock is short of the deadline.
        QCoreApplication::processEvents();
        QCoreApplication::processEvents();
        QCOMPARE(fired.count(), 0);
        QVERIFY(t.isActive());
        link.step(0.001);
        QTRY_COMPARE(fired.count(), 1);
        QVERIFY(!t.isActive());
        link.step(10.0);
        QCoreApplication::processEvents();
        QCOMPARE(fired.count(), 1);
    }

    void repeatingFiresOncePerPeriodAndOncePerBigStep()
    {
        SteppedClockLink link;
        LinkTimer t;
        t.followClockOf(&link);
        t.setInterval(100);
        QSignalSpy fired(&t, &LinkTimer::timeout);
        t.start();
        for (int i = 0; i < 100; ++i) { // one simulated second in 10 ms steps
            link.step(0.01);
            QCoreApplication::processEvents();
        }
        QVERIFY2(fired.count() >= 9 && fired.count() <= 10, qPrintable(QString::number(fired.count())));
        fired.clear();
        link.step(5.0); // a step of fifty periods gives one timeout, not a burst
        QCoreApplication::processEvents();
        QCOMPARE(fired.count(), 1);
    }

    void stopAndRestartCountFromTheRestart()
    {
        SteppedClockLink link;
        LinkTimer t;
        t.setSingleShot(true);
        t.followClockOf(&link);
        QSignalSpy fired(&t, &LinkTimer::timeout);
        t.start(250);
        link.step(0.2);
        t.stop();
        link.step(0.2);
        QCoreApplication::processEvents();
        QCOMPARE(fired.count(), 0);
        t.start(250); // deadline 0.65
        link.step(0.2);
        QCoreApplication::processEvents();
        QCOMPARE(fired.count(), 0);
        link.step(0.05);
        QTRY_COMPARE(fired.count(), 1);
    }

    // What the same step released (a reply the device sent meanwhile) is
    // handled before the timer looks: a reply due at the deadline wins.
    void workQueuedByTheSameStepComesFirst()
    {
        SteppedClockLink link;
        LinkTimer t;
        t.setSingleShot(true);
        QObject::connect(&link, &slew::transport::Link::clockStepped, &link, [&] {
            QMetaObject::invokeMethod(&link, [&] { t.stop(); }, Qt::QueuedConnection);
        });
        t.followClockOf(&link);
        QSignalSpy fired(&t, &LinkTimer::timeout);
        t.start(100);
        link.step(0.1);
        QCoreApplication::processEvents(); // the reply's stop, then the timer's check
        QCoreApplication::processEvents();
        QCOMPARE(fired.count(), 0);
    }

    void withoutASteppedClockItIsAWallClockTimer()
    {
        LinkTimer t;
        t.setSingleShot(true);
        t.followClockOf(nullptr);
        QSignalSpy fired(&t, &LinkTimer::timeout);
        t.start(10);
        QVERIFY(fired.wait(5000));
        QCOMPARE(fired.count(), 1);
    }

    void aRunningTimerMovesToTheNewClock()
    {
        SteppedClockLink link;
        LinkTimer t;
        t.setSingleShot(true);
        t.start(60000); // on the wall clock: would take a minute
        t.followClockOf(&link);
        QVERIFY(t.isActive());
        QSignalSpy fired(&t, &LinkTimer::timeout);
        link.step(60.0);
        QTRY_COMPARE(fired.count(), 1);
    }
};

QTEST_GUILESS_MAIN(LinkTimerTest)
#include "tst_linktimer.moc"
