// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// When commands go to a radio, whatever carries them (rigctld over TCP,
// libhamlib on a worker thread, the controller's UP/DN):
//
// - one command on the wire at a time;
// - at most one waiting per kind; a newer one replaces it where it stands
//   in line, so a slow CAT bus skips stale frequencies, never builds a
//   backlog, and a kind that is re-sent every cycle is not pushed to the
//   back by the others;
// - a minimum interval from the end of one command (its answer, or its
//   failure) to the start of the next, so a bus that needs quiet after a
//   reply gets it however slowly the radio answers.
//
// The pacer only decides when. It emits ready() with the command to send;
// the link sends it and calls finished() once it is answered or given up.
// An exchange that takes more than one command (a read of both
// frequencies, the link's opening) hands its next command to finished():
// that one keeps the wire, ahead of anything waiting, after the same
// interval. No timer runs while nothing waits. Pure Qt Core: no I/O.

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <optional>
#include <vector>

namespace slew::radio {

enum class CommandKind { ReceiveFrequency, TransmitFrequency, Mode, TransmitMode, Split, Read };

struct PacedCommand {
    CommandKind kind = CommandKind::Read;
    QString text; // what goes on the wire, without its line end
    int tag = 0;  // the link's own mark of what this exchange is; untouched here
    // What a setting carries, for a link that hands it on as a value rather
    // than as text (the controller's UP/DN): the newest, as the command is.
    double hz = 0;
    QString mode{};
};

class CommandPacer : public QObject {
    Q_OBJECT
public:
    explicit CommandPacer(QObject *parent = nullptr);

    // Queues the command, or replaces the one of its kind still waiting.
    void submit(const PacedCommand &command);
    // The same, ahead of every waiting command (an exchange's follow-up
    // still goes first): for a command that answers what was just read,
    // and is worth less the longer it waits.
    void submitFirst(const PacedCommand &command);
    // The command on the wire is done; `next`, when given, goes next.
    void finished(const std::optional<PacedCommand> &next = std::nullopt);
    // Forgets the command on the wire and every waiting one (link closed).
    void clear();
    // Forgets the waiting commands; the one on the wire, and the rest of its
    // exchange, go on.
    void dropWaiting();

    void setMinimumIntervalMs(int ms);
    int minimumIntervalMs() const { return m_minimumIntervalMs; }

    const std::optional<PacedCommand> &inFlight() const { return m_inFlight; }
    bool isBusy() const { return m_inFlight.has_value(); }
    // Waiting commands, a follow-up included.
    qsizetype waitingCount() const { return qsizetype(m_waiting.size()) + (m_followUp ? 1 : 0); }
    // How many waiting commands a newer one of their kind replaced, since made.
    int replacedCount() const { return m_replaced; }

signals:
    // Send this now; call finished() when it is done.
    void ready(const slew::radio::PacedCommand &command);

private:
    void pump();
    qint64 quietLeftMs() const;

    std::optional<PacedCommand> m_inFlight;
    std::optional<PacedCommand> m_followUp;
    std::vector<PacedCommand> m_waiting; // in line; one per kind at most
    QElapsedTimer m_sinceFinished;       // invalid until a command finished
    QTimer m_quietTimer;                 // runs only while a command waits out the interval
    int m_minimumIntervalMs = 0;
    int m_replaced = 0;
    bool m_pumping = false;
};

} // namespace slew::radio
