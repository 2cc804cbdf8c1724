// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The controller board's command interpreter: Easycomm bytes in, answers
// out, acting on a SimulatedRotator. One per connection (each host has its
// own parser state and its own view of what was pushed to it); the rotator
// and the counters are shared.
//
// Answers to the queries of one input line leave as one output line, joined
// by spaces: Hamlib 4.5 and SatNOGS send `AZ EL` and read `AZ10.0 EL20.0`
// back on a single line, Hamlib 4.6 sends `AZ` and `EL` on lines of their own
// and so gets two. The GS-232 dialects answer as a Yaesu controller does:
// `+0aaa+0eee` or `AZ=aaa  EL=eee` ended by CR LF, and `?>` for what it cannot
// read. No I/O here: the caller moves the bytes.

#include "firmwarecounters.h"
#include "simulatedrotator.h"
#include "simulatoroptions.h"
#include "spidfirmware.h"

#include "protocol/dialect.h"
#include "protocol/message.h"
#include "protocol/parser.h"

#include <QByteArray>
#include <QHash>
#include <QStringList>

#include <functional>
#include <optional>

namespace slew::sim {

class SimulatorFirmware {
public:
    SimulatorFirmware(SimulatedRotator &rotator, FirmwareCounters &counters, protocol::Dialect dialect);

    protocol::Dialect dialect() const { return m_dialect; }

    // The Micro-2g dialect is served by its own controller program
    // (micro2g/micro2gcontroller.h), shared by every connection: this
    // firmware then only cuts the bytes into lines, hands each to
    // `controller` and ends every reply line with CR LF.
    using LineHandler = std::function<QStringList(const QString &line)>;
    void serveMicro2g(LineHandler controller) { m_micro2g = std::move(controller); }
    // The SPID dialects have no lines: a SpidFirmware reads their frames,
    // and the line machinery below (line ends, alarms, unsolicited
    // reports) stays idle. Made by the constructor for a SPID dialect; this
    // replaces its settings.
    void configureSpid(const SpidSettings &settings);
    // Answer as this firmware does (simulatoroptions.h); Slew's own by default.
    void setFirmware(Firmware firmware) { m_firmware = firmware; }
    Firmware firmware() const { return m_firmware; }

    // Feeds bytes from the host; returns what the device answers to them
    // (possibly nothing, possibly several lines). At most a few alarms per
    // call; the rest are counted and summarised as `ALsuppressed:n`.
    QByteArray receive(QByteArrayView bytes);

    // True when the input so far ended in a space: the Easycomm III derivative lets a command
    // end on a space alone, so the caller gives it a moment and then calls
    // endLine() rather than wait for a line end that may never come.
    bool awaitingLineEnd() const { return m_awaitingLineEnd; }
    // Bytes of a line wait for its end (the host may never send it).
    bool hasUnfinishedLine() const
    {
        if (m_spid)
            return false; // a part frame waits for its bytes: SPID has no line to end
        return m_micro2g ? !m_micro2gLine.isEmpty() : m_parser.hasUnfinishedLine();
    }
    QByteArray endLine();

    // the Easycomm III derivative's unsolicited reports: every field whose text differs from
    // what this host was last sent, one per line. The first call sends all.
    QByteArray unsolicitedChanges();

    // The version string VE reports in this dialect.
    QByteArray version() const;

private:
    QByteArray receiveMicro2g(QByteArrayView bytes);
    void handle(const protocol::Message &m, QByteArray &out);
    void manualMove(protocol::Op op); // ML MR MU MD at the manual speed, SA SE
    void answer(const QByteArray &token);
    void alarm(const char *kind, QByteArrayView what, QByteArray &out);
    void refuse(const protocol::Message &m, QByteArray &out);
    void finishLine(QByteArray &out);
    // K3NG's (simulatorfirmware_k3ng.cpp).
    bool pointAzimuth(double degrees); // within K3NG's tolerance, short of the target
    bool speaksK3ngEasycom() const;
    void handleK3ngEasycom(const protocol::Message &m, QByteArray &out);
    QByteArray reportSeparator() const; // between two answers on one line
    // The SatNOGS firmware's (simulatorfirmware_satnogs.cpp).
    int registerRead(int asked) const; // which register a CR n reads
    int combinedStatus() const;        // GS for the whole rotator
    void stopAxis(Axis axis);          // SA, SE: let go, or hold where read (SatNOGS)
    bool answersAtAll() const { return m_dialect != protocol::Dialect::Easycomm1; }
    bool sendsAlarms() const;

    QByteArray angle(protocol::Op op, double degrees) const;
    QByteArray inputReply(int index, double value) const;
    QByteArray registerReply(int index, double value) const;
    QByteArray velocityReply(protocol::Op op) const;

    SimulatedRotator &m_rotator;
    FirmwareCounters &m_counters;
    protocol::Dialect m_dialect;
    Firmware m_firmware = Firmware::Generic;
    protocol::Parser m_parser;
    QByteArray m_lineAnswers;
    bool m_awaitingLineEnd = false;
    int m_alarmsThisChunk = 0;   // alarms raised by the bytes of one receive()
    int m_suppressedAlarms = 0;  // past the cap, summarised in one line

    // Radio fields of Easycomm I/II: kept and read back, used for nothing.
    QHash<int, QByteArray> m_radio;
    QHash<int, int> m_outputs;
    QByteArray m_time;
    double m_manualSpeedShare = 1.0; // GS-232's X1..X4: a quarter to all of the manual speed

    QHash<QByteArray, QByteArray> m_pushed; // field -> last text pushed

    std::optional<SpidFirmware> m_spid;
    LineHandler m_micro2g;
    QByteArray m_micro2gLine;
    bool m_micro2gOverlong = false;
};

} // namespace slew::sim
