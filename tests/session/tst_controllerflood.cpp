// SPDX-License-Identifier: GPL-3.0-or-later
// A faulty controller that floods the line with replies nobody can read:
// Easycomm lines of garbage (escape sequences and bells among them), SPID
// frames whose digits are out of range, and random bytes, tens of thousands
// of each, with a readable position reply between every thousand. The
// session's error lines stay a burst and summaries whose counts add up to
// every unreadable reply; no control character reaches them; the condition
// is raised once and cleared once readable replies have come back for a
// while; and every readable reply among the garbage moves the position.
//
// The fake controller's clock moves 5 ms each time the event loop comes
// round (fakedevice.h): the flood takes well under a simulated second, and
// the waits for the alarm to clear and for the summary step through
// simulated seconds, never the wall clock.

#include "../common/simulatorpump.h"
#include "fakedevice.h"
#include "protocol/parser.h"
#include "protocol/spidcodec.h"
#include "session/rotatorsession.h"

#include <QRandomGenerator>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>

#include <cmath>

using slew::protocol::Dialect;
using slew::session::RotatorSession;
namespace spid = slew::protocol::spid;

namespace {

constexpr int kChunks = 30;

// The unreadable replies a parser of this dialect finds in these bytes:
// what the session must account for, line by line or in a summary.
qint64 unreadableIn(const QByteArray &bytes, Dialect d)
{
    slew::protocol::Parser parser(d);
    qint64 n = 0;
    parser.feed(bytes, [&](const slew::protocol::Message &m) { n += m.op == slew::protocol::Op::Invalid; });
    return n;
}

// Error lines that name one unreadable reply, and the counts the summaries give.
qint64 accountedFor(const QStringList &lines)
{
    static const QRegularExpression summary(QStringLiteral("^(\\d+) more unreadable repl(y|ies)\\b.*from the controller suppressed$"));
    qint64 n = 0;
    for (const QString &line : lines) {
        if (line.startsWith(QStringLiteral("unreadable reply")))
            ++n;
        else if (const QRegularExpressionMatch m = summary.match(line); m.hasMatch())
            n += m.captured(1).toLongLong();
    }
    return n;
}

bool hasControlCharacters(const QString &line)
{
    for (const QChar c : line) {
        const char16_t u = c.unicode();
        if (u < 0x20 || (u >= 0x7f && u < 0xa0))
            return true;
    }
    return false;
}

bool hasPosition(const QSignalSpy &positions, double az, double el)
{
    for (const QList<QVariant> &args : positions) {
        if (std::abs(args.at(0).toDouble() - az) < 0.05 && std::abs(args.at(1).toDouble() - el) < 0.05)
            return true;
    }
    return false;
}

} // namespace

class ControllerFloodTest : public QObject {
    Q_OBJECT
private slots:
    void easycommGarbageIsABurstSummariesAndOneAlarm();
    void spidFramesOutOfRangeAreABurstSummariesAndOneAlarm();
    void randomBytesAreABurstSummariesAndOneAlarm();

private:
    // Connects, floods with what garbage(k) gives between readable replies,
    // and checks everything the header promises. `good(k)` is the readable
    // reply after chunk k, at position (100 + k, 10 + k).
    void flood(Dialect d, const std::function<QByteArray(int)> &garbage, const std::function<QByteArray(int)> &good,
               const std::function<QByteArray(const QByteArray &)> &binaryAnswer = {});
};

