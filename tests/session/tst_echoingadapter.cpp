// SPDX-License-Identifier: GPL-3.0-or-later
// Some serial adapters hand every byte the host sends straight back, ahead
// of the controller's answer. The session must behave the same with such an
// adapter as without it. The simulator plays one (`echo=1`), and the same
// script runs with and without it in each dialect: probe, version, a
// register read, a go-to driven to arrival on the simulator's manual clock,
// a register write read back, a stop. What the session concluded is then
// compared; only the count of echoes it set aside may differ.

#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "session/rotatorsession.h"

#include <QSignalSpy>
#include <QTest>

#include <QPointF>

#include <cmath>
#include <optional>

using slew::session::RotatorSession;

namespace {

// What one run of the script found out, as text that compares whole.
struct Outcome {
    QStringList facts;
    int echoesIgnored = 0;
};

QString describe(const slew::session::Capabilities &c)
{
    return QStringLiteral("position %1 version %2 status %3 errors %4 inputs %5 config %6 encoders %7")
        .arg(c.positionFeedback)
        .arg(c.version)
        .arg(c.status)
        .arg(c.errors)
        .arg(c.inputs)
        .arg(c.config)
        .arg(c.encoders);
}

} // namespace

class EchoingAdapterTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { slew::registerLinkSchemes(); }

    void theSessionIsTheSameWithAndWithoutEcho_data()
    {
        QTest::addColumn<QString>("dialect");
        for (const char *d : {"easycomm2", "easycomm3", "satnogs", "gs232b"})
            QTest::newRow(d) << QString::fromLatin1(d);
    }

    void theSessionIsTheSameWithAndWithoutEcho()
    {
        QFETCH(QString, dialect);
        const Outcome plain = runScript(dialect, false);
        if (QTest::currentTestFailed())
            return;
        const Outcome echoed = runScript(dialect, true);
        if (QTest::currentTestFailed())
            return;
        qInfo("%s", qPrintable(plain.facts.join(QStringLiteral(" | "))));
        QCOMPARE(echoed.facts, plain.facts);
        QCOMPARE(plain.echoesIgnored, 0);
        QVERIFY2(echoed.echoesIgnored > 0, "the echo never reached the session");
    }

private:
    Outcome runScript(const QString &dialect, bool echo)
    {
        Outcome out;
        const QString uri = QStringLiteral("sim:?clock=manual&dialect=%1&start_az=10&start_el=5%2")
                                .arg(dialect, echo ? QStringLiteral("&echo=1") : QString());
        RotatorSession session;
        slew::model::RotatorProfile profile;
        profile.dialect = *slew::protocol::dialectFromName(dialect);
        session.setProfile(profile);
        QSignalSpy refused(&session, &RotatorSession::commandRefused);
        QSignalSpy failed(&session, &RotatorSession::requestFailed);
        QSignalSpy errors(&session, &RotatorSession::errorOccurred);
        QSignalSpy alarms(&session, &RotatorSession::alarmReceived);
        // The registers the script reads (telemetry polls others, as often
        // as the wall clock allows, which differs from run to run).
        QStringList values;
        connect(&session, &RotatorSession::configValueReceived, this, [&values](int reg, const QString &value) {
            if (reg == 1 || reg == 7)
                values << QStringLiteral("CR%1 = %2").arg(reg).arg(value);
        });
        // 50 ms of simulated time each time the event loop comes round, and
        // runEventLoopUntil keeps it coming round: the go-to's few simulated
        // seconds pass in a blink. From the start: a half-duplex line's
        // turn-around (satnogs) is simulated time too.
        SimulatorPump pump(0.05);
        session.connectTo(uri);
        pump.drive(slew::sim::simulatorBehind(session.link()));
        if (!runEventLoopUntil([&] { return session.capabilities().probed && session.hasPosition(); }, 10000)) {
            QTest::qFail(qPrintable(QStringLiteral("%1: no probe or position").arg(uri)), __FILE__, __LINE__);
            return out;
        }
        out.facts << describe(session.capabilities()) << QStringLiteral("version %1").arg(session.version());
        out.facts << QStringLiteral("at %1 %2").arg(session.azimuth(), 0, 'f', 1).arg(session.elevation(), 0, 'f', 1);

        const bool registers = session.capabilities().config;
        if (registers) {
            session.readConfig(1);
            if (!runEventLoopUntil([&] { return !values.filter(QStringLiteral("CR1 =")).isEmpty(); }, 5000))
                out.facts << QStringLiteral("CR1 unanswered");
        }
        // An echoed `AZ30 EL20` taken for a report would put the antenna at
        // the target the moment the command left.
        std::optional<QPointF> firstAfterGoto;
        connect(&session, &RotatorSession::positionChanged, this, [&](double az, double el, bool stale) {
            if (!stale && !firstAfterGoto && session.targetAzimuth() == 30)
                firstAfterGoto = QPointF(az, el);
        });
        if (!session.gotoPosition(30, 20))
            out.facts << QStringLiteral("go-to refused");
        const bool arrived = runEventLoopUntil(
            [&] {
                return !session.positionStale() && std::abs(session.azimuth() - 30) < 0.2
                    && std::abs(session.elevation() - 20) < 0.2;
            },
            20000);
        out.facts << QStringLiteral("first position after the go-to short of the target: %1")
                         .arg(firstAfterGoto && firstAfterGoto->x() < 25 && firstAfterGoto->y() < 18);
        out.facts << QStringLiteral("arrived %1 at %2 %3")
                         .arg(arrived)
                         .arg(session.azimuth(), 0, 'f', 0)
                         .arg(session.elevation(), 0, 'f', 0);
        if (registers) {
            session.writeConfig(7, QStringLiteral("45"));
            session.readConfig(7);
            if (!runEventLoopUntil([&] { return !values.filter(QStringLiteral("CR7 =")).isEmpty(); }, 5000))
                out.facts << QStringLiteral("CR7 unanswered");
        }
        out.facts << values;
        out.facts << QStringLiteral("stop %1").arg(bool(session.stop(QStringLiteral("the test"))));
        pump.pause();
        out.facts << QStringLiteral("refused %1, failed %2, errors %3, alarms %4")
                         .arg(refused.count())
                         .arg(failed.count())
                         .arg(errors.count())
                         .arg(alarms.count());
        for (const QList<QVariant> &e : errors)
            out.facts << e.at(0).toString();
        for (const QList<QVariant> &f : failed)
            out.facts << f.at(0).toString() + QStringLiteral(": ") + f.at(1).toString();
        out.echoesIgnored = session.echoesIgnored();
        session.disconnectFromRotator();
        return out;
    }
};

QTEST_GUILESS_MAIN(EchoingAdapterTest)
#include "tst_echoingadapter.moc"
