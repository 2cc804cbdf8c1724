// SPDX-License-Identifier: GPL-3.0-or-later
// What the operator reads: the position never shows "-0.0", and the event
// log keeps its time column in view however long a line is.

#include "eventlog.h"
#include "positionreadout.h"

#include "session/rotatorsession.h"

#include <QApplication>
#include <QDateTime>
#include <QLabel>
#include <QScrollBar>
#include <QTest>

using namespace slew;

class TestReadouts : public QObject {
    Q_OBJECT
private slots:
    void noNegativeZero()
    {
        QCOMPARE(ui::shownTenths(-0.04), 0.0);
        QVERIFY(!std::signbit(ui::shownTenths(-0.04)));
        QCOMPARE(ui::shownTenths(-0.05), -0.1);
        QCOMPARE(ui::shownTenths(12.34), 12.3);

        session::RotatorSession session;
        ui::PositionReadout readout(&session);
        emit session.positionChanged(-0.03, -0.04, false);
        const auto *az = readout.findChild<QLabel *>(QStringLiteral("readoutAzimuth"));
        const auto *el = readout.findChild<QLabel *>(QStringLiteral("readoutElevation"));
        QVERIFY(az && el);
        QVERIFY2(!az->text().contains(u'-') && !el->text().contains(u'-'), qPrintable(az->text() + el->text()));
        QCOMPARE(el->text().trimmed(), QStringLiteral("0.0°"));
    }

    void eventLogKeepsTheTimesInView()
    {
        // As in the window: lines arrive while the Events tab is hidden,
        // and it is opened later.
        ui::EventLog log;
        for (int i = 0; i < 20; ++i)
            log.addEvent(QDateTime::currentDateTime(), ui::AlarmMonitor::Severity::Warning,
                         QStringLiteral("a long line from a controller ") + QString(300, u'x'));
        log.resize(400, 200);
        log.show();
        QVERIFY(QTest::qWaitForWindowExposed(&log));
        QVERIFY(log.horizontalScrollBar()->maximum() > 0); // there is somewhere to scroll to
        QCOMPARE(log.horizontalScrollBar()->value(), 0);
        // And while it is shown.
        log.addEvent(QDateTime::currentDateTime(), ui::AlarmMonitor::Severity::Info, QString(500, u'y'));
        QCOMPARE(log.horizontalScrollBar()->value(), 0);
    }
};

QTEST_MAIN(TestReadouts)
#include "tst_readouts.moc"
