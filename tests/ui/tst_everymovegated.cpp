// SPDX-License-Identifier: GPL-3.0-or-later
// Every path to the wire passes the one gate (model/movegate.h). The session
// runs over an in-process scripted link that reports narrower limits than
// the profile's (azimuth 10..350, elevation 0..80 against 0..360, 0..90), as
// a rotctld peer does, and stands at azimuth 350, on the reported limit.
// Each path is then asked for a move outside those limits, and the test
// reads the bytes that reached the link: no move may be among them.
//
// The paths: the session's own commands, the go-to panel, a plot click and
// its confirmation, the jog pad, presets, park, the register editor, the
// traffic console's raw line, the rotctld server, the tuner's step and
// slewctl's runner; and the session's commands again in the rotctld dialect,
// which a rotctld:// link's session speaks. A legal go-to at the end shows
// that the link's record does see moves, so the test can fail.
//
// Then a controller whose position cannot be read (K3NG's GS-232B report on
// an Easycomm link: the wrong dialect): no face sends a move, neither the
// window, nor rotctld, nor slewctl, nor a command from the broker, nor
// tracking or the schedule, which say why the antenna waits.

#include "../common/scriptedlink.h"

#include "bridge/rotctldserver.h"
#include "rotor/configeditor.h"
#include "console/consolecommand.h"
#include "console/consolerunner.h"
#include "rotor/gotopanel.h"
#include "rotor/jogpad.h"
#include "stationwindow.h"
#include "station/station.h"
#include "rotor/parkhomepanel.h"
#include "rotor/polarplotwidget.h"
#include "rotor/presetpanel.h"
#include "remote/remotecommand.h"
#include "session/rotatorsession.h"
#include "station/remotecommands.h"
#include "station/schedulerunner.h"
#include "tracking/passrunner.h"
#include "tracking/tracktarget.h"
#include "rotor/targetconfirmation.h"
#include "rotor/trafficconsole.h"
#include "tuning/stepexperiment.h"

#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTcpSocket>
#include <QTest>

#include <functional>

using slew::session::Axis;
using slew::session::RotatorSession;

class EveryMoveGatedTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        registerScriptedLinkScheme();
        scriptedLinkReports() = slew::model::RotatorLimits{10.0, 350.0, 0.0, 80.0};
    }

    void init()
    {
        scriptedLinkDialect() = slew::protocol::Dialect::Easycomm3;
        m_station = std::make_unique<slew::station::Station>();
        m_session = m_station->session();
        slew::model::RotatorProfile profile; // 0..360, 0..90, park at 0/90
        m_session->setProfile(profile);
        m_window = std::make_unique<slew::ui::StationWindow>(m_station.get());
        m_window->show();
        m_session->connectTo(QStringLiteral("scripted:"));
        QTRY_VERIFY(lastScriptedLink());
        m_device = lastScriptedLink()->scripted();
        m_device->azimuth = 350.0;
        m_device->elevation = 40.0;
        // The probe done too, so that no unanswered query holds the line
        // while the paths are walked.
        QTRY_VERIFY_WITH_TIMEOUT(m_session->isConnected() && m_session->capabilities().probed
                                     && m_session->hasPosition() && m_session->reportedLimits(),
                                 30000);
        QCOMPARE(m_session->azimuth(), 350.0);
    }

    void cleanup()
    {
        scriptedLinkReports() = slew::model::RotatorLimits{10.0, 350.0, 0.0, 80.0};
        m_window.reset();
        m_session = nullptr;
        m_station.reset();
    }

    void theSessionsOwnCommands()
    {
        expectNothingSent("go-to past the link's azimuth", [&] { QVERIFY(!m_session->gotoPosition(355, 10)); });
        expectNothingSent("go-to past the profile's elevation", [&] { QVERIFY(!m_session->gotoPosition(100, 95)); });
        expectNothingSent("one axis past the link's elevation",
                          [&] { QVERIFY(!m_session->gotoAxis(Axis::Elevation, 85)); });
        expectNothingSent("one azimuth position past the link's limit", [&] {
            QVERIFY(!m_session->gotoAxis(Axis::Azimuth, 5, RotatorSession::AzimuthIs::Position));
        });
        expectNothingSent("a drive further into the limit it stands on",
                          [&] { QVERIFY(!m_session->moveAxis(Axis::Azimuth, 5.0)); });
        expectNothingSent("a relative move past the link's azimuth", [&] { QVERIFY(!m_session->moveBy(5, 0)); });
        expectNothingSent("a relative move past the profile's elevation", [&] { QVERIFY(!m_session->moveBy(0, 55)); });
        expectNothingSent("park at an elevation past the link's limit", [&] { QVERIFY(!m_session->park()); });
        expectNothingSent("a park azimuth register past the link's limit",
                          [&] { QVERIFY(!m_session->writeConfig(7, QStringLiteral("355"))); });
        for (const char *raw : {"AZ355.0 EL10.0", "EL85", "VR5000", "MR", "CW8,85", "PARK"})
            expectNothingSent(QByteArray("raw ") + raw, [&] { QVERIFY(!m_session->sendRaw(QString::fromLatin1(raw))); });
    }

    void theOperatorWindow()
    {
        auto *go = m_window->gotoPanel();
        expectNothingSent("go-to panel", [&] {
            go->findChild<QLineEdit *>(QStringLiteral("gotoAzimuth"))->setText(QStringLiteral("355"));
            go->findChild<QLineEdit *>(QStringLiteral("gotoElevation"))->setText(QStringLiteral("10"));
            QVERIFY(!go->findChild<QPushButton *>(QStringLiteral("gotoButton"))->isEnabled());
            QVERIFY(go->findChild<QLabel *>(QStringLiteral("gotoMessage"))->text().contains(QStringLiteral("link reports")));
            QVERIFY(!go->go()); // Enter pressed all the same
        }, false);
        expectNothingSent("plot click", [&] { emit m_window->polarPlot()->targetPicked(355, 10); }, false);
        expectNothingSent("a confirmed plot target",
                          [&] { emit m_window->targetConfirmation()->accepted(355, 10); });
        expectNothingSent("jog pad", [&] { jogRightOnce(); });
        expectNothingSent("park button", [&] { clickPark(); });
        // A preset stored where the rotator once stood, past what the link
        // now allows.
        m_device->azimuth = 355.0;
        QTRY_COMPARE_WITH_TIMEOUT(m_session->azimuth(), 355.0, 15000);
        QVERIFY(m_window->presetPanel()->storeCurrent(QStringLiteral("beyond")));
        m_device->azimuth = 350.0;
        QTRY_COMPARE_WITH_TIMEOUT(m_session->azimuth(), 350.0, 15000);
        const int beyond = int(m_window->presetPanel()->presets().size()) - 1;
        expectNothingSent("preset", [&] { QVERIFY(!m_window->presetPanel()->recall(beyond)); });
        expectNothingSent("register editor", [&] {
            auto *editor = m_window->configEditor();
            auto *value = editor->findChild<QLineEdit *>(QStringLiteral("configValue7"));
            QVERIFY(value);
            // As typed (the field waits for the controller's value, which the
            // scripted link never gives, so it takes no keys).
            value->setText(QStringLiteral("355"));
            emit value->textEdited(value->text());
            QCOMPARE(editor->apply(), 0);
            QCOMPARE(editor->fieldState(7), slew::ui::ConfigEditor::FieldState::Invalid);
        }, false);
        expectNothingSent("traffic console", [&] {
            auto *console = m_window->trafficConsole();
            console->findChild<QLineEdit *>(QStringLiteral("rawCommand"))->setText(QStringLiteral("AZ355"));
            QTest::mouseClick(console->findChild<QPushButton *>(QStringLiteral("rawSend")), Qt::LeftButton);
            QVERIFY(console->findChild<QLabel *>(QStringLiteral("rawMessage"))->text().startsWith(QStringLiteral("Not sent")));
        });
    }

    void theRotctldServer() { rotctldRefuses("rotctld ", {"P 355 10\n", "P 100 85\n", "M 16 50\n"}); }

    void theTunerAndSlewctl()
    {
        slew::tuning::StepExperiment step(m_session);
        expectNothingSent("tuning step ending past the link's azimuth", [&] {
            QVERIFY(!step.start(Axis::Azimuth, 340, 355));
            QVERIFY2(step.error().contains(QStringLiteral("link reports")), qPrintable(step.error()));
        }, false);
        expectNothingSent("tuning step starting past the link's elevation",
                          [&] { QVERIFY(!step.start(Axis::Elevation, 85, 70)); });

        slew::console::ConsoleRunner runner(m_session, false);
        QSignalSpy finished(&runner, &slew::console::ConsoleRunner::finished);
        expectNothingSent("slewctl goto", [&] {
            QString error;
            const auto command = slew::console::parseConsoleCommand({QStringLiteral("goto"), QStringLiteral("355"),
                                                                     QStringLiteral("10")},
                                                                    &error);
            QVERIFY2(command, qPrintable(error));
            runner.run(*command);
            QTRY_COMPARE(finished.count(), 1);
            QCOMPARE(finished.at(0).at(0).value<slew::console::ExitCode>(), slew::console::ExitCode::Refused);
        });
    }

    void theRotctldDialect()
    {
        // Reconnected speaking rotctld, as to a rotctld:// peer: the scripted
        // link answers p, _ and RPRT 0 as rotctld does.
        m_session->disconnectFromRotator();
        scriptedLinkDialect() = slew::protocol::Dialect::Rotctld;
        slew::model::RotatorProfile profile = m_session->profile();
        profile.dialect = slew::protocol::Dialect::Rotctld;
        m_session->setProfile(profile);
        m_session->connectTo(QStringLiteral("scripted:"));
        QVERIFY(lastScriptedLink());
        m_device = lastScriptedLink()->scripted();
        QCOMPARE(m_device->dialect, slew::protocol::Dialect::Rotctld);
        m_device->azimuth = 350.0;
        m_device->elevation = 40.0;
        QTRY_VERIFY_WITH_TIMEOUT(m_session->isConnected() && m_session->capabilities().probed
                                     && m_session->hasPosition() && m_session->reportedLimits(),
                                 30000);
        QCOMPARE(m_session->azimuth(), 350.0);

        expectNothingSent("rotctld go-to past the link's azimuth", [&] { QVERIFY(!m_session->gotoPosition(355, 10)); });
        expectNothingSent("rotctld elevation alone past the link's limit",
                          [&] { QVERIFY(!m_session->gotoAxis(Axis::Elevation, 85)); });
        expectNothingSent("rotctld azimuth alone past the link's limit", [&] {
            QVERIFY(!m_session->gotoAxis(Axis::Azimuth, 5, RotatorSession::AzimuthIs::Position));
        });
        expectNothingSent("rotctld drive into the limit", [&] { QVERIFY(!m_session->moveAxis(Axis::Azimuth, 5.0)); });
        expectNothingSent("rotctld park past the link's elevation", [&] { QVERIFY(!m_session->park()); });
        // Raw lines: rotctld's moves through the gate, and what Slew cannot
        // read (w passes bytes to the rotator, + asks another answer form,
        // a lone number is half a command) not at all.
        for (const char *raw : {"P 355 10", "\\set_pos 100 85", "M 16 50", "K", "w AZ355", "+P 355 10", "355"})
            expectNothingSent(QByteArray("rotctld raw ") + raw,
                              [&] { QVERIFY(!m_session->sendRaw(QString::fromLatin1(raw))); });
        // What rotctld has no command for is refused, not sent.
        QVERIFY(!m_session->readConfig(1));
        QVERIFY(!m_session->writeConfig(7, QStringLiteral("100")));

        // A legal elevation-only move goes out as P with the azimuth kept.
        const qsizetype mark = m_device->written.size();
        QVERIFY(m_session->gotoAxis(Axis::Elevation, 30));
        QCOMPARE(m_device->movesSince(mark), (QStringList{QStringLiteral("AZ350"), QStringLiteral("EL30")}));
        QVERIFY2(m_device->written.sliced(mark).contains("P 350.00 30.00\n"), m_device->written.sliced(mark).constData());
    }

    void noPositionNoMoveFromAnyFace()
    {
        // The whole travel this time, so that tracking has a plan to hold.
        scriptedLinkReports() = slew::model::RotatorLimits{0.0, 360.0, 0.0, 90.0};
        m_session->disconnectFromRotator();
        m_session->connectTo(QStringLiteral("scripted:"));
        QVERIFY(lastScriptedLink());
        m_device = lastScriptedLink()->scripted();
        m_device->positionUnreadable = true; // before the probe's first query
        QTRY_VERIFY_WITH_TIMEOUT(m_session->isConnected() && m_session->capabilities().probed, 30000);
        QVERIFY(!m_session->capabilities().positionFeedback);
        const QString why = QStringLiteral("no position read from the controller: check the dialect (easycomm3)");
        QCOMPARE(m_session->positionNotRead(), why);

        // The window: its go-to says the session's reason where it was typed.
        auto *go = m_window->gotoPanel();
        expectNothingSent("go-to panel, no position", [&] {
            go->findChild<QLineEdit *>(QStringLiteral("gotoAzimuth"))->setText(QStringLiteral("120"));
            go->findChild<QLineEdit *>(QStringLiteral("gotoElevation"))->setText(QStringLiteral("30"));
            QVERIFY(!go->go());
            const QString said = go->findChild<QLabel *>(QStringLiteral("gotoMessage"))->text();
            QVERIFY2(said.contains(why), qPrintable(said));
        });
        expectNothingSent("a confirmed plot target, no position",
                          [&] { emit m_window->targetConfirmation()->accepted(120, 30); });
        expectNothingSent("jog pad, no position", [&] { jogRightOnce(); });
        expectNothingSent("park button, no position", [&] { clickPark(); });
        expectNothingSent("traffic console, no position", [&] {
            auto *console = m_window->trafficConsole();
            console->findChild<QLineEdit *>(QStringLiteral("rawCommand"))->setText(QStringLiteral("AZ120.0 EL30.0"));
            QTest::mouseClick(console->findChild<QPushButton *>(QStringLiteral("rawSend")), Qt::LeftButton);
        });

        // rotctld (Gpredict, the SatNOGS client): an error, not RPRT 0.
        rotctldRefuses("rotctld, no position: ", {"P 120 30\n"});

        // slewctl.
        QString error;
        slew::console::ConsoleRunner runner(m_session, false);
        QSignalSpy finished(&runner, &slew::console::ConsoleRunner::finished);
        expectNothingSent("slewctl goto, no position", [&] {
            const auto command = slew::console::parseConsoleCommand(
                {QStringLiteral("goto"), QStringLiteral("120"), QStringLiteral("30")}, &error);
            QVERIFY2(command, qPrintable(error));
            runner.run(*command);
            QTRY_COMPARE(finished.count(), 1);
            QCOMPARE(finished.at(0).at(0).value<slew::console::ExitCode>(), slew::console::ExitCode::Refused);
        }, false);

        // Commands from the broker (MQTT): refused in the session's words.
        slew::station::RemoteCommands commands(m_station.get(), {});
        for (const char *json : {R"j({"id":"g","cmd":"goto","az":120,"el":30})j", R"j({"id":"j","cmd":"jog","az_speed":5})j",
                                 R"j({"id":"p","cmd":"park"})j"}) {
            expectNothingSent(QByteArray("broker ") + json, [&] {
                const std::optional<slew::remote::RemoteReply> reply = commands.handle(json);
                QVERIFY(reply);
                QVERIFY2(!reply->ok && reply->error.contains(why), qPrintable(reply->error));
            });
        }

        // Tracking, from the broker and from the schedule: the pass runner
        // takes the target and waits, saying why; no point goes out.
        slew::tracking::PassRunner *passes = m_station->passRunner();
        QSignalSpy passLog(passes, &slew::tracking::PassRunner::logLine);
        const QString waits = QStringLiteral("the antenna waits: ") + why;
        auto said = [&] {
            QStringList lines;
            for (const QList<QVariant> &args : std::as_const(passLog))
                lines << args.at(0).toString();
            return lines.join(u'\n');
        };
        auto saidWaits = [&] {
            for (const QList<QVariant> &args : std::as_const(passLog))
                if (args.at(0).toString() == waits)
                    return true;
            return false;
        };
        m_station->setPlace(slew::sky::Site{55.7, 12.6, 10, {}, {}});
        expectNothingSent("broker track, no position", [&] {
            const std::optional<slew::remote::RemoteReply> reply =
                commands.handle(R"j({"id":"t","cmd":"track","target":"azel:200,40"})j");
            QVERIFY(reply && reply->ok);
            QTRY_VERIFY2_WITH_TIMEOUT(saidWaits(), qPrintable(said()), 15000);
        }, false);
        m_station->untrack(QStringLiteral("test"));
        passLog.clear();
        const auto target = slew::tracking::TrackTarget::parseFixedOrCelestial(QStringLiteral("azel:200,40"), &error);
        QVERIFY2(target, qPrintable(error));
        expectNothingSent("schedule, no position", [&] {
            QCOMPARE(m_station->runSchedule({*target}, slew::station::ScheduleOptions{}).reason(), QString());
            QTRY_VERIFY2_WITH_TIMEOUT(saidWaits(), qPrintable(said()), 15000);
        }, false);
        m_station->untrack(QStringLiteral("test"));
    }

    void aLegalMoveIsSeen()
    {
        const qsizetype mark = m_device->written.size();
        QVERIFY(m_session->gotoPosition(100, 40));
        const QStringList moves = m_device->movesSince(mark);
        QVERIFY2(moves.size() == 2, qPrintable(moves.join(u' ')));
        QCOMPARE(moves.at(0), QStringLiteral("AZ100"));
    }

