// SPDX-License-Identifier: GPL-3.0-or-later
#include "rotctldserver.h"

#include "session/rotatorsession.h"
#include "transport/bareconnection.h"

#include <QMetaMethod>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <utility>

namespace slew::bridge {

using Kind = RotctldRequest::Kind;
using session::Axis;
using session::RotatorSession;

namespace {

QString peerName(const transport::BareConnection *c)
{
    return QStringLiteral("%1:%2").arg(c->peerAddress().toString()).arg(c->peerPort());
}

// Only requests that may move the rotator wake the session's full rate.
// A tracker that only reads (Gpredict asks `p` every cycle, engaged all day
// long) leaves a resting station at the rest rate: waking on every read
// would keep a watched station at the full rate for good. Its answers stay
// true: at rest the rotator stood still at the last poll, and nothing Slew
// sends has moved it since (a command wakes the full rate). Only something
// outside Slew can move it (the controller's own buttons); that shows
// within one rest interval (1 s by default) and is watched at the full rate
// from then on, so a reading tracker sees it at most about one Gpredict
// cycle (1 s by default) late. A rotator that stops answering is noticed at
// the rest rate's pace, a few seconds, as with nobody asking.
bool wakesPolling(RotctldRequest::Kind kind)
{
    switch (kind) {
    case Kind::SetPosition:
    case Kind::Stop:
    case Kind::Park:
    case Kind::Reset:
    case Kind::Move:
        return true;
    case Kind::GetPosition:
    case Kind::GetInfo:
    case Kind::DumpState:
    case Kind::Quit:
    case Kind::Unknown:
    case Kind::Malformed:
        return false;
    }
    return false;
}

double bearingDifference(double a, double b)
{
    const double d = std::fmod(std::abs(a - b), 360.0);
    return std::min(d, 360.0 - d);
}

} // namespace

RotctldServer::RotctldServer(session::RotatorSession *session, QObject *parent)
    : QObject(parent), m_session(session)
{
    // Hamlib's "command rejected": netrotctl reports it when it opens,
    // Gpredict counts it as a failed cycle.
    m_server.setRefusal("RPRT -9\n");
    m_clock.start();
    m_suppressedReport.setInterval(5000);
    connect(&m_suppressedReport, &QTimer::timeout, this, &RotctldServer::reportAllSuppressed);
    m_server.setBareConnections(true);
    connect(&m_server, &transport::BoundedTcpServer::connectionArrived, this, &RotctldServer::onClientArrived);
    connect(&m_server, &transport::BoundedTcpServer::notice, this,
            [this](const QString &text) { emit logMessage(tr("rotctld server: %1").arg(text)); });
    // Every reading, and every change of link, reaches the clients' threads.
    connect(m_session, &RotatorSession::commandRefused, this, [this](const QString &why) { m_lastRefusal = why; });
    connect(m_session, &RotatorSession::positionChanged, this, &RotctldServer::sharePosition);
    connect(m_session, &RotatorSession::stateChanged, this, &RotctldServer::sharePosition);
    sharePosition();
}

void RotctldServer::sharePosition()
{
    SharedPosition::Reading reading;
    // Only what this link has read: the last link's position, shown stale
    // in the window, would have a tracker steer from where the antenna was.
    reading.known = m_session->isConnected() && m_session->positionReadOnThisLink();
    if (reading.known) {
        // Trackers speak 0..360: a position in the overlap is reported as its bearing.
        reading.azimuth = std::fmod(m_session->azimuth(), 360.0);
        if (reading.azimuth < 0)
            reading.azimuth += 360.0;
        reading.elevation = m_session->elevation();
    }
    m_shared.position.set(reading);
}

void RotctldServer::connectNotify(const QMetaMethod &signal)
{
    // Position reads are said only to someone who listens: a station
    // service with nobody watching is not woken by them.
    if (signal == QMetaMethod::fromSignal(&RotctldServer::commandReceived))
        m_shared.activityWatched = true;
}

RotctldServer::~RotctldServer()
{
    close();
}

bool RotctldServer::listen(const QHostAddress &address, quint16 port, QString *error)
{
    close();
    if (!m_server.listen(address, port)) {
        if (error)
            *error = tr("cannot listen on %1:%2: %3").arg(address.toString()).arg(port).arg(m_server.errorString());
        return false;
    }
    emit logMessage(tr("rotctld server listening on %1:%2").arg(m_server.serverAddress().toString()).arg(m_server.serverPort()));
    return true;
}

void RotctldServer::close()
{
    m_server.close();
    const bool had = !m_clients.empty();
    // Each thread is woken (its socket shut) before any is waited for.
    for (auto &[id, c] : m_clients)
        c.thread->stop();
    for (auto &[id, c] : m_clients) {
        c.thread->wait();
        c.connection->deleteLater();
    }
    m_clients.clear();
    if (had)
        emit clientsChanged();
}

void RotctldServer::holdRemote(const QString &holder)
{
    if (m_remoteHeld)
        return;
    m_remoteHeld = true;
    emit remoteHeldChanged(true);
    emit logMessage(tr("remote control held by %1: remote moves are refused")
                        .arg(holder.isEmpty() ? tr("the operator") : holder));
}

void RotctldServer::releaseRemote()
{
    if (!m_remoteHeld)
        return;
    m_remoteHeld = false;
    emit remoteHeldChanged(false);
    emit logMessage(tr("remote control handed back"));
}

QList<RotctldServer::ClientInfo> RotctldServer::clients() const
{
    QList<ClientInfo> out;
    for (const auto &[id, c] : m_clients)
        out.append(c.thread->info());
    return out;
}

void RotctldServer::onClientArrived(transport::BareConnection *connection)
{
    if (!m_allowed.isEmpty() && !m_allowed.contains(connection->peerAddress())) {
        emit logMessage(tr("refused rotctld client %1: not in the allowed list").arg(peerName(connection)));
        connection->abort();
        connection->deleteLater();
        return;
    }
    connection->setNoDelay(true);
    const quint64 id = m_nextId++;
    const QString peer = peerName(connection);
    RotctldClient::Hooks hooks;
    hooks.answer = [this](quint64 client, const RotctldRequest &request) { answerFor(client, request); };
    hooks.log = [this](quint64 client, const QString &text) {
        if (const auto it = m_clients.find(client); it != m_clients.end())
            logClient(it->second, text);
    };
    hooks.activity = [this](quint64 client) {
        if (const auto it = m_clients.find(client); it != m_clients.end())
            emit commandReceived(it->second.peer, it->second.thread->info().lastCommand);
    };
    hooks.finished = [this](quint64 client) { drop(client); };
    Client &c = m_clients[id];
    c.peer = peer;
    c.connection = connection;
    // The connection object stays here, without its descriptor, as the
    // listening server's count of this client until it leaves.
    c.thread = std::make_unique<RotctldClient>(id, connection->takeDescriptor(), peer, &m_shared, this, hooks);
    if (!c.thread->start()) {
        emit logMessage(tr("rotctld client %1 could not be served (no thread for it); closed").arg(peer));
        connection->deleteLater();
        m_clients.erase(id);
        return;
    }
    emit logMessage(tr("rotctld client %1 connected").arg(peer));
    emit clientsChanged();
}

void RotctldServer::drop(quint64 id)
{
    const auto it = m_clients.find(id);
    if (it == m_clients.end())
        return;
    Client &c = it->second;
    c.thread->stop();
    c.thread->wait();
    reportSuppressed(c);
    emit logMessage(tr("rotctld client %1 left").arg(c.peer));
    c.connection->deleteLater();
    m_clients.erase(it);
    emit clientsChanged();
}

void RotctldServer::answerFor(quint64 id, const RotctldRequest &request)
{
    const auto it = m_clients.find(id);
    if (it == m_clients.end())
        return; // gone meanwhile: its thread has stopped waiting
    it->second.thread->deliver(answer(it->second, request));
}

QByteArray RotctldServer::answer(Client &c, const RotctldRequest &r)
{
    const QString command = c.thread->info().lastCommand;
    emit commandReceived(c.peer, command);
    // The client hears Hamlib's code; the log hears why the session said no
    // ("no position read from the controller: check the dialect", a limit).
    m_lastRefusal.clear();
    const QByteArray reply = answerRequest(c, r, command);
    if (!m_lastRefusal.isEmpty())
        logClient(c, tr("rotctld client %1: '%2' refused: %3").arg(c.peer, command, std::exchange(m_lastRefusal, {})));
    return reply;
}

QByteArray RotctldServer::answerRequest(Client &c, const RotctldRequest &r, const QString &command)
{
    // A tracker that steers has the move watched at the full rate from its
    // start (session/pollpace.h), also when the deadband holds its P back
    // (the rotator may still be on its way there) or the move is refused.
    // Reading does not wake it (wakesPolling says why).
    if (wakesPolling(r.kind))
        m_session->wakePolling();
    if (m_logCommands && r.kind != Kind::GetPosition && r.kind != Kind::Unknown && r.kind != Kind::Malformed)
        logClient(c, tr("rotctld %1: %2").arg(c.peer, command));
    const auto &profile = m_session->profile();
    switch (r.kind) {
    case Kind::GetPosition: { // answered by the client's thread; this for completeness
        const SharedPosition::Reading reading = m_shared.position.get();
        if (!reading.known)
            return formatStatus(r, int(HamlibError::Io));
        return formatPosition(r, reading.azimuth, reading.elevation);
    }
    case Kind::SetPosition:
        if (const int refused = refuseElevation(c, command, r.el != 0.0); refused != 0)
            return formatStatus(r, refused);
        return formatStatus(r, steered(c, setPosition(r)));
    case Kind::Stop:
        return formatStatus(r, m_session->stop(tr("rotctld client %1: S").arg(c.peer)) ? 0 : int(HamlibError::Io));
    case Kind::Park:
        if (m_remoteHeld)
            return formatStatus(r, int(HamlibError::Rejected));
        if (!m_session->isConnected())
            return formatStatus(r, int(HamlibError::Io));
        return formatStatus(r, m_session->park() ? 0 : int(HamlibError::InvalidArgument));
    case Kind::Reset:
        // Hamlib's reset takes a type, and 1 ("reset all") is the only one.
        if (r.resetType != 1) {
            logClient(c, tr("rotctld client %1: reset type %2 means nothing; only 1 (reset all)")
                             .arg(c.peer)
                             .arg(r.resetType));
            return formatStatus(r, int(HamlibError::InvalidArgument));
        }
        if (m_remoteHeld)
            return formatStatus(r, int(HamlibError::Rejected));
        if (!m_session->isConnected())
            return formatStatus(r, int(HamlibError::Io));
        if (!protocol::dialectSupports(m_session->profile().dialect, protocol::Op::Reset)) {
            // No homing command in this dialect (a SPID controller, GS-232):
            // Hamlib's "feature not available", not a bad argument.
            logClient(c, tr("rotctld client %1: reset refused: %2 has no homing command")
                             .arg(c.peer, protocol::dialectName(m_session->profile().dialect)));
            return formatStatus(r, int(HamlibError::NotAvailable));
        }
        return formatStatus(r, m_session->home() ? 0 : int(HamlibError::InvalidArgument));
    case Kind::Move:
        if (const int refused = refuseElevation(c, command, (r.direction & (2 | 4 | 32 | 64 | 128 | 256)) != 0); refused != 0)
            return formatStatus(r, refused);
        return formatStatus(r, steered(c, move(r)));
    case Kind::GetInfo: {
        QString info = QStringLiteral("Slew rotator bridge");
        if (!m_session->version().isEmpty())
            info += QStringLiteral(" (%1)").arg(m_session->version());
        return formatInfo(r, info);
    }
    case Kind::DumpState: {
        // The travel a client may command: the gate's, in the pointing frame
        // (an azimuth-only rotator's elevation range is the single value 0).
        const model::RotatorLimits l = m_session->moveGate().limits();
        return formatDumpState({l.azMin, l.azMax, l.elMin, l.elMax, protocol::dialectRow(profile.dialect).hamlibModel});
    }
    case Kind::Quit:
        return {};
    case Kind::Unknown:
    case Kind::Malformed:
        // Logged once, as the refusal; the line itself is in it.
        logClient(c, tr("rotctld client %1: %2").arg(c.peer, r.error));
        return formatStatus(r, int(HamlibError::InvalidArgument));
    }
    return formatStatus(r, int(HamlibError::InvalidArgument));
}

void RotctldServer::logClient(Client &c, const QString &text)
{
    if (!c.logAllowance.take(m_clock.elapsed())) {
        if (!m_suppressedReport.isActive())
            m_suppressedReport.start();
        return;
    }
    reportSuppressed(c);
    emit logMessage(input::loggableText(text));
}

void RotctldServer::reportSuppressed(Client &c)
{
    if (const int n = c.logAllowance.takeSuppressed(); n > 0)
        emit logMessage(tr("%1 more lines from %2 suppressed").arg(n).arg(c.peer));
}

void RotctldServer::reportAllSuppressed()
{
    bool any = false;
    for (auto &[id, c] : m_clients) {
        reportSuppressed(c);
        any = any || c.logAllowance.suppressed() > 0;
    }
    if (!any)
        m_suppressedReport.stop();
}

int RotctldServer::refuseElevation(Client &c, const QString &command, bool wantsElevation)
{
    if (!wantsElevation || !m_session->isAzimuthOnly())
        return 0;
    // Hamlib's "feature not available" (RPRT -11): the rotator has no such
    // axis, which is not a position out of range (RPRT -1).
    logClient(c, tr("rotctld client %1: '%2' refused: this rotator turns azimuth only (send elevation 0)")
                     .arg(c.peer, command));
    return int(HamlibError::NotAvailable);
}

int RotctldServer::steered(const Client &c, int status)
{
    if (status == 0) {
        m_lastSteering = c.peer;
        m_lastSteeringAt.start();
    }
    return status;
}

QString RotctldServer::remoteSteering(qint64 withinMs) const
{
    return m_lastSteeringAt.isValid() && m_lastSteeringAt.elapsed() <= withinMs ? m_lastSteering : QString();
}

int RotctldServer::setPosition(const RotctldRequest &r)
{
    if (m_remoteHeld)
        return int(HamlibError::Rejected);
    if (!m_session->isConnected())
        return int(HamlibError::Io);
    // The deadband is measured from where the rotator is going now. After a
    // stop, a jog, park, home or a new link there is no such target, and a
    // tracker's repeated P goes out again.
    if (const auto active = m_session->activeTarget();
        active && bearingDifference(r.az, active->azimuth) < m_deadband && std::abs(r.el - active->elevation) < m_deadband) {
        // Still checked: a target inside the deadband of a legal one can be illegal.
        if (m_session->previewPointing(r.az, r.el).allowed()) {
            ++m_suppressed;
            return 0;
        }
    }
    // Hamlib 4.5 answers an out-of-range position with RPRT -1 (invalid argument).
    return m_session->gotoPosition(r.az, r.el) ? 0 : int(HamlibError::InvalidArgument);
}

int RotctldServer::move(const RotctldRequest &r)
{
    if (m_remoteHeld)
        return int(HamlibError::Rejected);
    if (!m_session->isConnected())
        return int(HamlibError::Io);
    // Hamlib's speed is 1..100 (-1: unchanged); Slew maps it to 0.1..10 °/s,
    // the range Hamlib's Easycomm III backend sends ((speed-1)*100 mdeg/s).
    const int speed = r.speed < 0 ? 50 : std::clamp(r.speed, 1, 100);
    const double degreesPerSecond = speed / 10.0;
    bool ok = true;
    bool any = false;
    auto go = [&](Axis axis, double v) {
        any = true;
        ok = m_session->moveAxis(axis, v) && ok;
    };
    const int d = r.direction;
    if (d & (2 | 32 | 64))
        go(Axis::Elevation, degreesPerSecond); // up, up-left, up-right
    if (d & (4 | 128 | 256))
        go(Axis::Elevation, -degreesPerSecond); // down, down-left, down-right
    if (d & (8 | 32 | 128))
        go(Axis::Azimuth, -degreesPerSecond); // left / CCW
    if (d & (16 | 64 | 256))
        go(Axis::Azimuth, degreesPerSecond); // right / CW
    if (!any)
        return int(HamlibError::InvalidArgument);
    return ok ? 0 : int(HamlibError::InvalidArgument);
}

} // namespace slew::bridge
