// SPDX-License-Identifier: GPL-3.0-or-later
// transport::DescriptorSet on socket pairs: only the ready descriptors'
// handlers run, what is left unread is reported again, writability only
// when asked for, and a descriptor removed by a handler of the same turn is
// not reported.

#include "transport/descriptorset.h"

#include <QCoreApplication>
#include <QTest>

#include <sys/socket.h>
#include <unistd.h>

#include <array>

using slew::transport::DescriptorSet;

namespace {

struct SocketPair {
    std::array<int, 2> fd{-1, -1};
    SocketPair() { ::socketpair(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0, fd.data()); }
    ~SocketPair()
    {
        for (int f : fd)
            ::close(f);
    }
};

} // namespace

namespace {

// Absence is shown by turns of the event loop, not by time: a descriptor
// still ready (level-triggered) would be reported on every turn.
void turnEventLoop(int turns)
{
    for (int i = 0; i < turns; ++i)
        QCoreApplication::processEvents(QEventLoop::AllEvents);
}

} // namespace

class DescriptorSetTest : public QObject {
    Q_OBJECT
private slots:
    void onlyTheReadyOnesRun();
    void whatIsLeftUnreadIsReportedAgain();
    void writableOnlyWhenAskedFor();
    void removedInTheSameTurnIsNotReported();
};

void DescriptorSetTest::onlyTheReadyOnesRun()
{
    DescriptorSet set;
    QVERIFY(set.isValid());
    SocketPair a, b;
    int aEvents = 0, bEvents = 0;
    QVERIFY(set.add(a.fd[0], DescriptorSet::Readable, [&](int e) { aEvents |= e; }) != 0);
    QVERIFY(set.add(b.fd[0], DescriptorSet::Readable, [&](int e) { bEvents |= e; }) != 0);
    QCOMPARE(::write(a.fd[1], "x", 1), 1);
    QTRY_COMPARE(aEvents, int(DescriptorSet::Readable));
    QCOMPARE(bEvents, 0);
}

void DescriptorSetTest::whatIsLeftUnreadIsReportedAgain()
{
    DescriptorSet set;
    SocketPair a;
    int calls = 0;
    set.add(a.fd[0], DescriptorSet::Readable, [&](int) { ++calls; });
    QCOMPARE(::write(a.fd[1], "x", 1), 1);
    QTRY_VERIFY(calls >= 3); // never read
    char byte = 0;
    QCOMPARE(::read(a.fd[0], &byte, 1), 1);
    turnEventLoop(5); // a report already queued before the read
    const int settled = calls;
    turnEventLoop(50);
    QCOMPARE(calls, settled);
}

void DescriptorSetTest::writableOnlyWhenAskedFor()
{
    DescriptorSet set;
    SocketPair a;
    int events = 0;
    const quint64 key = set.add(a.fd[0], DescriptorSet::Readable, [&](int e) { events |= e; });
    turnEventLoop(50);
    QCOMPARE(events, 0);
    set.watch(key, DescriptorSet::Readable | DescriptorSet::Writable);
    QTRY_COMPARE(events, int(DescriptorSet::Writable));
    set.watch(key, DescriptorSet::Readable);
    events = 0;
    turnEventLoop(50);
    QCOMPARE(events, 0);
}

void DescriptorSetTest::removedInTheSameTurnIsNotReported()
{
    DescriptorSet set;
    SocketPair a, b;
    quint64 aKey = 0, bKey = 0;
    int aCalls = 0, bCalls = 0;
    // Whichever runs first removes the other, and both are ready at once.
    aKey = set.add(a.fd[0], DescriptorSet::Readable, [&](int) {
        ++aCalls;
        set.remove(bKey);
        set.remove(aKey);
    });
    bKey = set.add(b.fd[0], DescriptorSet::Readable, [&](int) {
        ++bCalls;
        set.remove(aKey);
        set.remove(bKey);
    });
    QCOMPARE(::write(a.fd[1], "x", 1), 1);
    QCOMPARE(::write(b.fd[1], "x", 1), 1);
    QTRY_COMPARE(aCalls + bCalls, 1);
    turnEventLoop(50);
    QCOMPARE(aCalls + bCalls, 1);
}

QTEST_GUILESS_MAIN(DescriptorSetTest)
#include "tst_descriptorset.moc"
