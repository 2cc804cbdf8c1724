// SPDX-License-Identifier: GPL-3.0-or-later
// The window's alarm monitor and a controller whose replies turn to garbage:
// one keyed alarm ("Unreadable replies") raised once however long the
// garbage lasts, a bounded event log, and the alarm cleared once readable
// replies have come back; a position that never reads is an alarm too. The
// fake controller keeps its own clock, moved by the event loop
// (tests/session/fakedevice.h); nothing sleeps.

#include "../common/simulatorpump.h"
#include "../session/fakedevice.h"
#include "station/alarmmonitor.h"
#include "session/rotatorsession.h"

#include <QSignalSpy>
#include <QTest>

using slew::session::RotatorSession;
using slew::station::AlarmMonitor;

class UnreadableAlarmTest : public QObject {
    Q_OBJECT
private slots:
    void garbageIsOneAlarmThatClears()
    {
        FakeDevice device;
        RotatorSession s;
        AlarmMonitor monitor(&s);
        s.connectTo(device.uri());
        TRY_VERIFY(s.isConnected() && s.capabilities().probed && s.hasPosition());

        QSignalSpy events(&monitor, &AlarmMonitor::eventLogged);
        auto alarmsRaised = [&] {
            int n = 0;
            for (const QList<QVariant> &e : events)
                n += e.at(1).value<AlarmMonitor::Severity>() == AlarmMonitor::Severity::Alarm
                     && e.at(2).toString().startsWith(QStringLiteral("Unreadable replies"));
            return n;
        };
        // Each readable reply among the garbage is used (the fake's own
        // answers to polls come in between, so every position is looked for).
        QSignalSpy positions(&s, &RotatorSession::positionChanged);
        auto seen = [&](double az) {
            for (const QList<QVariant> &p : positions) {
                if (std::abs(p.at(0).toDouble() - az) < 0.05)
                    return true;
            }
            return false;
        };
        for (int k = 0; k < 20; ++k) {
            QByteArray chunk;
            for (int i = 0; i < 1000; ++i)
                chunk += "#garbage\x1b]0;" + QByteArray::number(i) + "\n";
            device.push(chunk + "AZ" + QByteArray::number(50 + k) + ".0 EL30.0\n");
            TRY_VERIFY(seen(50 + k));
        }
        QCOMPARE(alarmsRaised(), 1);
        QVERIFY(monitor.isActive(QStringLiteral("unreadable")));
        QVERIFY(monitor.anySevere());
        QVERIFY2(events.size() <= 15, qPrintable(QString::number(events.size())));

        // Readable replies only, for longer than the condition's window.
        TRY_VERIFY_WITH_TIMEOUT(!monitor.isActive(QStringLiteral("unreadable")), 30000);
        QCOMPARE(alarmsRaised(), 1);
        QVERIFY(monitor.activeAlarms().isEmpty());
    }

    void aPositionItCannotReadIsAnAlarm()
    {
        // K3NG's GS-232B report on an Easycomm link: connected, and nothing
        // it sends can move the antenna. One alarm in the refusal's words,
        // cleared when a position is read at last.
        FakeDevice device;
        bool wrongDialect = true;
        device.script = [&](const QByteArray &line) -> QByteArray {
            if (line == "AZ EL")
                return wrongDialect ? QByteArray("AZ=059EL=025\n") : QByteArray("AZ59.0 EL25.0\n");
            return {};
        };
        RotatorSession s;
        AlarmMonitor monitor(&s);
        s.connectTo(device.uri());
        TRY_VERIFY(s.isConnected() && s.capabilities().probed);
        QVERIFY(monitor.isActive(QStringLiteral("no-position")));
        QVERIFY(monitor.anySevere());
        QVERIFY2(monitor.activeAlarms().contains(QStringLiteral("No position read from the controller: check the dialect (easycomm3)")),
                 qPrintable(monitor.activeAlarms().join(u'\n')));
        wrongDialect = false;
        TRY_VERIFY_WITH_TIMEOUT(!monitor.isActive(QStringLiteral("no-position")), 30000);
        QVERIFY(s.hasPosition());
    }
};

QTEST_GUILESS_MAIN(UnreadableAlarmTest)
#include "tst_unreadablealarm.moc"