void ControllerFloodTest::flood(Dialect d, const std::function<QByteArray(int)> &garbage,
                                const std::function<QByteArray(int)> &good,
                                const std::function<QByteArray(const QByteArray &)> &binaryAnswer)
{
    FakeDevice device;
    device.binary = binaryAnswer;
    RotatorSession s;
    slew::model::RotatorProfile profile;
    profile.dialect = d;
    s.setProfile(profile);
    s.connectTo(device.uri());
    TRY_VERIFY(s.isConnected() && s.capabilities().probed && s.hasPosition());

    QStringList errors;
    connect(&s, &RotatorSession::errorOccurred, &s, [&](const QString &m) { errors << m; });
    // By name, so this test builds (and fails) on a session without it.
    QSignalSpy alarm(&s, SIGNAL(unreadableRepliesAlarm(bool,QString)));
    QSignalSpy positions(&s, &RotatorSession::positionChanged);

    QByteArray everything;
    for (int k = 0; k < kChunks; ++k) {
        const QByteArray bytes = garbage(k) + good(k);
        everything += bytes;
        const qsizetype before = positions.size();
        device.push(bytes);
        // The readable reply at the end of the chunk is used: the position moves.
        TRY_VERIFY(positions.size() > before && hasPosition(positions, 100 + k, 10 + k));
    }
    const qint64 unreadable = unreadableIn(everything, d);
    QVERIFY2(unreadable >= 20000, qPrintable(QString::number(unreadable)));
    for (int k = 0; k < kChunks; ++k)
        QVERIFY2(hasPosition(positions, 100 + k, 10 + k), qPrintable(QStringLiteral("readable reply %1 lost").arg(k)));

    // The flood took well under a simulated second: a burst, and not more.
    const qsizetype duringFlood = errors.size();
    QVERIFY2(duringFlood <= 12, qPrintable(QStringLiteral("%1 lines for %2 unreadable replies; first: %3")
                                                .arg(duringFlood).arg(unreadable).arg(errors.value(0))));
    QVERIFY2(alarm.isValid(), "the session has no unreadableRepliesAlarm(bool, QString) signal");
    QCOMPARE(alarm.size(), 1);
    QCOMPARE(alarm.at(0).at(0).toBool(), true);
    QVERIFY2(alarm.at(0).at(1).toString().contains(QStringLiteral("unreadable")), qPrintable(alarm.at(0).at(1).toString()));

    // The garbage stops; polls bring readable replies. The condition clears
    // once, and what was held back is reported: every unreadable reply is
    // accounted for, in a few lines.
    TRY_VERIFY_WITH_TIMEOUT(alarm.size() == 2 && accountedFor(errors) >= unreadable, 60000);
    QCOMPARE(alarm.at(1).at(0).toBool(), false);
    QCOMPARE(accountedFor(errors), unreadable);
    QVERIFY2(errors.size() <= duringFlood + 2, qPrintable(errors.join(QLatin1Char('\n'))));
    for (const QString &line : std::as_const(errors)) {
        QVERIFY2(!hasControlCharacters(line), qPrintable(line.toLatin1().toPercentEncoding(" '")));
        QVERIFY2(line.size() <= 200, qPrintable(line));
    }
    qInfo("%lld unreadable replies: %lld error lines", unreadable, qint64(errors.size()));
}

void ControllerFloodTest::easycommGarbageIsABurstSummariesAndOneAlarm()
{
    flood(
        Dialect::Easycomm3,
        [](int k) {
            QByteArray chunk;
            for (int i = 0; i < 1000; ++i)
                chunk += "Q\x1b[31mZ" + QByteArray::number(k * 1000 + i) + "\x07\n";
            return chunk;
        },
        [](int k) { return "AZ" + QByteArray::number(100 + k) + ".0 EL" + QByteArray::number(10 + k) + ".0\n"; });
}

void ControllerFloodTest::spidFramesOutOfRangeAreABurstSummariesAndOneAlarm()
{
    // Well-formed Rot2Prog replies whose azimuth digits read 9999: 639.9°,
    // outside the SPID range.
    QByteArray outOfRange = spid::encodeReply(10, 20, Dialect::Rot2Prog, 2, 2);
    for (int i = 1; i <= 4; ++i)
        outOfRange[i] = 9;
    flood(
        Dialect::Rot2Prog, [&](int) { return outOfRange.repeated(1000); },
        [](int k) { return spid::encodeReply(100 + k, 10 + k, Dialect::Rot2Prog, 2, 2); },
        [](const QByteArray &bytes) {
            // Polls are answered with the position the last chunk left.
            return bytes == spid::encodeStatus() ? spid::encodeReply(10, 20, Dialect::Rot2Prog, 2, 2) : QByteArray();
        });
}

void ControllerFloodTest::randomBytesAreABurstSummariesAndOneAlarm()
{
    QRandomGenerator random(25);
    flood(
        Dialect::Easycomm3,
        [&](int) {
            QByteArray chunk(8000, Qt::Uninitialized);
            // No '?': a lone `?` or `?>` is a controller's refusal, not
            // garbage (docs/protocol.md, "Controllers in the field").
            for (char &c : chunk)
                do
                    c = char(random.bounded(256));
                while (c == '?');
            // Each chunk ends a line, so the readable reply after it is one.
            for (char &c : chunk) // lines short enough to be read, not refused as overlong
                if (random.bounded(8) == 0)
                    c = '\n';
            return chunk + '\n';
        },
        [](int k) { return "AZ" + QByteArray::number(100 + k) + ".0 EL" + QByteArray::number(10 + k) + ".0\n"; });
}

QTEST_GUILESS_MAIN(ControllerFloodTest)
#include "tst_controllerflood.moc"
