// SPDX-License-Identifier: GPL-3.0-or-later
// What the operator reads: the position never shows "-0.0", the event log
// keeps its time column in view however long a line is, and check boxes and
// radio buttons can be seen on the dark theme.

#include "../common/fakestationface.h"
#include "eventlog.h"
#include "operatortheme.h"
#include "rotor/positionreadout.h"

#include "session/rotatorsession.h"
#include "sky/utctime.h"
#include "tracking/stationclock.h"

#include <QApplication>
#include <QCheckBox>
#include <QRadioButton>
#include <QStyle>
#include <QDateTime>
#include <QLabel>
#include <QScrollBar>
#include <QTest>

using namespace slew;

class TestReadouts : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { ui::applyOperatorTheme(*static_cast<QApplication *>(QCoreApplication::instance())); }

    void indicatorsStandOutFromTheWindow()
    {
        // An unticked box and an unchosen radio button: some pixels of the
        // indicator must differ clearly from the window behind them.
        QCheckBox check(QStringLiteral("Ask before moving"));
        QRadioButton radio(QStringLiteral("Both axes"));
        const QColor window = QApplication::palette().color(QPalette::Window);
        for (QAbstractButton *button : {static_cast<QAbstractButton *>(&check), static_cast<QAbstractButton *>(&radio)}) {
            button->resize(button->sizeHint());
            const QImage image = button->grab().toImage();
            // The indicator alone, not the text beside it.
            const int indicatorWidth = button->style()->pixelMetric(
                button == &check ? QStyle::PM_IndicatorWidth : QStyle::PM_ExclusiveIndicatorWidth, nullptr, button);
            int contrasting = 0;
            for (int y = 0; y < image.height(); ++y) {
                for (int x = 0; x < std::min(image.width(), indicatorWidth); ++x) {
                    const QColor c = image.pixelColor(x, y);
                    if (std::abs(c.lightness() - window.lightness()) > 60)
                        ++contrasting;
                }
            }
            QVERIFY2(contrasting >= 20, qPrintable(QStringLiteral("%1: %2 pixels stand out")
                                                       .arg(button->text()).arg(contrasting)));
        }
    }

    void noNegativeZero()
    {
        QCOMPARE(ui::shownTenths(-0.04), 0.0);
        QVERIFY(!std::signbit(ui::shownTenths(-0.04)));
        QCOMPARE(ui::shownTenths(-0.05), -0.1);
        QCOMPARE(ui::shownTenths(12.34), 12.3);

        FakeStationFace station;
        ui::PositionReadout readout(&station);
        face::StationState state;
        state.link = QStringLiteral("connected");
        state.position = QPointF(-0.03, -0.04);
        state.stale = false;
        station.setState(state);
        const auto *az = readout.findChild<QLabel *>(QStringLiteral("readoutAzimuth"));
        const auto *el = readout.findChild<QLabel *>(QStringLiteral("readoutElevation"));
        QVERIFY(az && el);
        QVERIFY2(!az->text().contains(u'-') && !el->text().contains(u'-'), qPrintable(az->text() + el->text()));
        QCOMPARE(el->text().trimmed(), QStringLiteral("0.0°"));
    }

    void eventLogKeepsEveryLineInView()
    {
        // As in the window: lines arrive while the Events tab is hidden,
        // and it is opened later. Long lines wrap, a long word in them too:
        // nothing to scroll sideways to, the times in view.
        ui::EventLog log;
        for (int i = 0; i < 20; ++i)
            log.addEvent(QDateTime::currentDateTime(), station::AlarmMonitor::Severity::Warning,
                         QStringLiteral("a long line from a controller ") + QString(300, u'x'));
        log.resize(400, 200);
        log.show();
        QVERIFY(QTest::qWaitForWindowExposed(&log));
        QCOMPARE(log.horizontalScrollBar()->maximum(), 0);
        QVERIFY(log.verticalScrollBar()->maximum() > 0); // the lines are taller instead
        // And while it is shown.
        log.addEvent(QDateTime::currentDateTime(), station::AlarmMonitor::Severity::Info, QString(500, u'y'));
        QCOMPARE(log.horizontalScrollBar()->maximum(), 0);
    }

    void eventLogStampsARehearsalWithItsTime()
    {
        // On the station's clock: the computer's time, or during a
        // rehearsal the rehearsal's, marked.
        ui::EventLog log;
        tracking::StationClock clock;
        log.setClock(&clock);
        log.addEvent(station::AlarmMonitor::Severity::Info, QStringLiteral("connected"));
        QVERIFY2(log.toPlainText().startsWith(QDate::currentDate().toString(QStringLiteral("yyyy-MM-dd"))),
                 qPrintable(log.toPlainText()));
        const double start = *sky::julianFromIso(QStringLiteral("2018-01-22T09:19:00Z"));
        clock.rehearse(start, 1.0);
        log.addEvent(station::AlarmMonitor::Severity::Info, QStringLiteral("AOS"));
        const QString last = log.toPlainText().split(u'\n').last();
        const QString stamp = sky::utcFromJulian(start).toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"));
        QVERIFY2(last.startsWith(stamp) && last.endsWith(QStringLiteral("info [rehearsal] AOS")), qPrintable(last));
    }
};

QTEST_MAIN(TestReadouts)
#include "tst_readouts.moc"