private:
    // The window's own controls, as the operator uses them.
    void jogRightOnce()
    {
        auto *right = m_window->jogPad()->findChild<QPushButton *>(QStringLiteral("jogRight"));
        QTest::mousePress(right, Qt::LeftButton);
        QTest::mouseRelease(right, Qt::LeftButton);
    }
    // A tracker on the session's own rotctld server: each request answered
    // with an error (RPRT -n), and nothing sent to the rotator.
    void rotctldRefuses(const QByteArray &path, const QList<QByteArray> &requests)
    {
        slew::bridge::RotctldServer server(m_session);
        QString error;
        QVERIFY2(server.listen(QHostAddress::LocalHost, 0, &error), qPrintable(error));
        QTcpSocket tracker;
        tracker.connectToHost(QHostAddress::LocalHost, server.port());
        QTRY_COMPARE(tracker.state(), QAbstractSocket::ConnectedState);
        for (const QByteArray &request : requests) {
            expectNothingSent(path + request, [&] {
                tracker.write(request);
                QTRY_VERIFY(tracker.canReadLine());
                const QByteArray answer = tracker.readLine();
                QVERIFY2(answer.startsWith("RPRT -"), (request + " -> " + answer).constData());
            });
        }
    }
    void clickPark() { QTest::mouseClick(m_window->findChild<QPushButton *>(QStringLiteral("parkButton")), Qt::LeftButton); }

    // Runs one path, then checks that no move reached the link. A refusal
    // by the session itself is expected too unless the widget refused first
    // (sessionRefuses false: the widget showed the gate's preview instead).
    void expectNothingSent(const QByteArray &path, const std::function<void()> &act, bool sessionRefuses = true)
    {
        QSignalSpy refused(m_session, &RotatorSession::moveRefused);
        const qsizetype mark = m_device->written.size();
        act();
        if (QTest::currentTestFailed()) {
            qWarning("path: %s", path.constData());
            return;
        }
        QCoreApplication::processEvents();
        const QStringList moves = m_device->movesSince(mark);
        QVERIFY2(moves.isEmpty(), qPrintable(QStringLiteral("%1 sent %2").arg(QString::fromLatin1(path), moves.join(u' '))));
        if (sessionRefuses)
            QVERIFY2(refused.count() >= 1, path.constData());
    }

    std::unique_ptr<slew::station::Station> m_station;
    RotatorSession *m_session = nullptr;
    std::unique_ptr<slew::ui::StationWindow> m_window;
    ScriptedDevice *m_device = nullptr;
};

QTEST_MAIN(EveryMoveGatedTest)
#include "tst_everymovegated.moc"
