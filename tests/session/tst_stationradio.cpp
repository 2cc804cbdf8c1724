// SPDX-License-Identifier: GPL-3.0-or-later
// The Easycomm station commands for the radios (UP, DN, UM, DM) through a
// session, against the simulator, which keeps and answers them as the
// protocol tables say.

#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "session/controllerradiocommands.h"
#include "session/rotatorsession.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

using slew::protocol::Dialect;
using slew::session::ControllerRadioCommands;
using slew::session::RotatorSession;
using Path = ControllerRadioCommands::Path;

class ControllerRadioCommandsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void setsAndReadsFrequenciesAndModes()
    {
        RotatorSession s;
        QVERIFY(open(s, Dialect::Easycomm2));
        ControllerRadioCommands *radio = s.radioCommands();
        QVERIFY(radio->isSupported());
        QVERIFY(radio->canRead());
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QSignalSpy reported(radio, &ControllerRadioCommands::frequencyReported);

        QVERIFY(radio->setFrequency(Path::Uplink, 145900012.4));
        QVERIFY(radio->setFrequency(Path::Downlink, 435150000));
        QVERIFY(radio->setMode(Path::Downlink, QStringLiteral("usb")));
        QVERIFY(wrote(sent, "UP145900012"));
        QVERIFY(wrote(sent, "DN435150000"));
        QVERIFY(wrote(sent, "DMUSB"));

        QVERIFY(radio->readFrequency(Path::Uplink));
        QVERIFY(radio->readFrequency(Path::Downlink));
        QVERIFY(runEventLoopUntil([&] { return reported.count() >= 2; }, 5000));
        QCOMPARE(reported.at(0).at(0).value<Path>(), Path::Uplink);
        QCOMPARE(reported.at(0).at(1).toDouble(), 145900012.0);
        QCOMPARE(reported.at(1).at(0).value<Path>(), Path::Downlink);
        QCOMPARE(reported.at(1).at(1).toDouble(), 435150000.0);
    }

    void refusesWhatCannotBeSent()
    {
        RotatorSession s;
        QVERIFY(open(s, Dialect::Easycomm2));
        ControllerRadioCommands *radio = s.radioCommands();
        QSignalSpy sent(&s, &RotatorSession::bytesSent);
        QSignalSpy refused(&s, &RotatorSession::commandRefused);
        QVERIFY(!radio->setFrequency(Path::Uplink, std::nan("")));
        QVERIFY(!radio->setFrequency(Path::Uplink, 0));
        QVERIFY(!radio->setFrequency(Path::Uplink, 1e10)); // eleven digits
        QVERIFY(!radio->setMode(Path::Uplink, QStringLiteral("U SB")));
        QVERIFY(!radio->setMode(Path::Uplink, QStringLiteral("AVERYLONGMODE")));
        QCOMPARE(refused.count(), 5);
        for (const auto &args : sent)
            QVERIFY2(!args.at(0).toByteArray().startsWith('U'), args.at(0).toByteArray().constData());
    }

    void easycommOneTakesSettingsButAnswersNothing()
    {
        RotatorSession s;
        QVERIFY(open(s, Dialect::Easycomm1));
        ControllerRadioCommands *radio = s.radioCommands();
        QVERIFY(radio->isSupported());
        QVERIFY(!radio->canRead());
        QVERIFY(radio->setFrequency(Path::Downlink, 437800000));
        QVERIFY(!radio->readFrequency(Path::Downlink));
    }

    void aControllerWithoutThemRefuses()
    {
        RotatorSession s;
        QVERIFY(open(s, Dialect::Gs232B));
        QVERIFY(!s.radioCommands()->isSupported());
        QVERIFY(!s.radioCommands()->setFrequency(Path::Uplink, 145.9e6));
    }

private:
    static bool open(RotatorSession &s, Dialect dialect)
    {
        slew::model::RotatorProfile profile;
        profile.dialect = dialect;
        s.setProfile(profile);
        s.connectTo(QStringLiteral("sim:?clock=manual&dialect=%1").arg(slew::protocol::dialectName(dialect)));
        (new SimulatorPump(0.005, &s))->follow(&s);
        return runEventLoopUntil([&] { return s.isConnected() && s.capabilities().probed; }, 10000);
    }

    static bool wrote(const QSignalSpy &sent, const QByteArray &start)
    {
        for (const auto &args : sent) {
            if (args.at(0).toByteArray().startsWith(start))
                return true;
        }
        return false;
    }
};

QTEST_GUILESS_MAIN(ControllerRadioCommandsTest)
#include "tst_stationradio.moc"
