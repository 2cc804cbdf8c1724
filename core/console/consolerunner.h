// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Carries out one slewctl command on a RotatorSession and says how it went:
// lines for the operator (plain or one JSON object a line), and an exit code
// that tells a script a refused move from a lost link from a bad argument.

#include "consolecommand.h"
#include "session/movewatch.h"

#include <QObject>
#include <QTimer>

#include <optional>
#include <utility>

#include <memory>

namespace slew::session {
class RotatorSession;
}
namespace slew::tuning {
class HomingRun;
}

namespace slew::console {

enum class ExitCode {
    Ok = 0,
    Failed = 1,      // the controller did not answer, a read-back differed, --wait timed out
    BadArgument = 2, // the words made no command
    LinkFailure = 3, // no link to the rotator, or it was lost
    Refused = 4,     // refused: by Slew (limits, no such command; nothing sent) or by the controller (`?`)
};

class ConsoleRunner : public QObject {
    Q_OBJECT
public:
    ConsoleRunner(session::RotatorSession *session, bool json, QObject *parent = nullptr);
    ~ConsoleRunner() override;

    // How long to wait for the link and the first position, and for --wait.
    void setConnectTimeout(int ms) { m_connectTimeoutMs = ms; }
    void setArrivalTimeout(int ms) { m_arrivalTimeoutMs = ms; }

    // Starts the command once the session is connected; finished() follows.
    void run(const ConsoleCommand &command);
    // Ctrl-C: ends a watch; stops the rotator if a --wait move is under way.
    void interrupt();
    bool isRunning() const { return m_running; }

signals:
    void output(const QString &line);
    void problem(const QString &line);
    void finished(slew::console::ExitCode code);

private:
    void whenReady();
    void start();
    void startGoto();
    void startWatch();
    void startRaw();
    void sendRawWhenQuiet();
    void startConfig();
    void startHome();
    void watchMove(std::optional<QPointF> target);
    void moveEnded(session::MoveWatch::Outcome outcome, QPointF at, double offDeg);
    void printPosition(const char *event);
    void finish(ExitCode code, const QString &problemText = {});
    void finishWhenSent(ExitCode code = ExitCode::Ok, const QString &problemText = {});

    session::RotatorSession *m_session;
    bool m_json;
    int m_connectTimeoutMs = 10000;
    int m_arrivalTimeoutMs = 600000;
    ConsoleCommand m_command;
    bool m_running = false;
    bool m_started = false;
    bool m_seenConnected = false; // "link lost" only for a link that was up
    session::MoveWatch m_move; // for --wait: how the move ended
    bool m_interrupted = false; // stopping on Ctrl-C: arrival is no longer judged
    QTimer m_deadline;
    QTimer m_tick;
    QByteArray m_rawAnswer;
    bool m_rawSent = false;
    std::unique_ptr<tuning::HomingRun> m_homing;
    QList<QMetaObject::Connection> m_connections; // undone when the command ends
};

} // namespace slew::console
