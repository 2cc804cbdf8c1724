// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What every radio link that reads its radio back promises (radiolink.h,
// scriptedradiolink.h), checked over a real backend: tst_rigctldradio runs
// it over Hamlib's rigctld, tst_hamlibradio over libhamlib in process, both
// with Hamlib's dummy rig (model 1, which starts on 145 MHz, has no tuning
// step set, and takes any value). The script's own tests, over a fake
// backend, are in tst_commandpacer; what the dummy rig cannot show (a
// refusal, silence, a radio gone) is tested there.
//
// A test adds the rows with addContractRows() and runs the row's check
// with checkContract() on a link it made, closed.

#include "radio/scriptedradiolink.h"

#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>

#include <limits>

namespace radiolinkcontract {

using slew::radio::RadioFrequencies;
using slew::radio::RadioLink;
using slew::radio::ScriptedRadioLink;

// Long enough for a loaded 2-core machine; the dummy rig answers in 40 ms.
constexpr int kWaitMs = 15000;

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

inline bool idle(const ScriptedRadioLink &link)
{
    return !link.pacer().isBusy() && link.pacer().waitingCount() == 0;
}

inline void openLink(ScriptedRadioLink &link)
{
    link.open();
    QTRY_VERIFY_WITH_TIMEOUT(link.state() != RadioLink::State::Opening, kWaitMs);
    QCOMPARE(link.state(), RadioLink::State::Open);
}

// Opening reads the frequency, sets it back unchanged to time the round
// trip, and says so, naming the link first.
inline void opening(ScriptedRadioLink &link)
{
    QSignalSpy states(&link, &RadioLink::stateChanged);
    QSignalSpy sent(&link, &RadioLink::commandSent);
    QSignalSpy failed(&link, &RadioLink::commandFailed);
    openLink(link);
    if (QTest::currentTestFailed())
        return;
    QCOMPARE(states.count(), 2);
    QCOMPARE(states.at(0).at(0).value<RadioLink::State>(), RadioLink::State::Opening);
    QVERIFY2(states.at(0).at(1).toString().startsWith(label(link) + ": "), qPrintable(states.at(0).at(1).toString()));
    QCOMPARE(states.at(1).at(1).toString(),
             label(link) + QStringLiteral(": open at 145.000 000 MHz; a set answered in %1 ms").arg(link.latencyMs()));
    // The frequency read is the one set back: nothing changes on the radio.
    const QStringList commands = texts(sent);
    const qsizetype set = commands.indexOf(QRegularExpression(QStringLiteral(".* 145000000$")));
    QVERIFY2(set > 0, qPrintable(commands.join(", ")));
    QVERIFY(link.latencyMs() >= 0);
    QCOMPARE(link.tuningStepHz(), 1.0); // none set: 1 Hz
    QCOMPARE(failed.count(), 0);
}

// What was set is what is read back; the transmit frequency while split is on.
inline void readBack(ScriptedRadioLink &link)
{
    openLink(link);
    QSignalSpy read(&link, &RadioLink::frequenciesRead);
    QSignalSpy failed(&link, &RadioLink::commandFailed);
    link.setSplit(true);
    link.setReceiveHz(145900000.4); // whole hertz
    link.setTransmitHz(435100000);
    link.readFrequencies();
    QVERIFY(read.wait(kWaitMs));
    QCOMPARE(reading(read, 0).receiveHz.value_or(0), 145900000.0);
    QCOMPARE(reading(read, 0).transmitHz.value_or(0), 435100000.0);
    link.setSplit(false);
    link.readFrequencies();
    QVERIFY(read.wait(kWaitMs));
    QCOMPARE(reading(read, 1).receiveHz.value_or(0), 145900000.0);
    QVERIFY(!reading(read, 1).transmitHz);
    QCOMPARE(failed.count(), 0);
}

// Given at once, as a steering loop that fell behind would: the first
// leaves, each newer one replaces the one waiting, and the last is what the
// radio holds.
inline void newestReplacesWaiting(ScriptedRadioLink &link)
{
    openLink(link);
    QSignalSpy sent(&link, &RadioLink::commandSent);
    QSignalSpy read(&link, &RadioLink::frequenciesRead);
    const int replacedBefore = link.pacer().replacedCount();
    for (int i = 0; i < 10; ++i)
        link.setReceiveHz(145800000 + i * 10);
    QCOMPARE(sent.count(), 1);
    QCOMPARE(link.pacer().waitingCount(), 1);
    QTRY_VERIFY_WITH_TIMEOUT(idle(link), kWaitMs);
    QCOMPARE(sent.count(), 2);
    QVERIFY2(sent.at(1).at(0).toString().endsWith(" 145800090"), qPrintable(sent.at(1).at(0).toString()));
    QCOMPARE(link.pacer().replacedCount() - replacedBefore, 8);
    link.readFrequencies();
    QVERIFY(read.wait(kWaitMs));
    QCOMPARE(reading(read, 0).receiveHz.value_or(0), 145800090.0);
}

// What no radio can take is refused here, in the same words over every
// backend, and nothing is sent.
inline void unsendableRefused(ScriptedRadioLink &link)
{
    openLink(link);
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
    QVERIFY2(failed.at(4).at(0).toString().contains("USB\\x0aq"), qPrintable(failed.at(4).at(0).toString()));
    QVERIFY(idle(link));
    QCOMPARE(link.state(), RadioLink::State::Open);
}

// A link not open refuses every command, naming itself.
inline void closedRefuses(ScriptedRadioLink &link)
{
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
inline void dropWaiting(ScriptedRadioLink &link)
{
    openLink(link);
    QSignalSpy sent(&link, &RadioLink::commandSent);
    QSignalSpy failed(&link, &RadioLink::commandFailed);
    QSignalSpy read(&link, &RadioLink::frequenciesRead);
    link.setReceiveHz(145700000);
    link.setReceiveHz(145710000);
    link.setTransmitHz(435100000);
    link.setMode("FM", 0);
    QCOMPARE(link.pacer().waitingCount(), 3);
    link.dropWaiting();
    QCOMPARE(link.pacer().waitingCount(), 0);
    QTRY_VERIFY_WITH_TIMEOUT(idle(link), kWaitMs);
    QCOMPARE(sent.count(), 1);
    link.readFrequencies();
    QVERIFY(read.wait(kWaitMs));
    QCOMPARE(reading(read, 0).receiveHz.value_or(0), 145700000.0);
    QCOMPARE(failed.count(), 0);
}

// close() in the middle of an exchange: closed at once, and nothing of the
// exchange comes after it; the link opens again.
inline void closeMidExchange(ScriptedRadioLink &link)
{
    openLink(link);
    link.setSplit(true);
    QTRY_VERIFY_WITH_TIMEOUT(idle(link), kWaitMs);
    QSignalSpy states(&link, &RadioLink::stateChanged);
    QSignalSpy failed(&link, &RadioLink::commandFailed);
    QSignalSpy read(&link, &RadioLink::frequenciesRead);
    link.readFrequencies(); // two halves: the receive one on the wire
    link.setReceiveHz(145900000);
    link.close();
    QCOMPARE(link.state(), RadioLink::State::Closed);
    QCOMPARE(states.count(), 1);
    QCOMPARE(states.at(0).at(1).toString(), label(link) + ": closed");
    QVERIFY(idle(link));
    // The dummy answers within 50 ms: its answer, had it been taken, would show by then.
    QVERIFY(!read.wait(500));
    QCOMPARE(failed.count(), 0);
    QCOMPARE(states.count(), 1);
    openLink(link);
    link.readFrequencies();
    QVERIFY(read.wait(kWaitMs));
    QVERIFY(reading(read, 0).receiveHz);
}

inline void addContractRows()
{
    QTest::addColumn<QString>("check");
    for (const char *check : {"opening", "read back", "newest replaces waiting", "unsendable refused",
                              "closed refuses", "dropWaiting", "close mid-exchange"})
        QTest::newRow(check) << QString::fromLatin1(check);
}

inline void checkContract(const QString &check, ScriptedRadioLink &link)
{
    QCOMPARE(link.state(), RadioLink::State::Closed);
    if (check == "opening")
        opening(link);
    else if (check == "read back")
        readBack(link);
    else if (check == "newest replaces waiting")
        newestReplacesWaiting(link);
    else if (check == "unsendable refused")
        unsendableRefused(link);
    else if (check == "closed refuses")
        closedRefuses(link);
    else if (check == "dropWaiting")
        dropWaiting(link);
    else if (check == "close mid-exchange")
        closeMidExchange(link);
    else
        QFAIL(qPrintable("no check " + check));
}

} // namespace radiolinkcontract
