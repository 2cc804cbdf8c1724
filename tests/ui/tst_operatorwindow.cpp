// The operator window driven the way an operator drives it (clicks, typing,
// keys), against the in-process simulator on its manual clock, which the
// fixture pumps: moves, jogs and polls take simulated time, not wall time.

#include "windowfixture.h"

#include "alarmbanner.h"
#include "eventlog.h"
#include "rotor/configeditor.h"
#include "rotor/connectionbar.h"
#include "rotor/gotopanel.h"
#include "rotor/polarplotwidget.h"
#include "rotor/presetpanel.h"
#include "rotor/targetconfirmation.h"
#include "rotor/trafficconsole.h"
#include "telemetry/statuslaneview.h"
#include "telemetry/telemetrycharts.h"

#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QAction>
#include <QMessageBox>
#include <QPointer>
#include <QTest>

using slew::ui::ConfigEditor;
using slew::ui::TelemetryRecorder;

namespace {

const QRegularExpression kPositionCommand(QStringLiteral("^AZ\\s*-?\\d|EL\\s*-?\\d"));


} // namespace

class TestOperatorWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }

    void quitStopsTheRotatorThenCloses()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        f.window->show();
        QVERIFY(f.session.gotoPosition(f.session.azimuth() < 180 ? 300 : 60, 45));
        QVERIFY(f.waitFor([&] { return !f.isStill(); }, 10000));
        auto *quit = f.window->findChild<QAction *>(QStringLiteral("actionQuit"));
        QVERIFY(quit);
        QCOMPARE(quit->shortcut(), QKeySequence(QKeySequence::Quit));
        const int stopsBefore = f.sentCount(QRegularExpression(QStringLiteral("^SA")));
        quit->trigger();
        QVERIFY(f.waitFor([&] { return !f.window->isVisible(); }, 10000));
        QCOMPARE(f.sentCount(QRegularExpression(QStringLiteral("^SA"))), stopsBefore + 1);
        // The stop left before the window went.
        QVERIFY(f.waitUntilStill());
    }

    void helpMenuOpensWithoutBlocking()
    {
        WindowFixture f;
        for (const char *name : {"actionKeyboard", "actionAbout"}) {
            auto *action = f.window->findChild<QAction *>(QString::fromLatin1(name));
            QVERIFY2(action, name);
            action->trigger(); // opened, not exec()'d: this returns
            QPointer<QMessageBox> box = f.window->findChild<QMessageBox *>();
            QVERIFY2(box && box->isVisible(), name);
            QVERIFY(box->text().contains(QLatin1String(qstrcmp(name, "actionAbout") == 0 ? "Slew" : "Esc")));
            box->close(); // deletes itself: no note piles up behind the window
            QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
            QVERIFY(box.isNull());
        }
    }

    void jogRightMovesThenStopsTheAzimuth()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        const double start = f.session.azimuth();
        auto *right = f.find<QPushButton>(QStringLiteral("jogRight"));
        QVERIFY(right);
        QTest::mousePress(right, Qt::LeftButton);
        QVERIFY(f.waitFor([&] { return f.session.azimuth() > start + 2.0; }, 10000));
        QVERIFY(f.sentCount(QRegularExpression(QStringLiteral("^VR\\d"))) >= 1);
        QTest::mouseRelease(right, Qt::LeftButton);
        QVERIFY(f.sentCount(QRegularExpression(QStringLiteral("^SA"))) >= 1);
        QVERIFY(f.waitUntilStill());
        const double stoppedAt = f.session.azimuth();
        QVERIFY(f.waitUntilStill()); // and it stays there
        QCOMPARE_LE(std::abs(f.session.azimuth() - stoppedAt), 0.05);
        QCOMPARE_LE(std::abs(f.session.elevation() - f.recent.front().y()), 0.05);
    }

    void arrowKeysJogWhileHeld()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        f.window->activateWindow();
        f.find<QWidget>(QStringLiteral("polarPlot"))->setFocus();
        const double start = f.session.elevation();
        QTest::keyPress(f.window.get(), Qt::Key_Up);
        QVERIFY(f.waitFor([&] { return f.session.elevation() > start + 2.0; }, 10000));
        QTest::keyRelease(f.window.get(), Qt::Key_Up);
        // A key's release stops the axis once no autorepeat press follows it
        // (keyboardcontrol.h), a few milliseconds later.
        QVERIFY(f.waitFor([&] { return f.sentCount(QRegularExpression(QStringLiteral("^SE|^SA SE"))) >= 1; }, 5000));
        QVERIFY(f.waitUntilStill());
    }

    void gotoReachesTheTarget()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        WindowFixture::typeInto(f.find<QLineEdit>(QStringLiteral("gotoAzimuth")), QStringLiteral("40"));
        WindowFixture::typeInto(f.find<QLineEdit>(QStringLiteral("gotoElevation")), QStringLiteral("20,5"));
        auto *go = f.find<QPushButton>(QStringLiteral("gotoButton"));
        QVERIFY(go->isEnabled());
        QTest::mouseClick(go, Qt::LeftButton);
        QCOMPARE(f.sentCount(kPositionCommand), 1);
        QVERIFY(f.waitUntilAt(40.0, 20.5));
        QCOMPARE(f.window->polarPlot()->actual()->x(), f.session.azimuth());
    }

    // The controllers stations run, as slew-sim answers for them
    // (docs/protocol.md, "Controllers in the field"): a go-to from the
    // window is shown where the controller stopped, and the event log says
    // it arrived, K3NG's 2.3° short inside its tolerance, the SatNOGS
    // firmware's under its GS4 status.
    void gotoOnTheFirmwareStationsRun_data()
    {
        QTest::addColumn<QString>("uri");
        QTest::addColumn<double>("stopsAtAz");
        QTest::newRow("K3NG Easycom") << "sim:?model=satnogs&clock=manual&dialect=easycomm2&firmware=k3ng" << 37.7;
        QTest::newRow("K3NG GS-232B") << "sim:?model=satnogs&clock=manual&dialect=gs232b&firmware=k3ng" << 38.0;
        QTest::newRow("SatNOGS") << "sim:?model=satnogs&clock=manual&dialect=satnogs&firmware=satnogs" << 40.0;
    }

    void gotoOnTheFirmwareStationsRun()
    {
        QFETCH(QString, uri);
        QFETCH(double, stopsAtAz);
        WindowFixture f(uri);
        QVERIFY(f.connectAndWait());
        WindowFixture::typeInto(f.find<QLineEdit>(QStringLiteral("gotoAzimuth")), QStringLiteral("40"));
        WindowFixture::typeInto(f.find<QLineEdit>(QStringLiteral("gotoElevation")), QStringLiteral("20"));
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("gotoButton")), Qt::LeftButton);
        QVERIFY(f.waitUntilAt(stopsAtAz, 20.0, 0.2));
        QVERIFY(f.waitUntilStill());
        QCOMPARE(f.window->polarPlot()->actual()->x(), f.session.azimuth());
        auto log = [&] { return f.window->eventLog()->toPlainText(); };
        QVERIFY2(f.waitFor([&] { return log().contains(QStringLiteral(": arrived, at az")); }, 10000), qPrintable(log()));
        QVERIFY2(!log().contains(QStringLiteral("came to rest")), qPrintable(log()));
    }

    // The connection bar: a firmware the URI names is taken where it can
    // speak the dialect chosen, and one the profile held for another
    // dialect goes (no SatNOGS quirks on a GS-232 link).
    void theConnectionBarTakesTheFirmwareTheDialectAllows()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        slew::ui::ConnectionBar *bar = f.window->connectionBar();
        bar->setDialect(slew::protocol::Dialect::Gs232B);
        bar->setUri(QStringLiteral("tcp://127.0.0.1:9?firmware=k3ng"));
        bar->connectToRotator();
        QCOMPARE(f.session.profile().dialect, slew::protocol::Dialect::Gs232B);
        QCOMPARE(f.session.profile().firmware, slew::protocol::Firmware::K3ng);
        bar->disconnectFromRotator();
        slew::model::RotatorProfile satnogs = f.session.profile();
        satnogs.firmware = slew::protocol::Firmware::SatNogs;
        f.session.setProfile(satnogs);
        bar->setUri(QStringLiteral("tcp://127.0.0.1:9"));
        bar->connectToRotator();
        QCOMPARE(f.session.profile().firmware, slew::protocol::Firmware::Generic);
        bar->disconnectFromRotator();
    }

    void outOfRangeGotoSendsNothing_data()
    {
        QTest::addColumn<QString>("az");
        QTest::addColumn<QString>("el");
        QTest::newRow("azimuth past the stop") << "400" << "10";
        QTest::newRow("negative elevation") << "100" << "-3";
        QTest::newRow("elevation past the profile's 90") << "100" << "95";
        QTest::newRow("not a number") << "1o0" << "10";
    }

    void outOfRangeGotoSendsNothing()
    {
        QFETCH(QString, az);
        QFETCH(QString, el);
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        auto *azField = f.find<QLineEdit>(QStringLiteral("gotoAzimuth"));
        WindowFixture::typeInto(azField, az);
        WindowFixture::typeInto(f.find<QLineEdit>(QStringLiteral("gotoElevation")), el);
        auto *go = f.find<QPushButton>(QStringLiteral("gotoButton"));
        QVERIFY(!go->isEnabled());
        QVERIFY(!f.find<QLabel>(QStringLiteral("gotoMessage"))->text().isEmpty());
        QTest::mouseClick(go, Qt::LeftButton);
        QTest::keyClick(azField, Qt::Key_Return);
        QVERIFY(!f.window->gotoPanel()->go());
        const int polls = int(f.sent.size());
        QVERIFY(f.waitFor([&] { return f.sent.size() > polls + 3; }, 5000)); // the link is alive and still polling
        QCOMPARE(f.sentCount(kPositionCommand), 0);
    }

    void configApplyIsReadBackEqual()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        ConfigEditor *editor = f.window->configEditor();
        f.window->bringToFront(editor); // opening it reads the device
        // Every register this test looks at: CR7/CR8 come early, the session
        // reads them on connect, so they are no sign the rest are in.
        QVERIFY(f.waitFor([&] {
            return !editor->deviceValue(1).isEmpty() && !editor->deviceValue(2).isEmpty()
                && !editor->deviceValue(7).isEmpty();
        }, 10000));
        QCOMPARE(editor->fieldState(1), ConfigEditor::FieldState::Same);

        auto *kp = f.find<QLineEdit>(QStringLiteral("configValue1"));
        auto *parkAz = f.find<QLineEdit>(QStringLiteral("configValue7"));
        WindowFixture::typeInto(kp, QStringLiteral("12.5"));
        WindowFixture::typeInto(parkAz, QStringLiteral("123.25"));
        QCOMPARE(editor->fieldState(1), ConfigEditor::FieldState::Changed);
        QCOMPARE(editor->fieldState(7), ConfigEditor::FieldState::Changed);
        QCOMPARE(editor->fieldState(2), ConfigEditor::FieldState::Same);

        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("configApply")), Qt::LeftButton);
        QCOMPARE(f.sentCount(QRegularExpression(QStringLiteral("^CW"))), 2); // only what changed
        QVERIFY(f.waitFor([&] { return editor->fieldState(1) == ConfigEditor::FieldState::Confirmed; }, 10000));
        QVERIFY(f.waitFor([&] { return editor->fieldState(7) == ConfigEditor::FieldState::Confirmed; }, 10000));
        QCOMPARE(editor->deviceValue(1).toDouble(), 12.5);
        QCOMPARE(editor->deviceValue(7).toDouble(), 123.25);
    }

    void invalidConfigWritesNothing()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        ConfigEditor *editor = f.window->configEditor();
        f.window->bringToFront(editor);
        QVERIFY(f.waitFor([&] { return !editor->deviceValue(2).isEmpty() && !editor->deviceValue(8).isEmpty(); }, 10000));
        WindowFixture::typeInto(f.find<QLineEdit>(QStringLiteral("configValue2")), QStringLiteral("0.25"));
        WindowFixture::typeInto(f.find<QLineEdit>(QStringLiteral("configValue8")), QStringLiteral("120")); // park el above 90
        QCOMPARE(editor->fieldState(8), ConfigEditor::FieldState::Invalid);
        QCOMPARE(editor->apply(), 0);
        QCOMPARE(f.sentCount(QRegularExpression(QStringLiteral("^CW"))), 0);
        QVERIFY(f.find<QLabel>(QStringLiteral("configMessage"))->text().contains(QStringLiteral("Nothing was written")));
    }

    void profileExportAndImportRoundTrip()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        ConfigEditor *editor = f.window->configEditor();
        f.window->bringToFront(editor);
        QVERIFY(f.waitFor([&] { return !editor->deviceValue(6).isEmpty(); }, 10000));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("rotator.json"));
        QString error;
        QVERIFY2(editor->exportProfile(path, &error), qPrintable(error));
        QVERIFY2(editor->importProfile(path, &error), qPrintable(error));
        QCOMPARE(editor->fieldState(1), ConfigEditor::FieldState::Same); // same gains: nothing to apply
        QVERIFY(!editor->importProfile(dir.filePath(QStringLiteral("missing.json")), &error));
        QVERIFY(!error.isEmpty());
    }

    void chartsReceiveSamples()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        f.session.gotoPosition(30, 10);
        auto *charts = f.window->telemetryCharts();
        QVERIFY(f.waitFor([&] { return charts->series(TelemetryRecorder::AzActual)->count() > 5; }, 10000));
        QVERIFY(f.waitFor([&] { return charts->series(TelemetryRecorder::AzVelocity)->count() > 0; }, 10000));
        QVERIFY(f.waitFor([&] { return charts->series(TelemetryRecorder::AzCommanded)->count() > 0; }, 10000));
        QVERIFY(f.waitFor([&] { return !charts->statusLanes()->stretches(0).empty(); }, 10000)); // GS az
        const double lastAz = charts->series(TelemetryRecorder::AzActual)->points().back().y();
        QVERIFY(lastAz >= 0 && lastAz <= 30.5);

        charts->setPaused(true);
        const int frozen = charts->redrawCount();
        QVERIFY(f.waitUntilAt(30, 10));
        QCOMPARE(charts->redrawCount(), frozen);
        charts->setPaused(false);
        QVERIFY(charts->redrawCount() > frozen);

        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("t.csv"));
        QString error;
        QVERIFY2(charts->exportCsv(csv, &error), qPrintable(error));
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().split('\n');
        QVERIFY2(lines.front().startsWith("time_utc,unix_ms,Az (deg),El (deg),"), lines.front().constData());
        QVERIFY(lines.size() > 10);
    }

    void aJamRaisesTheAlarmBanner()
    {
        WindowFixture f(QStringLiteral("sim:?jam=az&jam_after=0.3&clock=manual"));
        QVERIFY(f.connectAndWait());
        auto *banner = f.window->alarmBanner();
        QVERIFY(!banner->isSevere());
        QVERIFY(f.session.gotoPosition(90, 0));
        QVERIFY(f.waitFor([&] { return banner->text().contains(QStringLiteral("motor"), Qt::CaseInsensitive); }, 15000));
        QVERIFY(!banner->isHidden());
        QVERIFY(banner->isSevere());
        const QString log = f.window->findChild<QWidget *>(QStringLiteral("eventLog"))->property("plainText").toString();
        QVERIFY(log.contains(QStringLiteral("ALARM")));
    }

    void plotClickAsksThenMoves()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        auto *plot = f.window->polarPlot();
        const QPoint at = plot->pointFor(90, 45).toPoint();
        QTest::mouseClick(plot, Qt::LeftButton, {}, at);
        QVERIFY(f.window->targetConfirmation()->pending().has_value());
        QCOMPARE(f.sentCount(kPositionCommand), 0); // asked, not sent
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("targetGo")), Qt::LeftButton);
        QCOMPARE(f.sentCount(kPositionCommand), 1);
        const auto picked = plot->azElAt(at);
        QVERIFY(f.waitUntilAt(picked->x(), picked->y(), 0.5));

        // With confirmation off a click moves at once.
        f.window->targetConfirmation()->setConfirmationWanted(false);
        QTest::mouseClick(plot, Qt::LeftButton, {}, plot->pointFor(180, 60).toPoint());
        QCOMPARE(f.sentCount(kPositionCommand), 2);
    }

    void presetsStoreAndRecallByAltAndNumber()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.session.gotoPosition(50, 25));
        QVERIFY(f.waitUntilAt(50, 25, 0.2));
        QVERIFY(f.waitUntilStill());
        auto *panel = f.window->presetPanel();
        QVERIFY(panel->storeCurrent(QStringLiteral("Relay")));
        QCOMPARE(panel->presets().size(), 1);
        QVERIFY(f.session.gotoPosition(10, 5));
        QVERIFY(f.waitUntilAt(10, 5));
        QVERIFY(f.waitUntilStill());
        f.find<QWidget>(QStringLiteral("polarPlot"))->setFocus();
        // A bare digit is no preset: "JAS-2" typed where a field lost its
        // focus moves nothing.
        const int before = f.sentCount(kPositionCommand);
        QTest::keyClick(f.window.get(), Qt::Key_1);
        QTest::keyClick(f.window.get(), Qt::Key_2);
        QCOMPARE(f.sentCount(kPositionCommand), before);
        // Alt+1 with "Ask before moving" on: asked first, as a plot click
        // is, and sent once accepted.
        slew::ui::TargetConfirmation *confirm = f.window->targetConfirmation();
        confirm->setConfirmationWanted(true);
        QTest::keyClick(f.window.get(), Qt::Key_1, Qt::AltModifier);
        QCOMPARE(f.sentCount(kPositionCommand), before);
        QVERIFY(confirm->pending().has_value());
        auto *question = confirm->findChild<QLabel *>();
        QVERIFY(question);
        QVERIFY2(question->text().contains(QStringLiteral("preset 'Relay'")), qPrintable(question->text()));
        confirm->accept();
        QCOMPARE(f.sentCount(kPositionCommand), before + 1);
        QVERIFY(f.waitUntilAt(50, 25));
        // With confirmation off, Alt+1 goes at once.
        QVERIFY(f.session.gotoPosition(10, 5));
        QVERIFY(f.waitUntilAt(10, 5));
        confirm->setConfirmationWanted(false);
        QTest::keyClick(f.window.get(), Qt::Key_1, Qt::AltModifier);
        QVERIFY(f.waitUntilAt(50, 25));
        QVERIFY(!panel->recall(5)); // no such preset: nothing sent
    }

    void anAzimuthOnlyRotatorHasNoElevationControls()
    {
        // One rotor of a Micro-2g controller; the link names the dialect.
        WindowFixture f(QStringLiteral("sim:?dialect=micro2g&rotor=3&clock=manual"));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.session.isAzimuthOnly());
        // No up and down, neither as buttons nor as keys.
        QVERIFY(!f.find<QPushButton>(QStringLiteral("jogUp"))->isEnabled());
        QVERIFY(!f.find<QPushButton>(QStringLiteral("jogDown"))->isEnabled());
        QVERIFY(f.find<QPushButton>(QStringLiteral("jogLeft"))->isEnabled());
        const int before = int(f.sent.size());
        f.find<QWidget>(QStringLiteral("polarPlot"))->setFocus();
        QTest::keyPress(f.window.get(), Qt::Key_Up);
        QTest::keyRelease(f.window.get(), Qt::Key_Up);
        QVERIFY(f.sent.mid(before).filter(QRegularExpression(QStringLiteral("^M|^S"))).isEmpty());
        // Elevation is 0 and not the operator's to change; azimuth goes.
        auto *el = f.find<QLineEdit>(QStringLiteral("gotoElevation"));
        QVERIFY(!el->isEnabled());
        QCOMPARE(el->text(), QStringLiteral("0"));
        WindowFixture::typeInto(f.find<QLineEdit>(QStringLiteral("gotoAzimuth")), QStringLiteral("90"));
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("gotoButton")), Qt::LeftButton);
        QVERIFY(f.sent.contains(QStringLiteral("3\rM090")));
        QVERIFY(f.waitUntilAt(90, 0, 7.0)); // within the controller's tolerance
        // The charts draw no flat elevation line.
        auto *charts = f.window->telemetryCharts();
        QVERIFY(!charts->series(TelemetryRecorder::ElActual)->isVisible());
        QVERIFY(charts->series(TelemetryRecorder::AzActual)->isVisible());
        // Back on a two-axis rotator, everything returns.
        f.window->connectTo(QString::fromLatin1(WindowFixture::fastSimOnItsClock), slew::protocol::Dialect::Easycomm3);
        QVERIFY(f.waitFor([&] { return f.session.isConnected() && !f.session.isAzimuthOnly(); }, 10000));
        QVERIFY(f.find<QPushButton>(QStringLiteral("jogUp"))->isEnabled());
        QVERIFY(el->isEnabled());
        QVERIFY(charts->series(TelemetryRecorder::ElActual)->isVisible());
    }

    void trafficConsoleShowsAndSendsRaw()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        auto *console = f.window->trafficConsole();
        QVERIFY(f.waitFor([&] { return console->entries().size() > 4; }, 5000));
        QVERIFY(std::any_of(console->entries().begin(), console->entries().end(),
                            [](const auto &e) { return !e.sent && e.line.startsWith("AZ"); }));
        QVERIFY(console->sendRaw(QStringLiteral("VE")));
        QCOMPARE(f.sent.back(), QStringLiteral("VE"));
        QVERIFY(!console->sendRaw(QStringLiteral("AZ400.0"))); // limits apply to raw lines too
        QVERIFY(f.find<QLabel>(QStringLiteral("rawMessage"))->text().startsWith(QStringLiteral("Not sent")));
        QCOMPARE(f.sentCount(kPositionCommand), 0);
        WindowFixture::typeInto(f.find<QLineEdit>(QStringLiteral("trafficFilter")), QStringLiteral("^VE"));
        const QString shown = f.find<QWidget>(QStringLiteral("trafficView"))->property("plainText").toString();
        QVERIFY(shown.contains(QStringLiteral("→ VE")));
        QVERIFY(!shown.contains(QStringLiteral("AZ EL")));
    }
};

QTEST_MAIN(TestOperatorWindow)
#include "tst_operatorwindow.moc"
