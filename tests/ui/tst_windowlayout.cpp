// SPDX-License-Identifier: GPL-3.0-or-later
// The operator window on a real X11 server at the size it opens with and at
// 1280x720, the smallest screen an operator brings to a mast: no widget on
// top of another, no text cut, on every tab; and nothing that happens while
// it runs (a long status, the operator's hold, an alarm, a click on the plot)
// makes the window grow past the screen or moves the plot under the pointer.

#include "layoutfaults.h"
#include "windowfixture.h"

#include "alarmbanner.h"
#include "bridge/rotctldserver.h"
#include "linkschemes.h"
#include "operatortheme.h"
#include "rotor/polarplotwidget.h"
#include "tracking/schedulepanel.h"
#include "widgets/scrollablepage.h"
#include "tracking/targetpicker.h"
#include "tracking/trackingpanel.h"
#include "tracking/upcomingpanel.h"
#include "rotor/targetconfirmation.h"
#include "telemetry/telemetryrecorder.h"
#include "windowstate.h"

#include <QApplication>
#include <QDir>
#include <QGuiApplication>
#include <QHostAddress>
#include <QLabel>
#include <QScreen>
#include <QScrollBar>
#include <QSettings>
#include <QStatusBar>
#include <QSplitter>
#include <QTabBar>
#include <QTabWidget>
#include <QToolButton>
#include <QTest>

using slew::ui::StationWindow;

namespace {

// Lets the layout settle after a change: posted layout requests run from
// the event loop.
void settle()
{
    for (int i = 0; i < 3; ++i)
        QCoreApplication::processEvents();
}

// Every page checked, and its picture kept for the eye in
// screenshots/WxH/ (the pictures in docs/screenshots come from here).
QString faultsOnEveryTab(StationWindow &window)
{
    QStringList all;
    QTabWidget *tabs = window.tabs();
    const QString folder = QStringLiteral("screenshots/%1x%2/").arg(window.width()).arg(window.height());
    QDir().mkpath(folder);
    const auto picture = [&](const QString &name) {
        window.grab().save(folder + name.toLower().replace(u' ', u'-') + QStringLiteral(".png"));
        // From 1280x720 up, a page has the room it needs: no scroll bar.
        if (window.width() < 1280 || window.height() < 720)
            return;
        for (const auto *page : window.findChildren<slew::ui::ScrollablePage *>())
            if (page->isVisible() && (page->horizontalScrollBar()->isVisible() || page->verticalScrollBar()->isVisible()))
                all << QStringLiteral("[%1] %2 scrolls at %3x%4 (page %5x%6, least %7x%8, room %9x%10)")
                           .arg(name, page->objectName())
                           .arg(window.width())
                           .arg(window.height())
                           .arg(page->widget()->width())
                           .arg(page->widget()->height())
                           .arg(page->widget()->minimumSizeHint().width())
                           .arg(page->widget()->minimumSizeHint().height())
                           .arg(page->viewport()->width())
                           .arg(page->viewport()->height());
    };
    for (int i = 0; i < tabs->count(); ++i) {
        tabs->setCurrentIndex(i);
        settle();
        for (const QString &fault : layoutFaults(&window))
            all << QStringLiteral("[%1] %2").arg(tabs->tabText(i), fault);
        // (The Tracking tab's page is itself a tab widget.)
        QList<QTabWidget *> innerTabs = tabs->widget(i)->findChildren<QTabWidget *>();
        if (auto *own = qobject_cast<QTabWidget *>(tabs->widget(i)))
            innerTabs.prepend(own);
        if (innerTabs.isEmpty())
            picture(tabs->tabText(i));
        // And every page of a tab that has pages of its own (Tracking).
        for (QTabWidget *inner : innerTabs) {
            for (int j = 0; j < inner->count(); ++j) {
                inner->setCurrentIndex(j);
                settle();
                for (const QString &fault : layoutFaults(&window))
                    all << QStringLiteral("[%1 / %2] %3").arg(tabs->tabText(i), inner->tabText(j), fault);
                picture(tabs->tabText(i) + u'-' + inner->tabText(j));
            }
            inner->setCurrentIndex(0);
        }
    }
    all.removeDuplicates();
    return all.join(QLatin1Char('\n'));
}

} // namespace

class WindowLayoutTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QCOMPARE(QGuiApplication::platformName(), QStringLiteral("xcb"));
        WindowFixture::prepareApplication();
        slew::registerLinkSchemes();
        slew::ui::applyOperatorTheme(*qobject_cast<QApplication *>(QCoreApplication::instance()));
    }

    void opensAtASizeTheScreenHolds()
    {
        // The screen here is 1920x1200: the window takes its own default.
        WindowFixture f;
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        QCOMPARE(f.window->size(), QSize(1440, 900));
        // On a smaller screen it takes what the screen has, never more.
        QCOMPARE(slew::ui::WindowState::openingSize(QSize(1280, 690)), QSize(1280, 690));
        QCOMPARE(slew::ui::WindowState::openingSize(QSize(1366, 740)), QSize(1366, 740));
        QCOMPARE(slew::ui::WindowState::openingSize(QSize(2560, 1400)), QSize(1440, 900));
        // A place kept on a bigger or a second screen comes back wholly on
        // this one: moved in, and no bigger than its room.
        using slew::ui::WindowState;
        const QRect field(0, 0, 1024, 600);
        QCOMPARE(WindowState::onScreen(QRect(600, 300, 800, 500), field), QRect(224, 100, 800, 500));
        QCOMPARE(WindowState::onScreen(QRect(-300, -40, 800, 500), field), QRect(0, 0, 800, 500));
        QCOMPARE(WindowState::onScreen(QRect(2000, 100, 1440, 900), field), QRect(0, 0, 1024, 600));
        QCOMPARE(WindowState::onScreen(QRect(100, 50, 640, 480), field), QRect(100, 50, 640, 480)); // in already
        QCOMPARE(WindowState::onScreen(QRect(1950, 40, 800, 500), QRect(1920, 0, 1280, 1024)), QRect(1950, 40, 800, 500));
    }

    void everyTabFits_data()
    {
        QTest::addColumn<QSize>("size");
        QTest::newRow("default 1440x900") << QSize(1440, 900);
        QTest::newRow("1280x720") << QSize(1280, 720);
        // A field screen: each page scrolls where it must, nothing squeezed.
        QTest::newRow("1024x600") << QSize(1024, 600);
    }

    void everyTabFits()
    {
        QFETCH(QSize, size);
        WindowFixture f;
        f.window->resize(size);
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        QVERIFY(f.connectAndWait());
        // The pages filled as on a station's first evening: element sets, a
        // rehearsal over JO65hq before FLOCK 2P-1's pass, a target chosen
        // and starred, a schedule of two.
        QVERIFY(f.loadElementSets(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle")));
        QVERIFY(f.rehearseAt(QStringLiteral("2018-01-22T07:40:00Z"), 1.0));
        slew::ui::TrackingPanel *tracking = f.window->trackingPanel();
        QVERIFY(tracking->selectTarget(QStringLiteral("FLOCK 2P-1")));
        QTest::mouseClick(tracking->targetPicker()->favouriteButton(), Qt::LeftButton);
        QVERIFY(f.window->schedulePanel()->addTarget(QStringLiteral("FLOCK 2P-1")));
        QVERIFY(f.window->schedulePanel()->addTarget(QStringLiteral("AO-91")));
        QVERIFY(QTest::qWaitFor([&] { return !tracking->isPlanning() && !f.window->upcomingPanel()->isPlanning()
                                             && f.window->schedulePanel()->isPreviewing(); },
                                10000));
        settle();
        QCOMPARE(f.window->size(), size);
        const QString faults = faultsOnEveryTab(*f.window);
        QSettings().remove(QStringLiteral("tracking/favourites"));
        QSettings().remove(QStringLiteral("schedule"));
        QVERIFY2(faults.isEmpty(), qPrintable(faults));
        QCOMPARE(f.window->size(), size);
    }

    void longTextsNeverWidenTheWindow()
    {
        const QSize size(1280, 720);
        WindowFixture f;
        f.window->resize(size);
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        QVERIFY(f.connectAndWait());

        // The operator's hold on the Trackers tab.
        QString error;
        QVERIFY2(f.window->rotctldServer()->listen(QHostAddress::LocalHost, 0, &error), qPrintable(error));
        f.window->bringToFront(reinterpret_cast<QWidget *>(f.window->rotctldPanel()));
        f.window->rotctldServer()->holdRemote();
        settle();
        QCOMPARE(f.window->size(), size);

        // An alarm with a long text.
        f.window->alarmBanner()->showAlarms(
            {QStringLiteral("Azimuth motor current over its limit for 3 s: the controller stopped the drive "
                            "and holds it until it is reset from its front panel or with RESET")},
            true);
        settle();
        QCOMPARE(f.window->size(), size);

        // Tracking: the pointing error's chart appears under the others, and
        // the radio's Doppler error under it.
        f.window->findChild<slew::ui::TelemetryRecorder *>()->recordPointingError(0.25);
        f.window->findChild<slew::ui::TelemetryRecorder *>()->recordDopplerError(1.5, -0.5);
        f.window->tabs()->setCurrentIndex(0);
        settle();
        QCOMPARE(f.window->size(), size);

        // A refusal under the plot, as long as the gate writes them.
        f.window->targetConfirmation()->showProblem(
            QStringLiteral("elevation 95.0° is outside the rotator's travel (0.0° to 90.0°) and its end stops"));
        settle();
        QCOMPARE(f.window->size(), size);
        const QString faults = layoutFaults(f.window.get()).join(QLatin1Char('\n'));
        QVERIFY2(faults.isEmpty(), qPrintable(faults));
    }

    void clickingThePlotMovesNothing()
    {
        WindowFixture f;
        f.window->resize(1280, 720);
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        QVERIFY(f.connectAndWait());
        settle();
        slew::ui::PolarPlotWidget *plot = f.window->polarPlot();
        const QRect before = plot->geometry();
        auto *question = f.find<QLabel>(QStringLiteral("targetQuestion"));
        QVERIFY(question);
        const QString idle = question->text();
        QTest::mouseClick(plot, Qt::LeftButton, {}, plot->rect().center() + QPoint(plot->width() / 5, 0));
        settle();
        QVERIFY(question->text() != idle); // the question is asked
        QCOMPARE(plot->geometry(), before);
        f.window->targetConfirmation()->cancel();
        settle();
        QCOMPARE(plot->geometry(), before);
    }

    void theWindowComesBackAsItWasLeft()
    {
        QList<int> leftSizes;
        {
            WindowFixture f;
            f.window->resize(1280, 720);
            QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
            settle();
            // The operator drags the splitter between the plot and the
            // controls 60 pixels to the left, and brings the Events tab forward.
            auto *splitter = f.find<QSplitter>(QStringLiteral("mainSplitter"));
            QVERIFY(splitter);
            const QList<int> before = splitter->sizes();
            QSplitterHandle *handle = splitter->handle(1);
            const QPoint grip = handle->rect().center();
            QTest::mousePress(handle, Qt::LeftButton, {}, grip);
            QTest::mouseMove(handle, grip - QPoint(60, 0));
            QTest::mouseRelease(handle, Qt::LeftButton, {}, grip - QPoint(60, 0));
            settle();
            leftSizes = splitter->sizes();
            QCOMPARE(leftSizes[0], before[0] - 60);
            QTabBar *bar = f.window->tabs()->tabBar();
            const int events = f.window->tabs()->count() - 1;
            QCOMPARE(f.window->tabs()->tabText(events), QStringLiteral("Events"));
            QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(events).center());
            QCOMPARE(f.window->tabs()->currentIndex(), events);
        }
        // The next start.
        WindowFixture again;
        QVERIFY(QTest::qWaitForWindowExposed(again.window.get()));
        settle();
        QCOMPARE(again.window->size(), QSize(1280, 720));
        QCOMPARE(again.find<QSplitter>(QStringLiteral("mainSplitter"))->sizes(), leftSizes);
        QCOMPARE(again.window->tabs()->tabText(again.window->tabs()->currentIndex()), QStringLiteral("Events"));
    }
};

QTEST_MAIN(WindowLayoutTest)
#include "tst_windowlayout.moc"
