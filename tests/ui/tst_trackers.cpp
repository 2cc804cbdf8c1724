// SPDX-License-Identifier: GPL-3.0-or-later
// The Trackers tab: the rotctld server started from the window, a tracker
// steering through it, the operator's Stop holding remote moves off until
// control is handed back; and the setup wizard opened from the menu.

#include "bridge/rotctldserver.h"
#include "eventlog.h"
#include "rotor/rotctldpanel.h"
#include "windowfixture.h"
#include "wizard/setupwizard.h"

#include <QAction>
#include <QCheckBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTcpSocket>
#include <QComboBox>
#include <QLineEdit>
#include <QSpinBox>
#include <QTest>
#include <QTreeWidget>

class TrackersTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }
    void trackerSteersUntilTheOperatorStops();
    void badAddressKeepsTheServerOff();
    void wizardOpensFromTheMenu();
    void serverSettingsSurviveARestart();
    void telemetryWindowSurvivesARestart();

private:
    static QByteArray ask(QTcpSocket &s, const QByteArray &line)
    {
        QSignalSpy ready(&s, &QTcpSocket::readyRead);
        s.write(line + '\n');
        // Generous: the answer is local and comes at once on a quiet machine,
        // but this waits for the event, not the time.
        return ready.wait(30000) ? s.readAll() : QByteArray();
    }
};

void TrackersTest::trackerSteersUntilTheOperatorStops()
{
    WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
    QVERIFY(f.connectAndWait());
    auto *panel = f.window->rotctldPanel();
    QVERIFY(panel->startListening(QStringLiteral("127.0.0.1"), 0));
    QVERIFY(f.find<QCheckBox>(QStringLiteral("rotctldEnabled"))->isChecked());
    QVERIFY(f.find<QLabel>(QStringLiteral("rotctldState"))->text().contains(QStringLiteral("Listening on 127.0.0.1")));

    QTcpSocket tracker;
    tracker.connectToHost(QHostAddress::LocalHost, f.window->rotctldServer()->port());
    TRY_COMPARE(tracker.state(), QAbstractSocket::ConnectedState);
    QCOMPARE(ask(tracker, "P 70 20"), QByteArray("RPRT 0\n"));
    QVERIFY(f.waitUntilAt(70, 20));
    // The panel lists the client and its last command.
    auto *clients = f.find<QTreeWidget>(QStringLiteral("rotctldClients"));
    TRY_COMPARE(clients->topLevelItemCount(), 1);
    TRY_COMPARE(clients->topLevelItem(0)->text(1), QStringLiteral("P 70 20"));

    // The operator's Stop: remote moves are refused until handed back.
    QTest::mouseClick(f.find<QPushButton>(QStringLiteral("stopButton")), Qt::LeftButton);
    QVERIFY(f.window->rotctldServer()->isRemoteHeld());
    QCOMPARE(ask(tracker, "P 100 30"), QByteArray("RPRT -9\n"));
    auto *handBack = f.find<QPushButton>(QStringLiteral("rotctldHandBack"));
    QVERIFY(handBack->isEnabled());
    QTest::mouseClick(handBack, Qt::LeftButton);
    QVERIFY(!f.window->rotctldServer()->isRemoteHeld());
    QCOMPARE(ask(tracker, "P 100 30"), QByteArray("RPRT 0\n"));
    QVERIFY(f.waitUntilAt(100, 30));
    // Each stop in Events with what asked: the button, then the tracker's S.
    QCOMPARE(ask(tracker, "S"), QByteArray("RPRT 0\n"));
    const QString events = f.window->eventLog()->toPlainText();
    QVERIFY2(events.contains(QStringLiteral("Stop (the STOP button) at az ")), qPrintable(events));
    QVERIFY2(events.contains(QStringLiteral("Stop (rotctld client 127.0.0.1:%1: S) at az ").arg(tracker.localPort())),
             qPrintable(events));
}

void TrackersTest::badAddressKeepsTheServerOff()
{
    WindowFixture f;
    QVERIFY(!f.window->rotctldPanel()->startListening(QStringLiteral("not-an-address"), 4533));
    QVERIFY(!f.window->rotctldServer()->isListening());
    QVERIFY(!f.find<QCheckBox>(QStringLiteral("rotctldEnabled"))->isChecked());
    QVERIFY(f.find<QLabel>(QStringLiteral("rotctldState"))->text().contains(QStringLiteral("not an address")));
}

void TrackersTest::wizardOpensFromTheMenu()
{
    WindowFixture f;
    QVERIFY(f.connectAndWait());
    auto *action = f.find<QAction>(QStringLiteral("actionSetupWizard"));
    QVERIFY(action);
    action->trigger();
    auto *wizard = f.find<slew::ui::SetupWizard>(QStringLiteral("setupWizard"));
    QVERIFY(wizard);
    QTRY_VERIFY(wizard->isVisible());
    QCOMPARE(wizard->session(), &f.session);
    wizard->reject(); // cancelling stops the rotator and closes
    QTRY_VERIFY(!f.find<slew::ui::SetupWizard>(QStringLiteral("setupWizard")));
}

void TrackersTest::serverSettingsSurviveARestart()
{
    {
        WindowFixture f;
        QVERIFY(!f.window->rotctldServer()->isListening());
        f.find<QSpinBox>(QStringLiteral("rotctldPort"))->setValue(0); // any free port
        f.find<QLineEdit>(QStringLiteral("rotctldAllowed"))->setText(QStringLiteral("127.0.0.1"));
        auto *enabled = f.find<QCheckBox>(QStringLiteral("rotctldEnabled"));
        enabled->show();
        QTest::mouseClick(enabled, Qt::LeftButton, {}, QPoint(5, enabled->height() / 2)); // the operator ticks it
        QVERIFY(f.window->rotctldServer()->isListening());
    }
    {
        // The next start: on again, as the operator left it.
        WindowFixture f;
        QVERIFY(f.find<QCheckBox>(QStringLiteral("rotctldEnabled"))->isChecked());
        QVERIFY(f.window->rotctldServer()->isListening());
        QCOMPARE(f.find<QLineEdit>(QStringLiteral("rotctldAllowed"))->text(), QStringLiteral("127.0.0.1"));
        auto *enabled = f.find<QCheckBox>(QStringLiteral("rotctldEnabled"));
        enabled->show();
        QTest::mouseClick(enabled, Qt::LeftButton, {}, QPoint(5, enabled->height() / 2)); // and off
        QVERIFY(!f.window->rotctldServer()->isListening());
    }
    {
        WindowFixture f;
        QVERIFY(!f.window->rotctldServer()->isListening());
        // Started from the command line: for that run only.
        QVERIFY(f.window->rotctldPanel()->startListening(QStringLiteral("127.0.0.1"), 0));
    }
    WindowFixture after;
    QVERIFY(!after.window->rotctldServer()->isListening());
}

void TrackersTest::telemetryWindowSurvivesARestart()
{
    {
        WindowFixture f;
        f.window->show();
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        auto *window = f.find<QComboBox>(QStringLiteral("chartWindow"));
        QCOMPARE(window->currentIndex(), 0);
        window->setFocus();
        // The operator picks the longest (arrow keys jog the rotator here).
        QTest::keyClick(window, Qt::Key_End);
        QCOMPARE(window->currentIndex(), window->count() - 1);
    }
    WindowFixture f;
    auto *window = f.find<QComboBox>(QStringLiteral("chartWindow"));
    QCOMPARE(window->currentIndex(), window->count() - 1);
}

QTEST_MAIN(TrackersTest)
#include "tst_trackers.moc"
