// SPDX-License-Identifier: GPL-3.0-or-later
// The remote window against a real broker and real station services: a
// Mosquitto of the test's own (TLS, accounts, access list) and `slew
// --headless --mqtt` processes on the built-in simulator. The window shows
// the station and says it is remote and how old its state is; a go-to, a
// jog and Stop move and stop the station's rotator; a move out of the
// travel is refused in the gate's words; a watcher's window is refused by
// the broker and nothing moves; a lost broker greys the window and it comes
// back by itself; the station network shows every station and opens one.
// Run offscreen and, as tst_remotewindow_x11, in a real X11 window, where
// the layout is checked at 1280x720 and the README's pictures are taken.

#include "../common/mosquittobroker.h"
#include "../common/stationprocess.h"
#include "layoutfaults.h"

#include "alarmbanner.h"
#include "operatortheme.h"
#include "rotor/polarplotwidget.h"
#include "remote/remotebanner.h"
#include "remote/remoteconnectdialog.h"
#include "remote/remotecontrols.h"
#include "remote/remoteopener.h"
#include "tracking/schedulepanel.h"
#include "tracking/scheduletimeline.h"
#include "stationwindow.h"
#include "rotor/gotopanel.h"
#include "rotor/jogpad.h"
#include "rotor/positionreadout.h"
#include "tracking/trackingline.h"
#include "remote/stationnetworkwindow.h"
#include "remote/stationtile.h"
#include "stopbutton.h"

#include "model/movegate.h"
#include "remote/remotestation.h"

#include <QApplication>
#include <QDir>
#include <QGuiApplication>
#include <QLabel>
#include <QPointer>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTabWidget>
#include <QTest>

#include <cmath>
#include <memory>

using slew::remote::RemoteStation;
using slew::ui::StationWindow;

namespace {

bool onX11()
{
    return QGuiApplication::platformName() == u"xcb";
}

} // namespace

class RemoteWindowTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        // File → Open remote station… keeps the address: in a scratch place.
        QStandardPaths::setTestModeEnabled(true);
        QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_settings.path());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settings.path());
        QCoreApplication::setOrganizationName(QStringLiteral("SlewTests"));
        slew::ui::applyOperatorTheme(*static_cast<QApplication *>(QCoreApplication::instance())); // as slew --remote draws it
        QString error;
        QVERIFY2(m_broker.start(&error), qPrintable(error));
        m_mast = std::make_unique<StationProcess>(station(QStringLiteral("mast"), QStringLiteral("sim:?start_az=200&start_el=20")));
        m_dish = std::make_unique<StationProcess>(station(QStringLiteral("dish2"), QStringLiteral("sim:?model=satnogs&start_az=90&start_el=60")));
        QVERIFY2(m_mast->logged("remote: connected to"), m_mast->said().constData());
        QVERIFY2(m_dish->logged("remote: connected to"), m_dish->said().constData());
    }

    void showsTheStationAndMovesIt()
    {
        StationWindow *window = open(QStringLiteral("operator"), QStringLiteral("mast"));
        QVERIFY(window);
        QPointer<StationWindow> guard(window);
        RemoteStation *remote = window->remoteStation();
        QTRY_VERIFY_WITH_TIMEOUT(remote->isLive(), 20000);
        // It says plainly that it is remote, which station, and how old.
        const QString banner = window->remoteBanner()->text();
        QVERIFY2(banner.startsWith(QStringLiteral("REMOTE: station mast on mqtts://operator@localhost:")), qPrintable(banner));
        QVERIFY2(banner.contains(QStringLiteral("s old")), qPrintable(banner));
        QVERIFY(window->windowTitle().contains(QStringLiteral("REMOTE")));
        // The local window's readout, on the station's face.
        QTRY_VERIFY(window->readout()->findChild<QLabel *>(QStringLiteral("readoutAzimuth"))->text().trimmed() == QStringLiteral("200.0°"));
        QVERIFY(window->polarPlot()->actual());
        QVERIFY(!window->polarPlot()->isStale());

        // Out of the travel: refused here in the station's gate's words, and
        // not sent.
        // The same go-to panel as the local window's, on the station's face.
        window->gotoPanel()->setFields(999, 30);
        QVERIFY(!window->gotoPanel()->findChild<QPushButton *>(QStringLiteral("gotoButton"))->isEnabled());
        QVERIFY(!window->gotoPanel()->go());
        const QString gate = slew::model::MoveGate(slew::model::RotatorLimits{0, 450, 0, 180}).pointing(999, 30, 200).refusal;
        QCOMPARE(gotoMessage(window), gate);

        // A go-to moves the station's rotator; its reply comes back.
        QSignalSpy replies(remote, &RemoteStation::replied);
        window->gotoPanel()->setFields(215, 25);
        QVERIFY(window->gotoPanel()->go());
        QTRY_VERIFY_WITH_TIMEOUT(!replies.isEmpty(), 10000);
        QCOMPARE(replies.first().at(2).toBool(), true);
        QTRY_VERIFY_WITH_TIMEOUT(remote->state()->position && std::abs(remote->state()->position->x() - 215) < 1
                                     && std::abs(remote->state()->position->y() - 25) < 1 && !remote->state()->moving,
                                 30000);

        // Stop, while it moves: it stops short.
        window->gotoPanel()->setFields(300, 45);
        QVERIFY(window->gotoPanel()->go());
        QTRY_VERIFY_WITH_TIMEOUT(remote->state()->moving, 10000);
        if (onX11()) // on its way, with the target shown: README's picture
            checkLayoutAndPicture(window, QStringLiteral("remote-window.png"));
        window->stopButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(!remote->state()->moving, 10000);
        QVERIFY2(remote->state()->position->x() < 290, qPrintable(QString::number(remote->state()->position->x())));

        // A jog turns while the button is held, and stops on release.
        auto *right = window->jogPad()->findChild<QPushButton *>(QStringLiteral("jogRight"));
        const double before = remote->state()->position->x();
        QTest::mousePress(right, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(remote->state()->moving && remote->state()->position->x() > before + 1, 10000);
        QTest::mouseRelease(right, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!remote->state()->moving, 10000);
        delete window;
    }

    void aWatcherMayOnlyWatch()
    {
        StationWindow *window = open(QStringLiteral("watcher"), QStringLiteral("mast"));
        QVERIFY(window);
        RemoteStation *remote = window->remoteStation();
        QTRY_VERIFY_WITH_TIMEOUT(remote->isLive(), 20000);
        const double az = remote->state()->position->x();
        window->gotoPanel()->setFields(az + 20, 30);
        QVERIFY(window->gotoPanel()->go());
        QTRY_VERIFY_WITH_TIMEOUT(gotoMessage(window).contains(QStringLiteral("this account may only watch")), 10000);
        QVERIFY2(gotoMessage(window).contains(QStringLiteral("Not authorized")), qPrintable(gotoMessage(window)));
        // Nothing moved: the station never heard it. Three samples later it
        // is where it was.
        QSignalSpy samples(remote, &RemoteStation::telemetryReceived);
        QTRY_VERIFY_WITH_TIMEOUT(samples.size() >= 3, 20000);
        for (const QList<QVariant> &sample : std::as_const(samples))
            QVERIFY(std::abs(*sample.at(0).value<slew::face::TelemetrySample>().az - az) < 0.2);
        QVERIFY(!remote->state()->moving);
        delete window;
    }

    void aLostBrokerGreysTheWindowUntilItIsBack()
    {
        StationWindow *window = open(QStringLiteral("operator"), QStringLiteral("mast"));
        QVERIFY(window);
        RemoteStation *remote = window->remoteStation();
        QTRY_VERIFY_WITH_TIMEOUT(remote->isLive(), 20000);
        m_broker.stop();
        QTRY_VERIFY_WITH_TIMEOUT(!remote->isLive(), 20000);
        QVERIFY2(window->remoteBanner()->text().contains(QStringLiteral("NOT LIVE")), qPrintable(window->remoteBanner()->text()));
        QVERIFY(!window->readout()->isEnabled());
        QVERIFY(window->polarPlot()->isStale());
        QVERIFY(window->alarmBanner()->isVisible() || !window->isVisible());
        QVERIFY(window->alarmBanner()->text().startsWith(QStringLiteral("Not live:")));
        QVERIFY(window->stopButton()->isEnabled()); // Stop is never greyed
        QString error;
        QVERIFY2(m_broker.start(&error, m_broker.port(), m_broker.plainPort()), qPrintable(error));
        // The window, and the stations, find it again by themselves.
        QTRY_VERIFY_WITH_TIMEOUT(remote->isLive(), 60000);
        QVERIFY(window->readout()->isEnabled());
        QVERIFY(!window->polarPlot()->isStale());
        delete window;
    }

    // A station that stops talking (its process stopped, its connection
    // still open: no last will) goes stale after 12 s. The banner counts the
    // state's age on; the alarm line, which is not refreshed, says the
    // threshold, so the two never give two different ages.
    void aSilentStationIsToldWithOneAge()
    {
        StationWindow *window = open(QStringLiteral("operator"), QStringLiteral("dish2"));
        QVERIFY(window);
        RemoteStation *remote = window->remoteStation();
        QTRY_VERIFY_WITH_TIMEOUT(remote->isLive(), 20000);
        ::kill(pid_t(m_dish->process.processId()), SIGSTOP);
        QTRY_VERIFY_WITH_TIMEOUT(!remote->isLive(), 20000);
        const QString alarm = window->alarmBanner()->text();
        QVERIFY2(alarm.startsWith(QStringLiteral("Not live: station dish2 has said nothing for over 12 s")), qPrintable(alarm));
        const QString banner = window->remoteBanner()->text();
        QVERIFY2(banner.contains(QStringLiteral("NOT LIVE: station dish2 has said nothing for over 12 s · last state 1")),
                 qPrintable(banner));
        // Two seconds on: the banner's age has moved, the alarm line has not
        // and needs not.
        QTRY_VERIFY_WITH_TIMEOUT(window->remoteBanner()->text() != banner, 5000);
        QCOMPARE(window->alarmBanner()->text(), alarm);
        ::kill(pid_t(m_dish->process.processId()), SIGCONT);
        QTRY_VERIFY_WITH_TIMEOUT(remote->isLive(), 20000);
        delete window;
    }

    void theNetworkShowsEveryStation()
    {
        QString error;
        const auto address = slew::remote::parseBrokerAddress(m_broker.url(QStringLiteral("watcher")), &error);
        QVERIFY2(address, qPrintable(error));
        QMainWindow *opened = slew::ui::openRemoteWindow(*address, MosquittoBroker::password(QStringLiteral("watcher")), &error);
        auto *network = qobject_cast<slew::ui::StationNetworkWindow *>(opened);
        QVERIFY2(network, qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(network->tileCount(), 2, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(network->tile(QStringLiteral("dish2"))->statusText().startsWith(QStringLiteral("az 90.0° el 60.0°")), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(network->tile(QStringLiteral("mast"))->plot()->actual().has_value(), 20000);
        QVERIFY(!network->tile(QStringLiteral("mast"))->plot()->isStale());
        if (onX11()) {
            network->resize(1280, 720);
            QDir().mkpath(QStringLiteral("screenshots"));
            QTRY_VERIFY(network->isVisible());
            QVERIFY(network->grab().save(QStringLiteral("screenshots/station-network.png")));
        }
        // Open: the station's own window, on a connection of its own.
        QWidget *station = network->openStation(QStringLiteral("dish2"));
        auto *window = qobject_cast<StationWindow *>(station);
        QVERIFY(window);
        QTRY_VERIFY_WITH_TIMEOUT(window->remoteStation()->isLive(), 20000);
        QCOMPARE(window->remoteStation()->name(), QStringLiteral("dish2"));
        delete window;
        delete network;
    }

    void showsTheScheduleAndThePlanOfAStation()
    {
        // A station that runs a schedule, FLOCK 2P-1 first and PERSEUS-M1
        // second, its clock a rehearsal from inside FLOCK 2P-1's pass over
        // JO65hq (AOS 09:15:45, LOS 09:27:10 UTC).
        StationProcess roof(station(QStringLiteral("roof"), QStringLiteral("sim:?start_az=0&start_el=0"))
                            + QStringList{"--qth", "JO65hq", "--tle",
                                          QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"), "--track",
                                          "FLOCK 2P-1", "--track", "PERSEUS-M1", "--clock-start", "2018-01-22T09:19:00Z"});
        QVERIFY2(roof.logged("remote: connected to"), roof.said().constData());
        StationWindow *window = open(QStringLiteral("watcher"), QStringLiteral("roof"));
        QVERIFY(window);
        RemoteStation *remote = window->remoteStation();
        QTRY_VERIFY_WITH_TIMEOUT(remote->isLive(), 20000);

        // The Schedule tab: the targets by priority, the time line, the pass
        // being followed.
        QTRY_VERIFY_WITH_TIMEOUT(remote->schedule() && remote->schedule()->current, 60000);
        auto *view = window->schedulePanel();
        QTRY_VERIFY2(view->stateText().contains(QStringLiteral("By priority: FLOCK 2P-1, PERSEUS-M1 (")),
                     qPrintable(view->stateText()));
        QVERIFY2(view->stateText().startsWith(QStringLiteral("Running: ")) && view->stateText().contains(QStringLiteral("Now: FLOCK 2P-1")),
                 qPrintable(view->stateText()));
        const auto &shown = view->timeline()->schedule();
        QCOMPARE(shown.passes.size(), remote->schedule()->schedule.passes.size());
        QVERIFY(!view->timeline()->barFor(shown.passes.at(*remote->schedule()->current)).isEmpty());

        // Beside STOP, what the station's tracking does, counted by its
        // rehearsal clock (by the wall clock this LOS was years ago).
        QTRY_VERIFY2_WITH_TIMEOUT(window->trackingLine()->text().startsWith(
                                      QStringLiteral("Tracking FLOCK 2P-1 until 09:27:10 UTC, 0:0")),
                                  qPrintable(window->trackingLine()->text()), 30000);
        {
            const QString line = window->trackingLine()->text();
            const QStringList left = line.section(QStringLiteral(", "), 1).section(u' ', 0, 0).split(u':');
            QCOMPARE(left.size(), 3);
            const int seconds = left[1].toInt() * 60 + left[2].toInt();
            QVERIFY2(seconds > 0 && seconds <= 8 * 60 + 10, qPrintable(line)); // LOS 09:27:10, clock from 09:19:00
            // The readout says the pass itself, not the phase again: as it
            // rose, though the schedule joined it at 09:19.
            const QString pass = window->findChild<QLabel *>(QStringLiteral("readoutPass"))->text();
            QCOMPARE(pass, QStringLiteral("Pass of FLOCK 2P-1 (NORAD 41617): 09:15:45–09:27:10 UTC, highest 56.4°"));
        }

        // The plan of the pass on the plot, as the local window draws it.
        QTRY_VERIFY_WITH_TIMEOUT(window->polarPlot()->passOverlay().has_value(), 30000);
        QVERIFY(window->polarPlot()->passOverlay()->sky.size() > 50);
        QVERIFY(window->polarPlot()->passOverlay()->planned.size() > 50);
        if (onX11()) {
            window->bringToFront(view);
            // On the track, for the picture: the antenna where the target is.
            QTRY_VERIFY_WITH_TIMEOUT(remote->state() && remote->state()->tracking == u"tracking" && remote->state()->position
                                         && remote->state()->target
                                         && std::abs(remote->state()->position->x() - remote->state()->target->x()) < 1
                                         && std::abs(remote->state()->position->y() - remote->state()->target->y()) < 1,
                                     60000);
            checkLayoutAndPicture(window, QStringLiteral("remote-schedule.png"));
        }
        delete window;
        QCOMPARE(roof.stop(SIGTERM), 0);
    }

    void theOpenDialogChecksTheAddress()
    {
        // File → Open remote station…: a bad address is said and opens nothing.
        slew::ui::RemoteConnectDialog dialog;
        dialog.addressField()->setText(QStringLiteral("mqtt://operator@192.0.2.1:1883/mast"));
        QVERIFY(!dialog.openRemote());
        QVERIFY2(dialog.problem().contains(QStringLiteral("in the clear")), qPrintable(dialog.problem()));
        dialog.addressField()->setText(QStringLiteral("mqtts://operator:secret@localhost/mast"));
        QVERIFY(!dialog.openRemote());
        QVERIFY2(dialog.problem().contains(QStringLiteral("no password in the address")), qPrintable(dialog.problem()));
        // A good one opens the station's window, and is kept; the password is not.
        dialog.addressField()->setText(m_broker.url(QStringLiteral("operator"), QStringLiteral("mast")));
        dialog.passwordField()->setText(MosquittoBroker::password(QStringLiteral("operator")));
        QVERIFY2(dialog.openRemote(), qPrintable(dialog.problem()));
        StationWindow *opened = nullptr;
        for (QWidget *w : QApplication::topLevelWidgets()) {
            if (auto *r = qobject_cast<StationWindow *>(w))
                opened = r;
        }
        QVERIFY(opened);
        QTRY_VERIFY_WITH_TIMEOUT(opened->remoteStation()->isLive(), 20000);
        QCOMPARE(QSettings().value(QLatin1String(slew::ui::RemoteConnectDialog::kAddressKey)).toString(),
                 m_broker.url(QStringLiteral("operator"), QStringLiteral("mast")));
        for (const QString &key : QSettings().allKeys())
            QVERIFY2(!QSettings().value(key).toString().contains(MosquittoBroker::password(QStringLiteral("operator"))),
                     qPrintable(key));
        delete opened;
    }

    void cleanupTestCase()
    {
        QCOMPARE(m_mast->stop(SIGTERM), 0);
        QCOMPARE(m_dish->stop(SIGTERM), 0);
    }

private:
    QStringList station(const QString &name, const QString &uri) const
    {
        return {QStringLiteral("--connect"), uri, QStringLiteral("--limits"), QStringLiteral("0:450,0:180"),
                QStringLiteral("--mqtt"), m_broker.url(QStringLiteral("station-") + name), QStringLiteral("--station-name"),
                name, QStringLiteral("--mqtt-password-file"), m_broker.passwordFile(QStringLiteral("station-") + name)};
    }

    static QString gotoMessage(StationWindow *window)
    {
        return window->gotoPanel()->findChild<QLabel *>(QStringLiteral("gotoMessage"))->text();
    }

    StationWindow *open(const QString &user, const QString &name)
    {
        QString error;
        const auto address = slew::remote::parseBrokerAddress(m_broker.url(user, name), &error);
        if (!address)
            return nullptr;
        QMainWindow *window = slew::ui::openRemoteWindow(*address, MosquittoBroker::password(user), &error);
        if (!window)
            qWarning("%s", qPrintable(error));
        return qobject_cast<StationWindow *>(window);
    }

    // The layout at 1280x720 as it is, and with the alarm banner up (a
    // station's alarm, or "Not live" when its state is late, as on a busy
    // machine): nothing squeezed either way.
    void checkLayoutAndPicture(StationWindow *window, const QString &file)
    {
        window->resize(1280, 720);
        QTRY_COMPARE(window->size(), QSize(1280, 720));
        auto faultsNow = [&] {
            QStringList faults = layoutFaults(window);
            if (!faults.isEmpty())
                faults << QStringLiteral("the window's least size: %1x%2")
                              .arg(window->minimumSizeHint().width())
                              .arg(window->minimumSizeHint().height());
            return faults;
        };
        QStringList faults = faultsNow();
        QVERIFY2(faults.isEmpty(), qPrintable(faults.join(u'\n')));
        QDir().mkpath(QStringLiteral("screenshots"));
        QVERIFY(window->grab().save(QStringLiteral("screenshots/") + file));
        const bool bannerWasUp = window->alarmBanner()->isVisible();
        window->alarmBanner()->showAlarms({QStringLiteral("Not live: no state from the station for 12 s")}, true);
        faults = faultsNow();
        QVERIFY2(faults.isEmpty(), qPrintable(QStringLiteral("with the alarm banner up:\n") + faults.join(u'\n')));
        if (!bannerWasUp)
            window->alarmBanner()->showAlarms({}, false);
    }

    QTemporaryDir m_settings;
    MosquittoBroker m_broker{{QStringLiteral("mast"), QStringLiteral("dish2"), QStringLiteral("roof")}};
    std::unique_ptr<StationProcess> m_mast, m_dish;
};

QTEST_MAIN(RemoteWindowTest)
#include "tst_remotewindow.moc"
