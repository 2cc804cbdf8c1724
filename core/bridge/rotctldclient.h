// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One rotctld client, served on a thread of its own.
//
// Trackers ask for the position far more often than they ask for anything
// else (Gpredict, and the SatNOGS client, ten of them at 10 Hz on a busy
// station). Answered on the main thread, each `p` was a turn of its event
// loop: a poll over every descriptor the process watches, then the client's,
// then recv and send, four system calls beside everything else the loop
// does. Here the thread blocks in read() on its own socket and answers `p`
// from the last reading (SharedPosition) with one write(): the two system
// calls of Hamlib's own rotctld, which serves each client on a thread too,
// and the main thread does not wake at all.
//
// Everything else a client asks (a go-to, stop, park, a move, the limits)
// is the session's business and the session lives on the main thread: the
// line goes there (Hooks::answer, queued) and this thread waits for the
// answer before it reads the next line, so a client's answers come in the
// order of its questions and a move is never answered before the stop sent
// ahead of it. The main thread never waits for a client.
//
// Memory stays bounded whatever a client does: it reads a chunk, answers
// it, and reads no more until the answers have left.
//
// Lines are read as the main-thread server read them: at most kMaxLine
// bytes (longer ones are refused once, RPRT -1, and skipped to their end),
// \n or \r ends one, an unterminated last line is answered at the end of
// input, `q` ends the session once the answers before it have left. A
// client that stops reading its answers is cut off once a send has waited
// kSendTimeoutMs (Shared::sendTimeoutMs) with nothing taken; one that reads
// slowly, a little at a time, is a slow reader and stays.
//
// A plain thread, not a QThread: a QThread brings an event dispatcher, and
// with it a descriptor of its own (glib's wake-up eventfd), which would
// double what each client costs the process in descriptors, and fail (abort,
// in glib) just when they run short (transport/boundedtcpserver.h).

#include "positionanswer.h"
#include "rotctldrequest.h"
#include "sharedposition.h"

#include <QByteArray>
#include <QDateTime>
#include <QObject>
#include <QString>

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

namespace slew::bridge {

class RotctldClient : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxLine = 1024;
    static constexpr int kSendTimeoutMs = 5000;
    // `p` traffic is said to the main thread at most this often, and only
    // while somebody listens (RotctldServer::commandReceived).
    static constexpr int kActivityIntervalMs = 250;

    // What the client asked last and when, for the Trackers tab.
    struct Info {
        QString peer;        // "127.0.0.1:53422"
        QString lastCommand; // the last line received, at most 80 characters
        QDateTime lastSeen;  // UTC
        int commands = 0;
    };

    // Called on the main thread (the `home` object's), queued from this one,
    // with the client's id; a client that has gone meanwhile is not found.
    struct Hooks {
        // Must be followed by deliver() on the client with this id, if it
        // is still there.
        std::function<void(quint64 id, const RotctldRequest &request)> answer;
        std::function<void(quint64 id, const QString &text)> log;
        // `p` was asked (throttled, see kActivityIntervalMs).
        std::function<void(quint64 id)> activity;
        // The session is over (the client left, `q`, a reset, stop()):
        // the owner may now wait() and destroy it.
        std::function<void(quint64 id)> finished;
    };

    // What every client of one server shares.
    struct Shared {
        SharedPosition position;
        std::atomic<bool> activityWatched{false};
        std::atomic<int> sendTimeoutMs{kSendTimeoutMs}; // for clients that connect after a change
    };

    // Takes the descriptor (a connected TCP socket) and closes it when done.
    RotctldClient(quint64 id, int descriptor, const QString &peer, Shared *shared, QObject *home, Hooks hooks);
    ~RotctldClient() override; // stops and waits, when still running

    quint64 id() const { return m_id; }
    Info info() const;

    // Starts serving; false (the descriptor closed) when no thread could be made.
    bool start();
    // Returns once the thread has ended (after stop(), or Hooks::finished).
    void wait();

    // The answer to the line handed to Hooks::answer. Any thread.
    void deliver(const QByteArray &answer);
    // Ends the session at once: no more reading or answering, the socket
    // closed. Any thread; wait() returns soon after.
    void stop();

private:
    void run();
    // The answers to a chunk of input; true in *quit on `q`.
    QByteArray consume(const char *bytes, qsizetype size, bool *quit);
    // The answer to one line (empty for none).
    QByteArray answer(QByteArrayView line);
    // Asks the main thread and waits; nullopt when stopped meanwhile.
    std::optional<QByteArray> askHome(const RotctldRequest &request);
    // Every byte sent, or false (a reset, or a peer that stopped reading).
    bool sendAll(const QByteArray &bytes);
    void log(const QString &text);
    void noteActivity();
    // Shuts our end gracefully (`q`, end of input) or at once, and closes.
    void closeSocket(bool graceful);

    const quint64 m_id;
    const QString m_peer;
    Shared *const m_shared;
    QObject *const m_home;
    const Hooks m_hooks;
    std::thread m_thread;

    mutable std::mutex m_mutex; // guards everything below it
    std::condition_variable m_answered;
    int m_fd;
    bool m_stopping = false;
    std::optional<QByteArray> m_answer;
    Info m_info; // its peer is m_peer

    // This thread's own.
    QByteArray m_buffer;      // a line begun and not yet ended
    bool m_discarding = false; // inside an overlong line
    QByteArray m_lastLine;     // trackers repeat theirs (`p`): parsed once
    std::optional<RotctldRequest> m_lastRequest;
    PositionAnswer m_positionAnswer;
    qint64 m_lastActivityMs = -kActivityIntervalMs;
};

} // namespace slew::bridge
