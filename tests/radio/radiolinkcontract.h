// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What every radio link promises (radiolink.h), checked over a real
// backend, and what the links that read their radio's dial back promise
// on top of it (scriptedradiolink.h).
//
// Every link: it opens and says so naming itself; it reads back what it
// was set to (the receive frequency, and the transmit one while split is
// on, or always where the link has a transmit path of its own); the newest
// setting replaces a waiting one; what no radio can take is refused in the
// same words over every backend (radiolimits.h); a link not open refuses
// every command; dropWaiting() forgets what waits; close() in the middle
// of an exchange leaves nothing of it behind. tst_controllerradio runs
// these over the rotator controller's UP/DN (a RotatorSession on the
// simulator), which reads back only what it was told.
//
// Links that read the dial: opening reads the frequency, sets it back
// unchanged to time a set's round trip, and names both. tst_rigctldradio
// runs these, with every link's rows, over Hamlib's rigctld,
// tst_hamlibradio over libhamlib in process, both with Hamlib's dummy rig
// (model 1, which starts on 145 MHz, has no tuning step set, and takes
// any value). The script's own tests, over a fake backend, are in
// tst_commandpacer; what the dummy rig cannot show (a refusal, silence, a
// radio gone) is tested there.
//
// A test adds the rows with addContractRows() and runs the row's check on
// a link it made, closed: checkEveryLinkContract() with a Backend for any
// link, checkContract() for a link that reads the dial (every link's check
// and its own).

#include "radio/commandpacer.h"
#include "radio/scriptedradiolink.h"

#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>

#include <limits>
#include <optional>

