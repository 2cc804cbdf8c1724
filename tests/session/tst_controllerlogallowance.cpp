// SPDX-License-Identifier: GPL-3.0-or-later
// The two pure pieces behind a flooding controller: the allowance of log
// lines (a burst, then one now and then, the rest counted by kind) and the
// unreadable-replies condition (raised by a stream, not a stray reply;
// cleared only after a quiet window, so mixed replies do not make it flap).

#include "session/controllerlogallowance.h"
#include "session/unreadablereplies.h"

#include <QTest>

using slew::session::ControllerLogAllowance;
using slew::session::UnreadableReplies;
using Kind = ControllerLogAllowance::Kind;

class ControllerLogAllowanceTest : public QObject {
    Q_OBJECT
private slots:
    void aBurstThenCountsThenASummaryWithTheNextLine()
    {
        ControllerLogAllowance log;
        int written = 0;
        for (int i = 0; i < 100000; ++i)
            written += int(log.take(Kind::Unreadable, 0, QStringLiteral("x")).size());
        QCOMPARE(written, int(ControllerLogAllowance::kBurst));
        QCOMPARE(log.heldBack(Kind::Unreadable), 100000 - qint64(ControllerLogAllowance::kBurst));
        QVERIFY(log.holdsBack());
        log.take(Kind::Alarm, 1, QStringLiteral("a"));
        log.take(Kind::Damaged, 2, QStringLiteral("d"));
        // The allowance refills: the next line comes after the summary.
        const QStringList lines = log.take(Kind::Unreadable, qint64(1000 / ControllerLogAllowance::kPerSecond) + 10,
                                           QStringLiteral("next"));
        QCOMPARE(lines, QStringList({QStringLiteral("99990 more unreadable replies, 1 more alarm, 1 more damaged reply "
                                                    "from the controller suppressed"),
                                     QStringLiteral("next")}));
        QVERIFY(!log.holdsBack());
        QVERIFY(log.takeSummary().isEmpty());
    }

    void aSummaryOnItsOwn()
    {
        ControllerLogAllowance log;
        for (int i = 0; i < 11; ++i)
            log.take(Kind::Unreadable, 0, QStringLiteral("x"));
        QCOMPARE(log.takeSummary(), QStringLiteral("1 more unreadable reply from the controller suppressed"));
        QVERIFY(log.takeSummary().isEmpty());
    }

    void aStreamRaisesOnceAStrayReplyDoesNot()
    {
        UnreadableReplies u;
        // One every two seconds for a minute: never ten within ten seconds.
        for (int s = 0; s < 60; s += 2)
            QVERIFY(!u.noteUnreadable(s * 1000 + 999 * (s % 4 == 0)));
        QVERIFY(!u.raised());
        u.reset();
        int raised = 0;
        for (int i = 0; i < 100000; ++i) {
            raised += u.noteUnreadable(i / 100); // 100 a millisecond, for a second
            QVERIFY(!u.noteReadable(i / 100)); // readable replies among them do not clear it
        }
        QCOMPARE(raised, 1);
        QVERIFY(u.raised());
        QVERIFY(u.inWindow(999) >= UnreadableReplies::kRaiseAt);
    }

    void clearsAfterAQuietWindowOfReadableReplies()
    {
        UnreadableReplies u;
        for (int i = 0; i < UnreadableReplies::kRaiseAt; ++i)
            u.noteUnreadable(5000);
        QVERIFY(u.raised());
        QVERIFY(!u.noteReadable(5000 + UnreadableReplies::kWindowSeconds * 1000 - 1));
        QVERIFY(u.noteReadable(5000 + UnreadableReplies::kWindowSeconds * 1000));
        QVERIFY(!u.raised());
        QVERIFY(!u.noteReadable(99999));
        QCOMPARE(u.inWindow(5000), 0);
    }
};

QTEST_GUILESS_MAIN(ControllerLogAllowanceTest)
#include "tst_controllerlogallowance.moc"
