#pragma once
// One simulated device as every endpoint shares it: the clock, the rotator,
// the line conditions and the settings the firmware answers with. A TCP
// server with three clients, a pseudo-terminal and an in-process link all
// talk to the same Simulator when they serve the same rotator.

#include "firmwarecounters.h"
#include "micro2g/micro2gcontroller.h"
#include "linkfaults.h"
#include "simclock.h"
#include "simulatedrotator.h"
#include "simulatoroptions.h"

#include <QObject>
#include <QTimer>

#include <memory>

namespace slew::sim {

class Simulator : public QObject {
    Q_OBJECT
public:
    explicit Simulator(const SimulatorOptions &options, QObject *parent = nullptr);

    SimClock &clock() { return m_clock; }
    const SimClock &clock() const { return m_clock; }
    SimulatedRotator &rotator() { return m_rotator; }
    const SimulatedRotator &rotator() const { return m_rotator; }
    const SimulatorOptions &options() const { return m_options; }

    // Brings the physics up to the clock's present; the firmware calls it
    // before it answers, so a reply is never a moment old. On the wall
    // clock nothing else runs the physics: a simulator nobody talks to
    // does nothing at all.
    void syncToNow();

    // A connection that pushes changes unsolicited (the Easycomm III
    // derivative's controller) needs the rotator run while it changes: on
    // the wall clock, ticked() then comes every kPushTickMs while it moves,
    // every kCoolingTickMs while only a motor's temperature still drifts,
    // and not at all once the rotator is at rest (SimulatedRotator::atRest).
    // Counted, one a connection.
    static constexpr int kPushTickMs = 25;
    static constexpr int kCoolingTickMs = 1000;
    void addPushListener();
    void removePushListener();
    // The firmware was just given input: a command may have set the
    // rotator moving, for the pushes to follow.
    void noteInput();

    // Manual clock: advance time (and the rotator) by this much.
    void advance(double seconds) { m_clock.advance(seconds); }

    void setAxisFaults(Axis axis, const AxisFaults &faults);
    LinkFaults linkFaults() const { return m_linkFaults; }
    void setLinkFaults(const LinkFaults &faults);

    // Cuts every open connection now, as if the cable were pulled.
    void dropConnections() { emit connectionsDropped(); }

    // The Micro-2g controller program, for connections in the micro2g
    // dialect: made on first use and run on this simulator's clock. Its
    // settings are read from options().stateFile when the simulator starts
    // and written back after every command that changes them.
    Micro2gController &micro2g();
    // One command line to that program, at the clock's present; its replies.
    QStringList handleMicro2g(const QString &line);
    // What went wrong reading or writing the state file, if anything.
    QString stateFileError() const { return m_stateFileError; }

    // Shared by every connection's firmware.
    FirmwareCounters &counters() { return m_counters; }
    const FirmwareCounters &counters() const { return m_counters; }

signals:
    // The rotator advanced: push and release what is due. On a manual
    // clock with every advance(); on the wall clock only for push listeners.
    void ticked();
    void linkFaultsChanged();
    void connectionsDropped();
    // The state file could not be written while running: the settings the
    // controller was just given will not survive a restart.
    void stateFileFailed(const QString &error);

private:
    void pushTick();

    SimulatorOptions m_options;
    SimClock m_clock;
    SimulatedRotator m_rotator;
    LinkFaults m_linkFaults;
    FirmwareCounters m_counters;
    std::unique_ptr<Micro2gController> m_micro2g;
    double m_micro2gAt = 0.0; // the clock time the controller has been run up to
    QString m_stateFileError;
    int m_pushListeners = 0;
    QTimer m_pushTick; // wall clock only: runs while a listener waits and the rotator is not at rest
};

} // namespace slew::sim
