// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A server that speaks Hamlib's rotctld protocol, so Gpredict, the SatNOGS
// client or `rotctl -m 2` can steer the rotator through Slew while the
// operator watches and keeps the Stop button.
//
// It sits on a RotatorSession: every move goes through the session's limit
// checks (and its overlap choice), nothing here talks to the rotator. Each
// client is served on a thread of its own (rotctldclient.h): position reads
// are answered there, from the session's last reading, and everything else
// comes here, to the session's thread, one line at a time. A client that
// floods, sends an overlong line or vanishes disturbs no one else.

#include "input/logtext.h"
#include "rotctldclient.h"
#include "rotctldrequest.h"
#include "transport/boundedtcpserver.h"

#include <QDateTime>
#include <QHostAddress>
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <map>
#include <memory>

namespace slew::transport {
class BareConnection;
}

namespace slew::session {
class RotatorSession;
}

namespace slew::bridge {

class RotctldServer : public QObject {
    Q_OBJECT
public:
    using ClientInfo = RotctldClient::Info;

    static constexpr int kMaxLine = RotctldClient::kMaxLine; // longer lines are refused
    static constexpr int kDefaultMaxClients = transport::BoundedTcpServer::kDefaultMaxClients;

    explicit RotctldServer(session::RotatorSession *session, QObject *parent = nullptr);
    ~RotctldServer() override;

    // Binds to the address (127.0.0.1 unless the operator names another);
    // port 0 picks a free one. False with a message that says why.
    bool listen(const QHostAddress &address, quint16 port, QString *error);
    void close();
    bool isListening() const { return m_server.isListening(); }
    // How long a client's answers may wait for it to read before it is cut
    // off (RotctldClient::kSendTimeoutMs); for clients that connect after.
    void setSendTimeout(int ms) { m_shared.sendTimeoutMs = ms; }
    // Clients at once; one more reads `RPRT -9` (rejected) and is closed.
    void setMaxClients(int count) { m_server.setMaxClients(count); }
    int maxClients() const { return m_server.maxClients(); }
    QHostAddress address() const { return m_server.serverAddress(); }
    quint16 port() const { return m_server.serverPort(); }

    // Only these peers may connect; empty lets any in.
    void setAllowedClients(const QList<QHostAddress> &peers) { m_allowed = peers; }
    // A target within this many degrees of the one the rotator is still
    // going to (RotatorSession::activeTarget) is answered RPRT 0 and not
    // sent: trackers re-send P every cycle, and a relay rotator re-commanded
    // for every 0.1° chatters. After a stop, a local move, park, home or a
    // lost link there is no such target, so the same P goes out again.
    void setDeadband(double degrees) { m_deadband = degrees; }
    double deadband() const { return m_deadband; }

    // The operator stays in charge: while held, remote moves are refused
    // (RPRT -9); a remote stop is always obeyed.
    bool isRemoteHeld() const { return m_remoteHeld; }
    // `holder` says who has the rotator, for the log (the operator by default).
    void holdRemote(const QString &holder = QString());
    void releaseRemote();

    // Also log every command but position polls (the station service does;
    // the window shows them in the Trackers tab instead). Whatever is logged
    // about one client is escaped, cut at 200 characters and held to a rate
    // (LogAllowance): a hostile client cannot flood the log or write
    // terminal escapes into it.
    void setLogCommands(bool on) { m_logCommands = on; }

    QList<ClientInfo> clients() const;
    // The client that steered the rotator (a go-to or a move it was not
    // refused) within the last `withinMs`, or empty: Slew's own tracking
    // holds off while a remote tracker drives, as remote trackers are held
    // off while Slew tracks.
    static constexpr qint64 kSteeringQuietMs = 10000;
    QString remoteSteering(qint64 withinMs = kSteeringQuietMs) const;
    int movesSuppressedByDeadband() const { return m_suppressed; }

signals:
    void clientsChanged();
    // A client asked something. Position reads are said at most every
    // RotctldClient::kActivityIntervalMs, and only while this is connected.
    void commandReceived(const QString &peer, const QString &line);
    void remoteHeldChanged(bool held);
    void logMessage(const QString &message);

protected:
    void connectNotify(const QMetaMethod &signal) override;

private:
    struct Client {
        std::unique_ptr<RotctldClient> thread;
        transport::BareConnection *connection = nullptr; // held for the server's count of clients
        input::LogAllowance logAllowance;
        QString peer;
    };

    void onClientArrived(transport::BareConnection *connection);
    // Forgets a client whose thread has ended, or ends it.
    void drop(quint64 id);
    // The answer to what a client's thread handed over, delivered to it.
    void answerFor(quint64 id, const RotctldRequest &request);
    QByteArray answer(Client &client, const RotctldRequest &request);
    QByteArray answerRequest(Client &client, const RotctldRequest &request, const QString &command);
    // The session's reading, for the clients' threads.
    void sharePosition();
    // Non-zero (RIG_ENAVAIL) when the request wants elevation from an
    // azimuth-only rotator, which is then logged as refused.
    int refuseElevation(Client &c, const QString &command, bool wantsElevation);
    int setPosition(const RotctldRequest &r);
    void logClient(Client &client, const QString &text);
    void reportSuppressed(Client &client);
    void reportAllSuppressed();
    int move(const RotctldRequest &r);
    // `status` of a go-to or a move from `c`; a success is remembered as steering.
    int steered(const Client &c, int status);

    session::RotatorSession *m_session;
    transport::BoundedTcpServer m_server;
    RotctldClient::Shared m_shared;
    std::map<quint64, Client> m_clients;
    quint64 m_nextId = 1; // never reused: a late answer finds nobody
    QList<QHostAddress> m_allowed;
    double m_deadband = 0.5;
    bool m_remoteHeld = false;
    int m_suppressed = 0;
    QString m_lastSteering;         // the peer that last steered
    QString m_lastRefusal;          // why the session refused the request being answered
    QElapsedTimer m_lastSteeringAt; // when (invalid: never)
    bool m_logCommands = false;
    QElapsedTimer m_clock;
    QTimer m_suppressedReport; // runs while some client has lines held back
};

} // namespace slew::bridge
