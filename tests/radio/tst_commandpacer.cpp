// SPDX-License-Identifier: GPL-3.0-or-later
// The pacer every radio link shares: one command on the wire, the newest of
// each kind replacing a waiting one in its place, follow-ups ahead of the
// line, and a minimum interval from one command's end to the next's start.
// And the exchange script that drives it for the links that read their
// radio back (rigctld, libhamlib), over a fake backend: the opening, the
// read-back, replacement, refusals and bad readings, giving up, dropping
// what waits, and closing in the middle of an exchange. The same contract
// over the real backends: radiolinkcontract.h.

#include "fakeexchangeperformer.h"
#include "radio/commandpacer.h"
#include "radio/scriptedradiolink.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include <algorithm>
#include <limits>
#include <memory>

using namespace slew::radio;

class CommandPacerTest : public QObject {
    Q_OBJECT
private slots:
    void sendsAtOnceWhenIdle();
    void oneOnTheWireNewestOfEachKindWaits();
    void followUpGoesAheadOfTheLine();
    void submitFirstGoesAheadOfTheWaiting();
    void minimumIntervalFromEndToStart();
    void synchronousAnswersDoNotRecurse();
    void clearForgetsEverything();
    void dropWaitingKeepsTheExchangeOnTheWire();

    void scriptOpensInOrder_data();
    void scriptOpensInOrder();
    void scriptOpeningFailures();
    void scriptReadsBothFrequenciesWhenSplit();
    void scriptAnswersAReadingFirst();
    void scriptReplacesWaitingCommands();
    void scriptRefusesUnsendableAndWhileClosed();
    void scriptPassesRefusalsOn();
    void scriptRefusesBadReadings_data();
    void scriptRefusesBadReadings();
    void scriptStepBounds_data();
    void scriptStepBounds();
    void scriptGivesUpOnSilence();
    void scriptGivesUpOnALostRadio_data();
    void scriptGivesUpOnALostRadio();
    void scriptDropWaitingFinishesTheExchange();
    void scriptCloseMidExchange();
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

void CommandPacerTest::submitFirstGoesAheadOfTheWaiting()
{
    CommandPacer pacer;
    QSignalSpy ready(&pacer, &CommandPacer::ready);
    pacer.submit({CommandKind::Read, "f"});
    pacer.submit({CommandKind::TransmitFrequency, "I 1"});
    pacer.submit({CommandKind::ReceiveFrequency, "F 1"});
    pacer.submit({CommandKind::Mode, "M FM 0"});
    // Ahead of the line, its older value taken out of its place...
    pacer.submitFirst({CommandKind::ReceiveFrequency, "F 2"});
    QCOMPARE(pacer.waitingCount(), 3);
    QCOMPARE(pacer.replacedCount(), 1);
    // ...but behind an exchange's follow-up.
    pacer.finished(PacedCommand{CommandKind::Read, "i"});
    for (int i = 0; i < 4; ++i)
        pacer.finished();
    QCOMPARE(texts(ready), (QStringList{"f", "i", "F 2", "I 1", "M FM 0"}));
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

// --- The exchange script, over a fake backend ---------------------------------

namespace {

// A script over a fake backend, as a link's owner holds it.
struct ScriptOverFake {
    FakeExchangePerformer *fake;
    std::unique_ptr<ScriptedRadioLink> link;

    ScriptOverFake()
    {
        auto performer = std::make_unique<FakeExchangePerformer>();
        fake = performer.get();
        link = std::make_unique<ScriptedRadioLink>(QStringLiteral("fake:"), std::move(performer));
    }
    // Opened, and what the opening performed forgotten.
    bool opened()
    {
        link->open();
        fake->performed.clear();
        fake->commands.clear();
        return link->isOpen();
    }
};

QStringList firstArguments(const QSignalSpy &spy)
{
    QStringList out;
    for (const QList<QVariant> &args : spy)
        out << args.at(0).toString();
    return out;
}

RadioAnswer refusal(int code, const QString &why)
{
    RadioAnswer a;
    a.code = code;
    a.why = why;
    return a;
}

} // namespace

void CommandPacerTest::scriptOpensInOrder_data()
{
    QTest::addColumn<bool>("mainSub");
    QTest::addColumn<bool>("splitKnown");
    QTest::addColumn<QStringList>("performed");
    // Read, set the same back to time it, the step, and whether split is on.
    QTest::newRow("split") << false << true << QStringList{"f", "F 145800000", "n", "s"};
    // Main and Sub have no split to ask; nor does a peer that cannot say.
    QTest::newRow("main and sub") << true << true << QStringList{"f", "F 145800000", "n"};
    QTest::newRow("split not askable") << false << false << QStringList{"f", "F 145800000", "n"};
}

void CommandPacerTest::scriptOpensInOrder()
{
    QFETCH(bool, mainSub);
    QFETCH(bool, splitKnown);
    QFETCH(QStringList, performed);
    ScriptOverFake s;
    s.fake->splitKnown = splitKnown;
    s.fake->split = QStringLiteral("1");
    if (mainSub)
        QCOMPARE(s.link->setVfoLayout(VfoLayout::MainSub), QString());
    QSignalSpy states(s.link.get(), &RadioLink::stateChanged);
    QSignalSpy sent(s.link.get(), &RadioLink::commandSent);
    QSignalSpy failed(s.link.get(), &RadioLink::commandFailed);
    s.fake->holding = true; // one answer at a time, to see each step
    s.link->open();
    QCOMPARE(s.link->state(), RadioLink::State::Opening);
    QCOMPARE(s.fake->openedWith, mainSub ? VfoLayout::MainSub : VfoLayout::Split);
    for (int i = 0; i < performed.size(); ++i) {
        QCOMPARE(s.fake->performed.size(), i + 1);
        QCOMPARE(s.link->state(), RadioLink::State::Opening);
        s.fake->answerHeld();
    }
    QCOMPARE(s.fake->performed, performed);
    QCOMPARE(firstArguments(sent), performed);
    QCOMPARE(s.link->state(), RadioLink::State::Open);
    QCOMPARE(failed.count(), 0);
    QCOMPARE(s.link->tuningStepHz(), 10.0);
    QCOMPARE(states.count(), 2);
    // Each detail names the link first (radiolink.h).
    QCOMPARE(states.at(0).at(1).toString(), QStringLiteral("fake: reaching the fake radio"));
    QCOMPARE(states.at(1).at(1).toString(),
             QStringLiteral("fake: open at 145.800 000 MHz; a set answered in %1 ms").arg(s.link->latencyMs()));
    // Split found on: a read asks the transmit frequency too. Main and Sub always do.
    s.fake->holding = false;
    s.fake->performed.clear();
    s.link->readFrequencies();
    const QStringList readsBoth{"i", "f"}, readsReceive{"f"}; // the receive frequency last
    QCOMPARE(s.fake->performed, (splitKnown || mainSub) ? readsBoth : readsReceive);
}

void CommandPacerTest::scriptOpeningFailures()
{
    {
        // A radio that cannot say its frequency does not open.
        ScriptOverFake s;
        s.fake->answerOverride = [](const QString &text) -> std::optional<RadioAnswer> {
            if (text == "f")
                return refusal(-6, "refused: RPRT -6 (input/output error)");
            return std::nullopt;
        };
        QSignalSpy states(s.link.get(), &RadioLink::stateChanged);
        s.link->open();
        QCOMPARE(s.link->state(), RadioLink::State::Closed);
        QCOMPARE(states.last().at(1).toString(),
                 QStringLiteral("fake: cannot read the frequency: refused: RPRT -6 (input/output error)"));
        QCOMPARE(s.fake->aborts, 1);
    }
    {
        // Nor one whose frequency is no frequency.
        ScriptOverFake s;
        s.fake->receive = QStringLiteral("nan");
        QSignalSpy states(s.link.get(), &RadioLink::stateChanged);
        s.link->open();
        QCOMPARE(states.last().at(1).toString(),
                 QStringLiteral("fake: cannot read the frequency: unusable answer: 'nan' is not a finite number"));
    }
    {
        // The backend cannot reach it: its words, after the link's name.
        ScriptOverFake s;
        s.fake->holdOpening = true;
        QSignalSpy states(s.link.get(), &RadioLink::stateChanged);
        QSignalSpy failed(s.link.get(), &RadioLink::commandFailed);
        s.link->open();
        s.fake->loseRadio(QStringLiteral("cannot connect"));
        QCOMPARE(s.link->state(), RadioLink::State::Closed);
        QCOMPARE(states.last().at(1).toString(), QStringLiteral("fake: cannot connect"));
        QCOMPARE(failed.count(), 0); // no command was out
        // A late word of the backend's changes nothing.
        s.fake->finishOpening();
        QCOMPARE(s.link->state(), RadioLink::State::Closed);
        QVERIFY(s.fake->performed.isEmpty());
    }
}

void CommandPacerTest::scriptReadsBothFrequenciesWhenSplit()
{
    ScriptOverFake s;
    QVERIFY(s.opened());
    QSignalSpy read(s.link.get(), &RadioLink::frequenciesRead);
    s.link->readFrequencies(); // split off: the receive frequency alone
    QCOMPARE(read.count(), 1);
    QCOMPARE(read.at(0).at(0).value<RadioFrequencies>().receiveHz.value_or(0), 145800000.0);
    QVERIFY(!read.at(0).at(0).value<RadioFrequencies>().transmitHz);
    s.link->setSplit(true);
    s.link->setReceiveHz(145900000.4); // whole hertz on the wire
    s.link->setTransmitHz(435100000);
    s.link->readFrequencies();
    QCOMPARE(read.count(), 2);
    const auto f = read.at(1).at(0).value<RadioFrequencies>();
    QCOMPARE(f.receiveHz.value_or(0), 145900000.0);
    QCOMPARE(f.transmitHz.value_or(0), 435100000.0);
    QCOMPARE(s.fake->performed, (QStringList{"f", "S 1", "F 145900000", "I 435100000", "i", "f"}));
}

void CommandPacerTest::scriptAnswersAReadingFirst()
{
    // What the owner sends in answer to a reading goes next, ahead of what
    // waited: a turn of the radio's dial then has one round trip to land
    // between the reading and the frequency, unseen.
    ScriptOverFake s;
    QVERIFY(s.opened());
    s.link->setSplit(true);
    s.fake->holding = true;
    s.fake->performed.clear();
    connect(s.link.get(), &RadioLink::frequenciesRead, s.link.get(),
            [&](const RadioFrequencies &) { s.link->setReceiveHz(145900000); });
    s.link->readFrequencies();
    s.link->setTransmitHz(435100000);
    s.link->setMode("USB", 0);
    for (int i = 0; i < 5; ++i)
        s.fake->answerHeld();
    QCOMPARE(s.fake->performed, (QStringList{"i", "f", "F 145900000", "I 435100000", "M USB 0"}));
}

void CommandPacerTest::scriptReplacesWaitingCommands()
{
    ScriptOverFake s;
    QVERIFY(s.opened());
    s.fake->holding = true;
    QSignalSpy sent(s.link.get(), &RadioLink::commandSent);
    s.link->setReceiveHz(145900000);
    for (int i = 1; i < 100; ++i)
        s.link->setReceiveHz(145900000 + i * 10);
    s.link->setTransmitHz(435100000);
    s.link->setMode("USB", 0);
    s.link->setTransmitHz(435100010);
    s.link->setSplit(true);
    QCOMPARE(s.fake->performed.size(), 1);
    QCOMPARE(s.link->pacer().waitingCount(), 4);
    while (s.fake->isHolding())
        s.fake->answerHeld();
    QCOMPARE(s.fake->performed, (QStringList{"F 145900000", "F 145900990", "I 435100010", "M USB 0", "S 1"}));
    QCOMPARE(firstArguments(sent), s.fake->performed);
    // The backend was handed the newest values, not only their text.
    QCOMPARE(s.fake->commands.at(1).hz, 145900990.0);
    QCOMPARE(s.fake->commands.at(2).hz, 435100010.0);
    QCOMPARE(s.link->pacer().replacedCount(), 98 + 1);
}

void CommandPacerTest::scriptRefusesUnsendableAndWhileClosed()
{
    ScriptOverFake s;
    QSignalSpy failed(s.link.get(), &RadioLink::commandFailed);
    s.link->setReceiveHz(145800000);
    s.link->readFrequencies();
    QCOMPARE(failed.count(), 2);
    QCOMPARE(failed.at(0).at(0).toString(), QStringLiteral("F 145800000"));
    QCOMPARE(failed.at(0).at(1).toString(), QStringLiteral("not sent: fake: is not open"));

    QVERIFY(s.opened());
    failed.clear();
    s.fake->refuse = [](const QString &text) { return text.startsWith("M FOO") ? QStringLiteral("no FOO here") : QString(); };
    s.link->setReceiveHz(std::numeric_limits<double>::quiet_NaN());
    s.link->setTransmitHz(0.4);
    s.link->setReceiveHz(2e12);
    s.link->setMode("USB\nq", 0);
    s.link->setMode(QStringLiteral("USB") + QChar(0) + "x", 0); // would read as USB in C
    s.link->setMode("", 0);
    s.link->setMode("USB", -2);
    s.link->setTransmitMode("LSB", 2000000);
    s.link->setMode("FOO", 0);
    QCOMPARE(failed.count(), 9);
    QVERIFY(s.fake->performed.isEmpty());
    QCOMPARE(failed.at(0).at(0).toString(), QStringLiteral("F nan"));
    QCOMPARE(failed.at(0).at(1).toString(), QStringLiteral("not sent: nan is not a finite number"));
    QCOMPARE(failed.at(1).at(1).toString(), QStringLiteral("not sent: 0.4 Hz is outside 1..1e+12 Hz"));
    QCOMPARE(failed.at(2).at(1).toString(), QStringLiteral("not sent: 2e+12 Hz is outside 1..1e+12 Hz"));
    QCOMPARE(failed.at(3).at(0).toString(), QStringLiteral("M USB\\x0aq 0"));
    QCOMPARE(failed.at(4).at(0).toString(), QStringLiteral("M USB\\x00x 0"));
    QCOMPARE(failed.at(7).at(1).toString(),
             QStringLiteral("not sent: a passband is from -1 to 1000000 Hz (0: the mode's default)"));
    QCOMPARE(failed.at(8).at(0).toString(), QStringLiteral("M FOO 0"));
    QCOMPARE(failed.at(8).at(1).toString(), QStringLiteral("not sent: no FOO here"));
    QCOMPARE(s.link->state(), RadioLink::State::Open);
}

void CommandPacerTest::scriptPassesRefusalsOn()
{
    ScriptOverFake s;
    QVERIFY(s.opened());
    s.fake->answerOverride = [](const QString &text) -> std::optional<RadioAnswer> {
        if (text == "S 1")
            return refusal(-9, "refused: RPRT -9 (command rejected)");
        return std::nullopt;
    };
    QSignalSpy failed(s.link.get(), &RadioLink::commandFailed);
    QSignalSpy read(s.link.get(), &RadioLink::frequenciesRead);
    s.link->setSplit(true);
    QCOMPARE(failed.count(), 1);
    QCOMPARE(failed.at(0).at(0).toString(), QStringLiteral("S 1"));
    QCOMPARE(failed.at(0).at(1).toString(), QStringLiteral("refused: RPRT -9 (command rejected)"));
    // Split was refused: a read asks no transmit frequency.
    s.link->readFrequencies();
    QCOMPARE(s.fake->performed, (QStringList{"S 1", "f"}));
    QCOMPARE(read.count(), 1);
    QCOMPARE(s.link->state(), RadioLink::State::Open);
}

void CommandPacerTest::scriptRefusesBadReadings_data()
{
    QTest::addColumn<bool>("hasValue");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("reason");
    QTest::newRow("nan") << true << "nan" << "unusable answer: 'nan' is not a finite number";
    QTest::newRow("huge") << true << "1e300" << "unusable answer: 1e+300 Hz is outside 1..1e+12 Hz";
    QTest::newRow("zero") << true << "0" << "unusable answer: 0 Hz is outside 1..1e+12 Hz";
    QTest::newRow("words") << true << "VFOA" << "unusable answer: 'VFOA' is not a number";
    QTest::newRow("escape") << true << "\x1b[2J" << "unusable answer: '\\x1b[2J' is not a number";
    QTest::newRow("nothing") << false << "" << "the answer held no value";
}

void CommandPacerTest::scriptRefusesBadReadings()
{
    QFETCH(bool, hasValue);
    QFETCH(QString, value);
    QFETCH(QString, reason);
    ScriptOverFake s;
    QVERIFY(s.opened());
    s.link->setSplit(true);
    QSignalSpy failed(s.link.get(), &RadioLink::commandFailed);
    QSignalSpy read(s.link.get(), &RadioLink::frequenciesRead);
    QString badOn;
    s.fake->answerOverride = [&](const QString &text) -> std::optional<RadioAnswer> {
        if (text != badOn)
            return std::nullopt;
        RadioAnswer a;
        if (hasValue)
            a.value = value;
        return a;
    };
    // A bad receive frequency, then a bad transmit one after a good receive one.
    badOn = QStringLiteral("f");
    s.link->readFrequencies();
    badOn = QStringLiteral("i");
    s.link->readFrequencies();
    QCOMPARE(failed.count(), 2);
    QCOMPARE(failed.at(0).at(0).toString(), QStringLiteral("f"));
    QCOMPARE(failed.at(0).at(1).toString(), reason);
    QCOMPARE(failed.at(1).at(0).toString(), QStringLiteral("i"));
    QCOMPARE(read.count(), 0); // nothing half-read either
    QCOMPARE(s.link->state(), RadioLink::State::Open);
    badOn.clear();
    s.link->readFrequencies();
    QCOMPARE(read.count(), 1);
}

void CommandPacerTest::scriptStepBounds_data()
{
    QTest::addColumn<QString>("step");
    QTest::addColumn<bool>("refused");
    QTest::addColumn<double>("stepHz");
    QTest::addColumn<QString>("failure"); // empty: none
    QTest::newRow("10 Hz") << "10" << false << 10.0 << "";
    QTest::newRow("1 MHz") << "1000000" << false << 1e6 << "";
    QTest::newRow("none set") << "0" << false << 1.0 << "";
    // A backend without get_ts refuses it: not known, no fault.
    QTest::newRow("refused") << "" << true << 1.0 << "";
    QTest::newRow("too coarse") << "2e6" << false << 1.0 << "unusable answer: 2000000 Hz is outside 0..1000000 Hz";
    QTest::newRow("negative") << "-5" << false << 1.0 << "unusable answer: -5 Hz is outside 0..1000000 Hz";
    QTest::newRow("nan") << "nan" << false << 1.0 << "unusable answer: 'nan' is not a finite number";
}

void CommandPacerTest::scriptStepBounds()
{
    QFETCH(QString, step);
    QFETCH(bool, refused);
    QFETCH(double, stepHz);
    QFETCH(QString, failure);
    ScriptOverFake s;
    s.fake->step = step;
    if (refused) {
        s.fake->answerOverride = [](const QString &text) -> std::optional<RadioAnswer> {
            if (text == "n")
                return refusal(-11, "refused: RPRT -11 (feature not available)");
            return std::nullopt;
        };
    }
    QSignalSpy failed(s.link.get(), &RadioLink::commandFailed);
    s.link->open();
    QCOMPARE(s.link->state(), RadioLink::State::Open); // a step is never a reason not to open
    QCOMPARE(s.link->tuningStepHz(), stepHz);
    QCOMPARE(failed.count(), failure.isEmpty() ? 0 : 1);
    if (!failure.isEmpty())
        QCOMPARE(failed.at(0).at(1).toString(), failure);
}

void CommandPacerTest::scriptGivesUpOnSilence()
{
    ScriptOverFake s;
    QVERIFY(s.opened());
    s.link->setReplyTimeoutMs(50);
    s.fake->holding = true; // and never answers
    QSignalSpy states(s.link.get(), &RadioLink::stateChanged);
    QSignalSpy failed(s.link.get(), &RadioLink::commandFailed);
    s.link->setMode("FM", 0);
    s.link->setReceiveHz(145900000); // waits behind it: forgotten
    QVERIFY(states.wait(5000));
    QCOMPARE(s.link->state(), RadioLink::State::Closed);
    const QString reason = QStringLiteral("fake: the fake did not answer 'M FM 0' within 0.05 s");
    QCOMPARE(states.last().at(1).toString(), reason);
    QCOMPARE(failed.count(), 1);
    QCOMPARE(failed.at(0).at(0).toString(), QStringLiteral("M FM 0"));
    QCOMPARE(failed.at(0).at(1).toString(), reason);
    QCOMPARE(s.fake->aborts, 1);
    QCOMPARE(s.link->pacer().waitingCount(), 0);
    // The answer that comes after all changes nothing.
    s.fake->answer(RadioAnswer{});
    QCOMPARE(states.count(), 1);
    QCOMPARE(failed.count(), 1);
    QCOMPARE(s.fake->performed, QStringList{"M FM 0"});
}

void CommandPacerTest::scriptGivesUpOnALostRadio_data()
{
    QTest::addColumn<QList<int>>("codes"); // the answers to M FM 0, one command each
    QTest::addColumn<QString>("closedBecause"); // empty: still open
    const QString timedOut = QStringLiteral("failed: Communication timed out");
    QTest::newRow("one timeout") << QList<int>{-5} << "";
    QTest::newRow("timeouts between answers") << QList<int>{-5, 0, -5, -9, -5} << "";
    QTest::newRow("two in a row") << QList<int>{-5, -5} << "fake: M FM 0 " + timedOut + ", 2 times in a row";
    QTest::newRow("I/O error") << QList<int>{-6} << "fake: M FM 0 failed: IO error";
    QTest::newRow("protocol error") << QList<int>{-8} << "fake: M FM 0 failed: Protocol error";
    QTest::newRow("refused") << QList<int>{-9, -9, -9} << "";
}

void CommandPacerTest::scriptGivesUpOnALostRadio()
{
    QFETCH(QList<int>, codes);
    QFETCH(QString, closedBecause);
    ScriptOverFake s;
    QVERIFY(s.opened());
    qsizetype given = 0;
    s.fake->answerOverride = [&](const QString &) -> std::optional<RadioAnswer> {
        const int code = codes.value(given++);
        const char *words = code == -5 ? "Communication timed out"
                            : code == -6 ? "IO error"
                            : code == -8 ? "Protocol error"
                                         : "Command rejected by the rig";
        return code == 0 ? RadioAnswer{} : refusal(code, QStringLiteral("failed: %1").arg(QLatin1String(words)));
    };
    QSignalSpy states(s.link.get(), &RadioLink::stateChanged);
    QSignalSpy failed(s.link.get(), &RadioLink::commandFailed);
    for (qsizetype i = 0; i < codes.size() && s.link->isOpen(); ++i)
        s.link->setMode("FM", 0);
    if (closedBecause.isEmpty()) {
        QCOMPARE(s.link->state(), RadioLink::State::Open);
        QCOMPARE(states.count(), 0);
        QCOMPARE(failed.count(), codes.size() - codes.count(0));
        return;
    }
    QCOMPARE(s.link->state(), RadioLink::State::Closed);
    QCOMPARE(states.last().at(1).toString(), closedBecause);
    QCOMPARE(failed.last().at(1).toString(), closedBecause);
    QCOMPARE(s.fake->aborts, 1);
}

void CommandPacerTest::scriptDropWaitingFinishesTheExchange()
{
    ScriptOverFake s;
    QVERIFY(s.opened());
    s.link->setSplit(true);
    s.fake->holding = true;
    QSignalSpy read(s.link.get(), &RadioLink::frequenciesRead);
    s.link->readFrequencies();
    s.link->setReceiveHz(145900000);
    s.link->setMode("FM", 0);
    s.link->dropWaiting();
    QCOMPARE(s.link->pacer().waitingCount(), 0);
    // The read on the wire finishes, its second half included...
    s.fake->answerHeld();
    s.fake->answerHeld();
    QCOMPARE(read.count(), 1);
    QCOMPARE(read.at(0).at(0).value<RadioFrequencies>().transmitHz.value_or(0), 435000000.0);
    // ...and nothing that waited follows.
    QVERIFY(!s.fake->isHolding());
    QCOMPARE(s.fake->performed, (QStringList{"S 1", "i", "f"}));
    QVERIFY(!s.link->pacer().isBusy());
}

void CommandPacerTest::scriptCloseMidExchange()
{
    ScriptOverFake s;
    QVERIFY(s.opened());
    s.link->setSplit(true);
    s.fake->holding = true;
    QSignalSpy states(s.link.get(), &RadioLink::stateChanged);
    QSignalSpy failed(s.link.get(), &RadioLink::commandFailed);
    QSignalSpy read(s.link.get(), &RadioLink::frequenciesRead);
    s.link->readFrequencies();
    s.link->setReceiveHz(145900000);
    s.link->close();
    QCOMPARE(s.link->state(), RadioLink::State::Closed);
    QCOMPARE(states.count(), 1);
    QCOMPARE(states.at(0).at(1).toString(), QStringLiteral("fake: closed"));
    QCOMPARE(s.fake->closes, 1);
    QVERIFY(!s.link->pacer().isBusy());
    QCOMPARE(s.link->pacer().waitingCount(), 0);
    // The read's answer, late: no second half, no reading, no failure.
    RadioAnswer late;
    late.value = QStringLiteral("145800000");
    s.fake->answer(late);
    QCOMPARE(s.fake->performed, (QStringList{"S 1", "i"}));
    QCOMPARE(read.count(), 0);
    QCOMPARE(failed.count(), 0);
    QCOMPARE(states.count(), 1);
    // Closing again says nothing; opening again starts over.
    s.link->close();
    QCOMPARE(states.count(), 1);
    s.fake->holding = false;
    s.link->open();
    QCOMPARE(s.link->state(), RadioLink::State::Open);
    QCOMPARE(s.fake->performed.mid(2), (QStringList{"f", "F 145800000", "n", "s"}));
}

QTEST_GUILESS_MAIN(CommandPacerTest)
#include "tst_commandpacer.moc"
