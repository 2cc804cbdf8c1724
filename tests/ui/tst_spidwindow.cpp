// SPDX-License-Identifier: GPL-3.0-or-later
// The operator window on a SPID controller (the in-process simulator on its
// manual clock): it offers what the dialect has (go-to, stop, jog at the
// controller's own speed, park by go-to) and greys out, with a reason, what
// it lacks (a jog speed, homing, registers, raw text lines).

#include "windowfixture.h"

#include "telemetry/telemetrycharts.h"

#include <QDir>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTabWidget>
#include <QTest>

#include <algorithm>
#include <cmath>

namespace {

QString simFor(const char *dialect, const char *more = "")
{
    return QStringLiteral("sim:?dialect=%1&clock=manual%2").arg(QLatin1String(dialect), QLatin1String(more));
}

void typeInto(QLineEdit *field, const QString &text)
{
    field->setFocus();
    field->selectAll();
    QTest::keyClick(field, Qt::Key_Backspace);
    QTest::keyClicks(field, text);
}

// Holds a jog button until the azimuth has gone past `degrees`, lets go, and
// checks the rotator comes to rest and stays there.
void jogAndRelease(WindowFixture &f, const QString &button, double degrees)
{
    const double start = f.session.azimuth();
    const double sign = button == QLatin1String("jogRight") ? 1.0 : -1.0;
    auto *b = f.find<QPushButton>(button);
    QVERIFY(b);
    QVERIFY(b->isEnabled());
    QTest::mousePress(b, Qt::LeftButton);
    QVERIFY2(f.waitFor([&] { return sign * (f.session.azimuth() - start) > degrees; }, 20000),
             qPrintable(QStringLiteral("from %1° to %2°").arg(start).arg(f.session.azimuth())));
    QTest::mouseRelease(b, Qt::LeftButton);
    QVERIFY(f.waitUntilStill());
    const double stoppedAt = f.session.azimuth();
    QVERIFY(f.waitUntilStill()); // and it stays there
    QCOMPARE_LE(std::abs(f.session.azimuth() - stoppedAt), 0.05);
}

} // namespace

class TestSpidWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }

    void theJogSpeedIsTheControllers_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::newRow("rot2prog") << QStringLiteral("rot2prog"); // jogs by go-to legs
        QTest::newRow("md01") << QStringLiteral("md01");         // jogs by its move command
    }

    void theJogSpeedIsTheControllers()
    {
        QFETCH(QString, dialect);
        WindowFixture f(simFor(qPrintable(dialect), "&start_az=100&start_el=20"));
        QVERIFY(f.connectAndWait());
        QCOMPARE(slew::protocol::dialectName(f.session.profile().dialect), dialect);
        auto *speed = f.find<QDoubleSpinBox>(QStringLiteral("jogSpeed"));
        QVERIFY(!speed->isEnabled());
        QVERIFY2(speed->toolTip().contains(dialect) && speed->toolTip().contains(QStringLiteral("own speed")),
                 qPrintable(speed->toolTip()));
        for (const char *name : {"jogLeft", "jogRight", "jogUp", "jogDown"})
            QVERIFY2(f.find<QPushButton>(QLatin1String(name))->isEnabled(), name);
        const qsizetype before = f.sent.size();
        jogAndRelease(f, QStringLiteral("jogRight"), 5.0);
        jogAndRelease(f, QStringLiteral("jogLeft"), 5.0);
        // The MD-01/02 jogs by its move command, the Rot2Prog by sets
        // (the fixture keeps each frame trimmed: its command byte ends it).
        const QChar command(dialect == QLatin1String("md01") ? 0x14 : 0x2F);
        const QStringList frames = f.sent.mid(before);
        QVERIFY(std::any_of(frames.begin(), frames.end(), [&](const QString &frame) { return frame.endsWith(command); }));
    }

    void aSpeedDialectGetsTheBoxBack()
    {
        WindowFixture f(simFor("rot2prog"));
        QVERIFY(f.connectAndWait());
        auto *speed = f.find<QDoubleSpinBox>(QStringLiteral("jogSpeed"));
        QVERIFY(!speed->isEnabled());
        f.window->connectTo(QString::fromLatin1(WindowFixture::fastSimOnItsClock), slew::protocol::Dialect::Easycomm3);
        QVERIFY(f.waitFor([&] { return f.session.isConnected() && f.session.capabilities().probed; }, 10000));
        QVERIFY(f.session.capabilities().velocity);
        QVERIFY(speed->isEnabled());
        QVERIFY(!speed->toolTip().contains(QStringLiteral("own speed")));
    }

    void goToAndStop()
    {
        WindowFixture f(simFor("rot2prog", "&start_az=10&start_el=10"));
        QVERIFY(f.connectAndWait());
        // Typed keys reach only the active window (on xcb it is not active by itself).
        f.window->activateWindow();
        QVERIFY(f.waitFor([&] { return f.window->isActiveWindow(); }, 5000));
        typeInto(f.find<QLineEdit>(QStringLiteral("gotoAzimuth")), QStringLiteral("60"));
        typeInto(f.find<QLineEdit>(QStringLiteral("gotoElevation")), QStringLiteral("30"));
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("gotoButton")), Qt::LeftButton);
        QVERIFY2(f.waitUntilAt(60, 30, 0.6), // within the controller's half-degree steps
                 qPrintable(QStringLiteral("%1 at %2/%3").arg(f.find<QLabel>(QStringLiteral("gotoMessage"))->text())
                                .arg(f.session.azimuth()).arg(f.session.elevation())));

        // A long move, stopped on its way: it ends short of the target.
        QVERIFY(f.session.gotoPosition(300, 30));
        QVERIFY(f.waitFor([&] { return f.session.azimuth() > 80; }, 20000));
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("stopButton")), Qt::LeftButton);
        QVERIFY(f.waitUntilStill());
        QCOMPARE_LT(f.session.azimuth(), 250.0);
        const double stoppedAt = f.session.azimuth();
        QVERIFY(f.waitUntilStill());
        QCOMPARE_LE(std::abs(f.session.azimuth() - stoppedAt), 0.05);
    }

    void homeIsGreyedOutAndParkGoesToThePark()
    {
        WindowFixture f(simFor("rot2prog", "&start_az=200&start_el=20"));
        QVERIFY(f.connectAndWait());
        auto *home = f.find<QPushButton>(QStringLiteral("homeButton"));
        QVERIFY(!home->isEnabled());
        QVERIFY2(home->toolTip().contains(QStringLiteral("rot2prog has no homing command")),
                 qPrintable(home->toolTip()));
        auto *park = f.find<QPushButton>(QStringLiteral("parkButton"));
        QVERIFY(park->isEnabled()); // emulated by a go-to
        QTest::mouseClick(park, Qt::LeftButton);
        const QString said = f.find<QLabel>(QStringLiteral("homeMessage"))->text();
        QVERIFY2(said.startsWith(QStringLiteral("Parking at")), qPrintable(said));
        // The park azimuth is a bearing: from 200° the gate takes 0° as 360°,
        // the nearer end of the travel.
        const double az = f.session.parkAzimuth(), el = f.session.parkElevation();
        const auto atPark = [&] {
            return !f.session.positionStale() && std::abs(std::remainder(f.session.azimuth() - az, 360.0)) < 0.6
                && std::abs(f.session.elevation() - el) < 0.6;
        };
        QVERIFY2(f.waitFor(atPark, 20000), qPrintable(QStringLiteral("parking at %1/%2, at %3/%4")
                                                           .arg(az)
                                                           .arg(el)
                                                           .arg(f.session.azimuth())
                                                           .arg(f.session.elevation())));
    }

    void theConfigurationTabSaysThereAreNoRegisters()
    {
        WindowFixture f(simFor("rot2prog"));
        QVERIFY(f.connectAndWait());
        auto *note = f.find<QLabel>(QStringLiteral("configNoRegisters"));
        QVERIFY(!note->isHidden());
        QVERIFY2(note->text().contains(QStringLiteral("rot2prog has no configuration registers")),
                 qPrintable(note->text()));
        for (const char *name : {"configApply", "configRead", "configReadRegister"})
            QVERIFY2(!f.find<QPushButton>(QLatin1String(name))->isEnabled(), name);
        QVERIFY(!f.find<QWidget>(QStringLiteral("configValue1"))->isEnabled());
        // The profile is not the controller's: it stays the operator's to move.
        QVERIFY(f.find<QPushButton>(QStringLiteral("configImport"))->isEnabled());
        QVERIFY(f.find<QPushButton>(QStringLiteral("configExport"))->isEnabled());
        // Nor does a binary controller take a typed line.
        QVERIFY(!f.find<QLineEdit>(QStringLiteral("rawCommand"))->isEnabled());
        QVERIFY(!f.find<QPushButton>(QStringLiteral("rawSend"))->isEnabled());
        // Nor report speed, load, temperature or status: no empty charts for them.
        const char *reports[] = {"chartSpeed", "chartLoad", "chartTemp", "chartStatus"};
        for (const char *name : reports)
            QVERIFY2(f.find<QWidget>(QLatin1String(name))->isHidden(), name);
        QVERIFY(!f.find<QWidget>(QStringLiteral("chartAzEl"))->isHidden());

        // A controller with registers has them back.
        f.window->connectTo(QString::fromLatin1(WindowFixture::fastSimOnItsClock), slew::protocol::Dialect::Easycomm3);
        QVERIFY(f.waitFor([&] { return f.session.isConnected() && f.session.capabilities().probed; }, 10000));
        QVERIFY(note->isHidden());
        QVERIFY(f.find<QPushButton>(QStringLiteral("configRead"))->isEnabled());
        QVERIFY(f.find<QLineEdit>(QStringLiteral("rawCommand"))->isEnabled());
        QVERIFY(f.find<QPushButton>(QStringLiteral("homeButton"))->isEnabled());
        for (const char *name : reports)
            QVERIFY2(!f.find<QWidget>(QLatin1String(name))->isHidden(), name);
    }

    // A Rot2Prog talks at 600 baud and a Rot1Prog at 1200: choosing the
    // dialect sets the serial rate, which the list now holds.
    void choosingASpidDialectSetsItsBaudRate()
    {
        WindowFixture f(simFor("rot2prog"));
        auto *dialect = f.find<QComboBox>(QStringLiteral("dialect"));
        auto *baud = f.find<QComboBox>(QStringLiteral("serialBaud"));
        QVERIFY(baud->findText(QStringLiteral("600")) >= 0 && baud->findText(QStringLiteral("1200")) >= 0);
        for (const auto &[name, rate] : {std::pair{"rot2prog", "600"}, std::pair{"rot1prog", "1200"}}) {
            baud->setCurrentText(QStringLiteral("19200"));
            dialect->setCurrentIndex(dialect->findText(QLatin1String(name)));
            emit dialect->activated(dialect->currentIndex()); // as a click on the item does
            QCOMPARE(baud->currentText(), QLatin1String(rate));
        }
        // Another dialect leaves the rate alone.
        baud->setCurrentText(QStringLiteral("9600"));
        dialect->setCurrentIndex(dialect->findText(QStringLiteral("easycomm3")));
        emit dialect->activated(dialect->currentIndex());
        QCOMPARE(baud->currentText(), QStringLiteral("9600"));
    }

    void rot1progHasNoUpAndDown()
    {
        WindowFixture f(simFor("rot1prog", "&start_az=100"));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.session.isAzimuthOnly());
        QVERIFY(!f.find<QPushButton>(QStringLiteral("jogUp"))->isEnabled());
        QVERIFY(!f.find<QPushButton>(QStringLiteral("jogDown"))->isEnabled());
        QVERIFY(!f.find<QDoubleSpinBox>(QStringLiteral("jogSpeed"))->isEnabled());
        jogAndRelease(f, QStringLiteral("jogRight"), 5.0);
    }

    void screenshot()
    {
        WindowFixture f(simFor("rot2prog", "&start_az=135&start_el=25"));
        QVERIFY(f.connectAndWait());
        f.window->resize(1500, 950);
        QVERIFY(f.waitUntilStill());
        auto *charts = f.window->telemetryCharts();
        const int before = charts->redrawCount();
        QVERIFY(f.waitFor([&] { return charts->redrawCount() > before + 2; }, 10000)); // the polls drawn
        QVERIFY(QDir().mkpath(QStringLiteral(SLEW_SCREENSHOT_DIR)));
        QVERIFY(f.window->grab().save(QStringLiteral(SLEW_SCREENSHOT_DIR "/spid-window.png")));
        f.window->bringToFront(f.find<QWidget>(QStringLiteral("configEditor")));
        QVERIFY(f.window->grab().save(QStringLiteral(SLEW_SCREENSHOT_DIR "/spid-configuration.png")));
    }
};

QTEST_MAIN(TestSpidWindow)
#include "tst_spidwindow.moc"
