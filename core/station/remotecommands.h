// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The commands a station takes from the broker (remote/remotecommand.h),
// obeyed under the same rules as every other face's:
//
//   - every move passes the session's limits gate, and a refusal is
//     answered in the gate's own words, as the window shows them;
//   - while the operator at the station holds remote control (after the
//     window's Stop, until control is handed back) remote moves are refused;
//   - while Slew's own tracking has the rotator, remote moves are refused
//     (as rotctld trackers are): untrack first;
//   - a jog is a lease (remotejog.h);
//   - a schedule is a move, held off as track is; ending one (unschedule)
//     is not, as untrack is not;
//   - a schedule's preview moves nothing and is answered later, with the
//     plan (one at a time: a newer one lets the one being planned go);
//   - the radio's hold is not a move: taken under any hold, handed back
//     to Doppler steering only when the operator at the station does not
//     hold remote control;
//   - Stop is always obeyed, hold or flood or not: every rotor stops.
//
// Commands arrive at most kPerSecond a second after a burst of kBurst;
// beyond that they are dropped unanswered (a stop still goes out), and the
// flood is logged once when it starts and once, with its count, when it ends.

#include "remote/remotecommand.h"
#include "session/sessiontypes.h"
#include "sky/elementsetformat.h"
#include "input/logtext.h"

#include <QObject>
#include <QTimer>

#include <optional>

namespace slew::station {

class RemoteJog;
class SchedulePreviewer;
class Station;

class RemoteCommands : public QObject {
    Q_OBJECT
public:
    static constexpr double kBurst = 20;
    static constexpr double kPerSecond = 10;

    // `elementSets`: the satellites a `track` may name besides those in the
    // station's element-set cache (the service's --tle).
    RemoteCommands(Station *station, const QList<sky::ElementSet> &elementSets, QObject *parent = nullptr);
    ~RemoteCommands() override;

    // Obeys one message from the command topic; the reply to publish when
    // the command has an id (none for a command dropped in a flood).
    std::optional<remote::RemoteReply> handle(const QByteArray &payload);
    // From now on every command but stop is refused with `why` (the station
    // is shutting down).
    void refuseFromNow(const QString &why) { m_refusing = why; }

    RemoteJog *jog() const { return m_jog; }
    int commandsDropped() const { return m_droppedTotal; }

signals:
    void logLine(const QString &line);
    // A reply that comes after handle() returned (a schedule's preview).
    void lateReply(const slew::remote::RemoteReply &reply);

private:
    session::CommandResult obey(const remote::RemoteCommand &command);
    session::CommandResult stopEveryRotor(const QString &cause);
    QString holdOnMoves() const; // why a remote move may not go now, or empty
    QString describe(const remote::RemoteCommand &command) const;
    session::CommandResult track(const remote::RemoteCommand &command);
    session::CommandResult schedule(const remote::RemoteCommand &command);
    session::CommandResult holdRadio(bool held);
    void endFlood();

    Station *m_station;
    QList<sky::ElementSet> m_elementSets;
    RemoteJog *m_jog;
    SchedulePreviewer *m_previewer;
    input::LogAllowance m_allowance{kBurst, kPerSecond}; // commands, not lines
    input::LogAllowance m_logAllowance;                  // what is logged of them
    QTimer m_floodEnd;    // quiet for a second: the flood has ended
    int m_dropped = 0;    // in the flood under way
    int m_droppedTotal = 0;
    QString m_refusing;
};

} // namespace slew::station