namespace radiolinkcontract {

using slew::radio::CommandPacer;
using slew::radio::RadioFrequencies;
using slew::radio::RadioLink;
using slew::radio::ScriptedRadioLink;

// Long enough for a loaded 2-core machine; the dummy rig answers in 40 ms.
constexpr int kWaitMs = 15000;

// What the contract needs of a link beyond RadioLink, and the two ways the
// backends honestly differ.
struct Backend {
    RadioLink &link;
    // Its pacer: whether a command is on the wire, what waits, what a newer
    // one replaced.
    const CommandPacer &pacer;
    // A setting holds the wire until the radio answers it (rigctld,
    // libhamlib). The controller's settings have no answer (written is
    // done), so where a row needs a command on the wire a reading holds
    // it, as the steering's check of the radio does.
    bool settingsAnswered = true;
    // With split off, a link whose radio keeps the transmit frequency on a
    // split VFO reads the receive one only; the controller has a transmit
    // path of its own (UP), read always.
    bool transmitWithoutSplit = false;
};

inline Backend backendOf(ScriptedRadioLink &link)
{
    return {link, link.pacer(), true, false};
}

inline QString label(const RadioLink &link)
{
    return link.uri().endsWith(QLatin1Char(':')) ? link.uri().chopped(1) : link.uri();
}

inline QStringList texts(const QSignalSpy &spy, int column = 0)
{
    QStringList out;
    for (const QList<QVariant> &args : spy)
        out << args.at(column).toString();
    return out;
}

inline RadioFrequencies reading(const QSignalSpy &spy, int at)
{
    return spy.at(at).at(0).value<RadioFrequencies>();
}

inline bool idle(const Backend &b)
{
    return !b.pacer.isBusy() && b.pacer.waitingCount() == 0;
}

// Open, and nothing of the opening left on the wire (the controller's
// opening reading comes after Open).
inline void openLink(const Backend &b)
{
    b.link.open();
    QTRY_VERIFY_WITH_TIMEOUT(b.link.state() != RadioLink::State::Opening, kWaitMs);
    QCOMPARE(b.link.state(), RadioLink::State::Open);
    QTRY_VERIFY_WITH_TIMEOUT(idle(b), kWaitMs);
}

// One reading, asked now; *out what it found.
inline void readNow(const Backend &b, RadioFrequencies *out)
{
    QSignalSpy read(&b.link, &RadioLink::frequenciesRead);
    b.link.readFrequencies();
    QVERIFY(read.wait(kWaitMs));
    *out = reading(read, int(read.count()) - 1);
}

// A setting of the receive frequency, and with it a command on the wire:
// the setting itself where its answer holds the wire, else a reading after
// it. How many commands that sent.
inline qsizetype holdTheWire(const Backend &b, double receiveHz, const QSignalSpy &sent)
{
    b.link.setReceiveHz(receiveHz);
    if (!b.settingsAnswered)
        b.link.readFrequencies();
    return sent.count();
}

// --- Every link ------------------------------------------------------------

// It opens, and says so naming itself first.
inline void opening(const Backend &b)
{
    QSignalSpy states(&b.link, &RadioLink::stateChanged);
    QSignalSpy failed(&b.link, &RadioLink::commandFailed);
    openLink(b);
    if (QTest::currentTestFailed())
        return;
    QVERIFY(!states.isEmpty());
    QCOMPARE(states.last().at(0).value<RadioLink::State>(), RadioLink::State::Open);
    for (const QString &detail : texts(states, 1))
        QVERIFY2(detail.startsWith(label(b.link) + ": "), qPrintable(detail));
    QVERIFY(b.link.latencyMs() >= 0);
    QCOMPARE(failed.count(), 0);
}

// What was set is what is read back: the receive frequency, in whole
// hertz; the transmit one while split is on, and with split off only where
// the link has a transmit path of its own.
inline void readBack(const Backend &b)
{
    openLink(b);
    QSignalSpy failed(&b.link, &RadioLink::commandFailed);
    b.link.setSplit(true);
    b.link.setReceiveHz(145900000.4); // whole hertz
    b.link.setTransmitHz(435100000);
    RadioFrequencies held;
    readNow(b, &held);
    if (QTest::currentTestFailed())
        return;
    QCOMPARE(held.receiveHz.value_or(0), 145900000.0);
    QCOMPARE(held.transmitHz.value_or(0), 435100000.0);
    b.link.setSplit(false);
    readNow(b, &held);
    if (QTest::currentTestFailed())
        return;
    QCOMPARE(held.receiveHz.value_or(0), 145900000.0);
    if (b.transmitWithoutSplit)
        QCOMPARE(held.transmitHz.value_or(0), 435100000.0);
    else
        QVERIFY(!held.transmitHz);
    QCOMPARE(failed.count(), 0);
}

// Given at once, as a steering loop that fell behind would, while a
// command holds the wire: each newer one replaces the one waiting, and the
// last is what the radio holds.
inline void newestReplacesWaiting(const Backend &b)
{
    openLink(b);
    QSignalSpy sent(&b.link, &RadioLink::commandSent);
    const int replacedBefore = b.pacer.replacedCount();
    const qsizetype onTheWire = holdTheWire(b, 145800000, sent);
    QCOMPARE(onTheWire, b.settingsAnswered ? 1 : 2);
    QVERIFY(b.pacer.isBusy());
    for (int i = 1; i < 10; ++i)
        b.link.setReceiveHz(145800000 + i * 10);
    QCOMPARE(sent.count(), onTheWire);
    QCOMPARE(b.pacer.waitingCount(), 1);
    QTRY_VERIFY_WITH_TIMEOUT(idle(b), kWaitMs);
    QCOMPARE(sent.count(), onTheWire + 1);
    QVERIFY2(sent.last().at(0).toString().endsWith("145800090"), qPrintable(sent.last().at(0).toString()));
    QCOMPARE(b.pacer.replacedCount() - replacedBefore, 8);
    RadioFrequencies held;
    readNow(b, &held);
    QCOMPARE(held.receiveHz.value_or(0), 145800090.0);
}

// What no radio can take is refused here, in the same words over every
// backend (radiolimits.h), and nothing is sent.
inline void unsendableRefused(const Backend &b)
{
    openLink(b);
    RadioLink &link = b.link;
    QSignalSpy sent(&link, &RadioLink::commandSent);
    QSignalSpy failed(&link, &RadioLink::commandFailed);
    link.setReceiveHz(std::numeric_limits<double>::quiet_NaN());
    link.setReceiveHz(std::numeric_limits<double>::infinity());
    link.setTransmitHz(0.4);
    link.setTransmitHz(2e12);
    link.setMode("USB\nq", 0);
    link.setMode("", 0);
    link.setMode("USB", -2);
    link.setTransmitMode("LSB", 2000000);
    QCOMPARE(sent.count(), 0);
    QCOMPARE(texts(failed, 1),
             (QStringList{"not sent: nan is not a finite number", "not sent: inf is not a finite number",
                          "not sent: 0.4 Hz is outside 1..1e+12 Hz", "not sent: 2e+12 Hz is outside 1..1e+12 Hz",
                          "not sent: a mode is a Hamlib mode name of letters and digits (USB, FM, PKTUSB)",
                          "not sent: a mode is a Hamlib mode name of letters and digits (USB, FM, PKTUSB)",
                          "not sent: a passband is from -1 to 1000000 Hz (0: the mode's default)",
                          "not sent: a passband is from -1 to 1000000 Hz (0: the mode's default)"}));
    // The refused command is named with its line end made visible.
    QVERIFY2(failed.at(4).at(0).toString().contains("USB\\x0aq"), qPrintable(failed.at(4).at(0).toString()));
    QVERIFY(idle(b));
    QCOMPARE(link.state(), RadioLink::State::Open);
}

// A link not open refuses every command, naming itself.
inline void closedRefuses(const Backend &b)
{
    RadioLink &link = b.link;
    QSignalSpy sent(&link, &RadioLink::commandSent);
    QSignalSpy failed(&link, &RadioLink::commandFailed);
    link.setReceiveHz(145800000);
    link.setMode("FM", 0);
    link.readFrequencies();
    const QString notOpen = QStringLiteral("not sent: %1 is not open").arg(link.uri());
    QCOMPARE(texts(failed, 1), (QStringList{notOpen, notOpen, notOpen}));
    QCOMPARE(sent.count(), 0);
}

// dropWaiting() forgets what waits; the command on the wire finishes.
inline void dropWaiting(const Backend &b)
{
    openLink(b);
    QSignalSpy sent(&b.link, &RadioLink::commandSent);
    QSignalSpy failed(&b.link, &RadioLink::commandFailed);
    const qsizetype onTheWire = holdTheWire(b, 145700000, sent);
    QCOMPARE(onTheWire, b.settingsAnswered ? 1 : 2);
    b.link.setReceiveHz(145710000);
    b.link.setTransmitHz(435100000);
    b.link.setMode("FM", 0);
    QCOMPARE(b.pacer.waitingCount(), 3);
    b.link.dropWaiting();
    QCOMPARE(b.pacer.waitingCount(), 0);
    QTRY_VERIFY_WITH_TIMEOUT(idle(b), kWaitMs);
    QCOMPARE(sent.count(), onTheWire);
    RadioFrequencies held;
    readNow(b, &held);
    QCOMPARE(held.receiveHz.value_or(0), 145700000.0);
    QCOMPARE(failed.count(), 0);
}

// close() in the middle of an exchange: closed at once, and nothing of the
// exchange comes after it; the link opens again.
inline void closeMidExchange(const Backend &b)
{
    RadioLink &link = b.link;
    openLink(b);
    link.setSplit(true);
    QTRY_VERIFY_WITH_TIMEOUT(idle(b), kWaitMs);
    QSignalSpy states(&link, &RadioLink::stateChanged);
    QSignalSpy failed(&link, &RadioLink::commandFailed);
    QSignalSpy read(&link, &RadioLink::frequenciesRead);
    link.readFrequencies(); // its (first) question on the wire, unanswered
    QVERIFY(b.pacer.isBusy());
    link.setReceiveHz(145900000);
    link.close();
    QCOMPARE(link.state(), RadioLink::State::Closed);
    QCOMPARE(states.count(), 1);
    QCOMPARE(states.at(0).at(1).toString(), label(link) + ": closed");
    QVERIFY(idle(b));
    // Every backend here answers within 50 ms: its answer, had it been
    // taken, would show by then.
    QVERIFY(!read.wait(500));
    QCOMPARE(failed.count(), 0);
    QCOMPARE(states.count(), 1);
    openLink(b);
    RadioFrequencies held;
    readNow(b, &held);
    QVERIFY(held.receiveHz);
}

inline void addContractRows()
{
    QTest::addColumn<QString>("check");
    for (const char *check : {"opening", "read back", "newest replaces waiting", "unsendable refused",
                              "closed refuses", "dropWaiting", "close mid-exchange"})
        QTest::newRow(check) << QString::fromLatin1(check);
}

inline void checkEveryLinkContract(const QString &check, const Backend &b)
{
    QCOMPARE(b.link.state(), RadioLink::State::Closed);
    if (check == "opening")
        opening(b);
    else if (check == "read back")
        readBack(b);
    else if (check == "newest replaces waiting")
        newestReplacesWaiting(b);
    else if (check == "unsendable refused")
        unsendableRefused(b);
    else if (check == "closed refuses")
        closedRefuses(b);
    else if (check == "dropWaiting")
        dropWaiting(b);
    else if (check == "close mid-exchange")
        closeMidExchange(b);
    else
        QFAIL(qPrintable("no check " + check));
}

// --- Links that read the dial ----------------------------------------------

// Opening reads the frequency, sets it back unchanged to time the round
// trip, and says so: Opening, then Open naming both.
inline void openingReadsTheDial(ScriptedRadioLink &link)
{
    QSignalSpy states(&link, &RadioLink::stateChanged);
    QSignalSpy sent(&link, &RadioLink::commandSent);
    opening(backendOf(link));
    if (QTest::currentTestFailed())
        return;
    QCOMPARE(states.count(), 2);
    QCOMPARE(states.at(0).at(0).value<RadioLink::State>(), RadioLink::State::Opening);
    QCOMPARE(states.at(1).at(1).toString(),
             label(link) + QStringLiteral(": open at 145.000 000 MHz; a set answered in %1 ms").arg(link.latencyMs()));
    // The frequency read is the one set back: nothing changes on the radio.
    const QStringList commands = texts(sent);
    const qsizetype set = commands.indexOf(QRegularExpression(QStringLiteral(".* 145000000$")));
    QVERIFY2(set > 0, qPrintable(commands.join(", ")));
    QCOMPARE(link.tuningStepHz(), 1.0); // none set: 1 Hz
}

// Every link's contract, and the dial's own opening.
inline void checkContract(const QString &check, ScriptedRadioLink &link)
{
    if (check == "opening") {
        QCOMPARE(link.state(), RadioLink::State::Closed);
        openingReadsTheDial(link);
    } else {
        checkEveryLinkContract(check, backendOf(link));
    }
}

} // namespace radiolinkcontract
