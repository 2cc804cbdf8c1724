// SPDX-License-Identifier: GPL-3.0-or-later
// The pacer every radio link shares: one command on the wire, the newest of
// each kind replacing a waiting one in its place, follow-ups ahead of the
// line, and a minimum interval from one command's end to the next's start.

#include "radio/commandpacer.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include <algorithm>

using namespace slew::radio;

class CommandPacerTest : public QObject {
    Q_OBJECT
private slots:
    void sendsAtOnceWhenIdle();
    void oneOnTheWireNewestOfEachKindWaits();
    void followUpGoesAheadOfTheLine();
    void minimumIntervalFromEndToStart();
    void synchronousAnswersDoNotRecurse();
    void clearForgetsEverything();
    void dropWaitingKeepsTheExchangeOnTheWire();
};

namespace {

QStringList texts(const QSignalSpy &spy)
{
    QStringList out;
    for (const QList<QVariant> &args : spy)
        out << args.at(0).value<PacedCommand>().text;
    return out;
}

} // namespace

void CommandPacerTest::sendsAtOnceWhenIdle()
{
    CommandPacer pacer;
    QSignalSpy ready(&pacer, &CommandPacer::ready);
    pacer.submit({CommandKind::ReceiveFrequency, "F 1", 7});
    QCOMPARE(ready.count(), 1);
    const PacedCommand sent = ready.at(0).at(0).value<PacedCommand>();
    QCOMPARE(sent.text, QStringLiteral("F 1"));
    QCOMPARE(sent.tag, 7); // handed back untouched
    QVERIFY(pacer.isBusy());
}

void CommandPacerTest::oneOnTheWireNewestOfEachKindWaits()
{
    CommandPacer pacer;
    QSignalSpy ready(&pacer, &CommandPacer::ready);
    pacer.submit({CommandKind::ReceiveFrequency, "F 1"});
    // While F 1 is out: a hundred receive frequencies, a mode, two transmit
    // frequencies and a read.
    for (int i = 2; i <= 100; ++i)
        pacer.submit({CommandKind::ReceiveFrequency, QStringLiteral("F %1").arg(i)});
    pacer.submit({CommandKind::Mode, "M FM 0"});
    pacer.submit({CommandKind::TransmitFrequency, "I 1"});
    pacer.submit({CommandKind::TransmitFrequency, "I 2"});
    pacer.submit({CommandKind::Read, "f"});
    QCOMPARE(ready.count(), 1);         // one on the wire
    QCOMPARE(pacer.waitingCount(), 4);  // one per kind
    QCOMPARE(pacer.replacedCount(), 99); // 98 receive, 1 transmit
    // A receive frequency given now replaces F 100 where it stands: first in line.
    pacer.submit({CommandKind::ReceiveFrequency, "F 101"});
    for (int i = 0; i < 4; ++i)
        pacer.finished();
    QCOMPARE(texts(ready), (QStringList{"F 1", "F 101", "M FM 0", "I 2", "f"}));
    pacer.finished();
    QVERIFY(!pacer.isBusy());
    QCOMPARE(pacer.waitingCount(), 0);
}

void CommandPacerTest::followUpGoesAheadOfTheLine()
{
    CommandPacer pacer;
    QSignalSpy ready(&pacer, &CommandPacer::ready);
    pacer.submit({CommandKind::Read, "f"});
    pacer.submit({CommandKind::ReceiveFrequency, "F 5"});
    pacer.submit({CommandKind::Read, "f"}); // a second read waits as any other
    pacer.finished(PacedCommand{CommandKind::Read, "i"});
    pacer.finished();
    pacer.finished();
    QCOMPARE(texts(ready), (QStringList{"f", "i", "F 5", "f"}));
}

void CommandPacerTest::minimumIntervalFromEndToStart()
{
    CommandPacer pacer;
    pacer.setMinimumIntervalMs(60);
    QElapsedTimer clock;
    clock.start();
    QList<qint64> sentAt;
    qint64 finishedAt = -1;
    QList<qint64> quiet; // from each finish to the next start
    connect(&pacer, &CommandPacer::ready, this, [&](const PacedCommand &) {
        sentAt << clock.elapsed();
        if (finishedAt >= 0)
            quiet << sentAt.last() - finishedAt;
        // The peer answers on the next turn of the loop.
        QTimer::singleShot(0, &pacer, [&] {
            finishedAt = clock.elapsed();
            pacer.finished();
        });
    });
    pacer.submit({CommandKind::ReceiveFrequency, "F 1"});
    pacer.submit({CommandKind::TransmitFrequency, "I 1"});
    pacer.submit({CommandKind::Mode, "M FM 0"});
    pacer.submit({CommandKind::Split, "S 1 VFOB"});
    QTRY_COMPARE(sentAt.size(), 4);
    QTRY_VERIFY(!pacer.isBusy());
    QCOMPARE(quiet.size(), 3);
    for (const qint64 q : quiet)
        QVERIFY2(q >= 60, qPrintable(QString::number(q)));
    QVERIFY(sentAt.first() < 60); // the first left at once
}

void CommandPacerTest::synchronousAnswersDoNotRecurse()
{
    // A link that answers inside ready() (libhamlib in process) finishes
    // each command before ready() returns.
    CommandPacer pacer;
    int depth = 0, deepest = 0, sent = 0;
    connect(&pacer, &CommandPacer::ready, this, [&](const PacedCommand &) {
        ++depth;
        deepest = std::max(deepest, depth);
        ++sent;
        pacer.finished();
        --depth;
    });
    pacer.submit({CommandKind::ReceiveFrequency, "F 1"});
    pacer.submit({CommandKind::TransmitFrequency, "I 1"});
    QCOMPARE(sent, 2);
    QCOMPARE(deepest, 1);
}

void CommandPacerTest::clearForgetsEverything()
{
    CommandPacer pacer;
    pacer.setMinimumIntervalMs(1000);
    QSignalSpy ready(&pacer, &CommandPacer::ready);
    pacer.submit({CommandKind::ReceiveFrequency, "F 1"});
    pacer.submit({CommandKind::Mode, "M FM 0"});
    pacer.clear();
    QVERIFY(!pacer.isBusy());
    QCOMPARE(pacer.waitingCount(), 0);
    pacer.finished(); // a late answer to the forgotten command does nothing
    QCOMPARE(ready.count(), 1);
    // A new connection starts without waiting out the old interval.
    pacer.submit({CommandKind::Read, "f"});
    QCOMPARE(ready.count(), 2);
}

void CommandPacerTest::dropWaitingKeepsTheExchangeOnTheWire()
{
    CommandPacer pacer;
    QSignalSpy ready(&pacer, &CommandPacer::ready);
    pacer.submit({CommandKind::Read, "f"});
    pacer.submit({CommandKind::ReceiveFrequency, "F 1"});
    pacer.submit({CommandKind::TransmitFrequency, "I 2"});
    pacer.dropWaiting();
    QCOMPARE(pacer.waitingCount(), 0);
    QVERIFY(pacer.isBusy()); // the read on the wire finishes...
    pacer.finished(PacedCommand{CommandKind::Read, "i"});
    QCOMPARE(ready.count(), 2); // ...its second half included
    QCOMPARE(ready.at(1).at(0).value<PacedCommand>().text, QStringLiteral("i"));
    pacer.finished();
    QCOMPARE(ready.count(), 2); // and nothing that waited follows
    QVERIFY(!pacer.isBusy());
}

QTEST_GUILESS_MAIN(CommandPacerTest)
#include "tst_commandpacer.moc"
