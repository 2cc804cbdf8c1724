// SPDX-License-Identifier: GPL-3.0-or-later
#include "rotctldserver.h"

#include "session/rotatorsession.h"
#include "transport/tcpconnection.h"

#include <QTimer>

#include <algorithm>
#include <cmath>
#include <utility>

namespace slew::bridge {

using Kind = RotctldRequest::Kind;
using session::Axis;
using session::RotatorSession;

namespace {

constexpr qint64 kReadChunk = 16 * 1024; // per event, so a flood cannot starve the GUI
// A client that is done (its end of input, or `q`) but does not read its
// answers is cut off after this.
constexpr int kCloseLingerMs = 5000;

QString peerName(const transport::TcpConnection *c)
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

bool isQuit(QByteArrayView line)
{
    return line == "q" || line == "Q" || line == "\\quit";
}

double bearingDifference(double a, double b)
{
    const double d = std::fmod(std::abs(a - b), 360.0);
    return std::min(d, 360.0 - d);
}

int hamlibModelFor(protocol::Dialect d)
{
    switch (d) {
    case protocol::Dialect::Easycomm1: return 201;
    case protocol::Dialect::Easycomm2: return 202;
    case protocol::Dialect::Easycomm3:
    case protocol::Dialect::SatNogs: return 204;
    case protocol::Dialect::Gs232A: return 601;
    case protocol::Dialect::Gs232B: return 603;
    case protocol::Dialect::Rotctld: return 2; // netrotctl: Slew is itself behind a rotctld
    case protocol::Dialect::Micro2g: return 1; // Hamlib has no Micro-2g backend: its dummy
    case protocol::Dialect::Rot2Prog: return 901;
    case protocol::Dialect::Rot1Prog: return 902;
    case protocol::Dialect::Md01: return 903;
    }
    return 204;
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
    const auto connections = m_clients.keys();
    for (transport::TcpConnection *c : connections) {
        c->disconnect(this);
        c->abort();
        c->deleteLater();
    }
    const bool had = !m_clients.isEmpty();
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
    for (const Client &c : m_clients)
        out.append(c.info);
    return out;
}

void RotctldServer::onClientArrived(transport::TcpConnection *connection)
{
    if (!m_allowed.isEmpty() && !m_allowed.contains(connection->peerAddress())) {
        emit logMessage(tr("refused rotctld client %1: not in the allowed list").arg(peerName(connection)));
        connection->abort();
        connection->deleteLater();
        return;
    }
    if (!connection->isOpen()) { // could not be watched (out of memory for epoll)
        emit logMessage(tr("rotctld client %1 could not be served; closed").arg(peerName(connection)));
        connection->deleteLater();
        return;
    }
    connection->setNoDelay(true);
    Client c;
    c.connection = connection;
    c.info.peer = peerName(connection);
    c.info.lastSeen = QDateTime::currentDateTimeUtc();
    m_clients.insert(connection, c);
    // Said again while anything is left to read: one chunk a turn of the
    // event loop, so a flood cannot starve the rest.
    connect(connection, &transport::TcpConnection::readable, this, [this, connection] { onReadable(connection); });
    connect(connection, &transport::TcpConnection::closed, this, [this, connection] { drop(connection); });
    emit logMessage(tr("rotctld client %1 connected").arg(c.info.peer));
    emit clientsChanged();
}

void RotctldServer::drop(transport::TcpConnection *connection)
{
    const auto it = m_clients.find(connection);
    if (it == m_clients.end())
        return;
    connection->abort(); // if still open
    reportSuppressed(*it);
    emit logMessage(tr("rotctld client %1 left").arg(it->info.peer));
    m_clients.erase(it);
    connection->deleteLater();
    emit clientsChanged();
}

QByteArray RotctldServer::consume(Client &c, QByteArrayView bytes, bool *quit)
{
    QByteArray out;
    *quit = false;
    while (!bytes.isEmpty()) {
        // Up to the next line end, or all there is.
        const qsizetype end = std::find_if(bytes.begin(), bytes.end(), [](char ch) { return ch == '\n' || ch == '\r'; })
                              - bytes.begin();
        const bool ended = end < bytes.size();
        const QByteArrayView part = bytes.first(end);
        bytes = bytes.sliced(ended ? end + 1 : end);
        if (!c.discarding && c.buffer.size() + part.size() > kMaxLine) {
            // Refused once, then everything up to the line end is dropped.
            c.buffer.clear();
            c.discarding = true;
            out += "RPRT -1\n";
            logClient(c, tr("rotctld client %1 sent a line over %2 bytes; refused").arg(c.info.peer).arg(kMaxLine));
        }
        if (c.discarding) {
            c.discarding = !ended;
            continue;
        }
        if (!ended) {
            c.buffer += part;
            continue;
        }
        if (c.buffer.isEmpty() && part.isEmpty())
            continue; // the \n of \r\n, or an empty line
        // A line read whole is answered from where it was read.
        QByteArray joined;
        QByteArrayView line = part;
        if (!c.buffer.isEmpty()) {
            joined = std::exchange(c.buffer, {}).append(part);
            line = joined;
        }
        line = line.trimmed();
        if (isQuit(line)) {
            *quit = true;
            return out;
        }
        out += answer(c, line);
    }
    return out;
}

QByteArray RotctldServer::answerLastLine(Client &c)
{
    const QByteArray last = std::exchange(c.buffer, {}).trimmed();
    if (c.discarding || last.isEmpty() || isQuit(last))
        return {};
    return answer(c, last);
}

void RotctldServer::onReadable(transport::TcpConnection *connection)
{
    auto it = m_clients.find(connection);
    if (it == m_clients.end())
        return;
    Client &c = *it;
    // One chunk, read where it is answered from: no copy on the heap for
    // every line.
    char bytes[kReadChunk];
    const qint64 n = connection->read(bytes, sizeof bytes);
    if (!connection->isOpen()) { // reset: nobody to answer
        drop(connection);
        return;
    }
    if (n == 0) {
        if (connection->atEnd())
            finishInput(c);
        return;
    }
    bool quit = false;
    const QByteArray out = consume(c, QByteArrayView(bytes, n), &quit);
    // Every answer of this read leaves in one write: Gpredict reads a `p`
    // answer with a single recv.
    connection->write(out);
    if (quit)
        connection->finish(kCloseLingerMs);
    if (!connection->isOpen()) {
        drop(connection);
        return;
    }
    if (connection->bytesToWrite() > kMaxUnsentAnswers) {
        emit logMessage(tr("rotctld client %1 is not reading its answers; disconnected").arg(c.info.peer));
        drop(connection);
    }
}

void RotctldServer::finishInput(Client &c)
{
    transport::TcpConnection *connection = c.connection;
    connection->write(answerLastLine(c));
    // Closes once the answers have left; a client that never reads them is
    // cut off.
    connection->finish(kCloseLingerMs);
    if (!connection->isOpen())
        drop(connection);
}

QByteArray RotctldServer::answer(Client &c, QByteArrayView line)
{
    // Trackers send the same line over and over (`p`): it is read once.
    if (!c.lastRequest || line != QByteArrayView(c.lastLine)) {
        c.lastLine = line.toByteArray();
        c.lastRequest = parseRotctldLine(line);
        c.info.lastCommand = QString::fromLatin1(line.first(std::min<qsizetype>(line.size(), 80))).trimmed();
    }
    const RotctldRequest r = *c.lastRequest; // shares its bytes; c may go while it is answered
    // UTC: the local time would look up the time zone (a file) for every
    // answer; the Trackers tab shows it in local time.
    c.info.lastSeen = QDateTime::currentDateTimeUtc();
    ++c.info.commands;
    emit commandReceived(c.info.peer, c.info.lastCommand);

    // A tracker that steers has the move watched at the full rate from its
    // start (session/pollpace.h), also when the deadband holds its P back
    // (the rotator may still be on its way there) or the move is refused.
    // Reading does not wake it (wakesPolling says why).
    if (wakesPolling(r.kind))
        m_session->wakePolling();
    if (m_logCommands && r.kind != Kind::GetPosition && r.kind != Kind::Unknown && r.kind != Kind::Malformed)
        logClient(c, tr("rotctld %1: %2").arg(c.info.peer, c.info.lastCommand));
    const auto &profile = m_session->profile();
    switch (r.kind) {
    case Kind::GetPosition: {
        if (!m_session->isConnected() || !m_session->hasPosition())
            return formatStatus(r, int(HamlibError::Io));
        // Trackers speak 0..360: a position in the overlap is reported as its bearing.
        double az = std::fmod(m_session->azimuth(), 360.0);
        if (az < 0)
            az += 360.0;
        return m_positionAnswer.answer(r, az, m_session->elevation());
    }
    case Kind::SetPosition:
        if (const int refused = refuseElevation(c, r.el != 0.0); refused != 0)
            return formatStatus(r, refused);
        return formatStatus(r, steered(c, setPosition(r)));
    case Kind::Stop:
        return formatStatus(r, m_session->stop() ? 0 : int(HamlibError::Io));
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
                             .arg(c.info.peer)
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
                             .arg(c.info.peer, protocol::dialectName(m_session->profile().dialect)));
            return formatStatus(r, int(HamlibError::NotAvailable));
        }
        return formatStatus(r, m_session->home() ? 0 : int(HamlibError::InvalidArgument));
    case Kind::Move:
        if (const int refused = refuseElevation(c, (r.direction & (2 | 4 | 32 | 64 | 128 | 256)) != 0); refused != 0)
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
        return formatDumpState({l.azMin, l.azMax, l.elMin, l.elMax, hamlibModelFor(profile.dialect)});
    }
    case Kind::Quit:
        return {};
    case Kind::Unknown:
    case Kind::Malformed:
        // Logged once, as the refusal; the line itself is in it.
        logClient(c, tr("rotctld client %1: %2").arg(c.info.peer, r.error));
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
        emit logMessage(tr("%1 more lines from %2 suppressed").arg(n).arg(c.info.peer));
}

void RotctldServer::reportAllSuppressed()
{
    bool any = false;
    for (Client &c : m_clients) {
        reportSuppressed(c);
        any = any || c.logAllowance.suppressed() > 0;
    }
    if (!any)
        m_suppressedReport.stop();
}

int RotctldServer::refuseElevation(Client &c, bool wantsElevation)
{
    if (!wantsElevation || !m_session->isAzimuthOnly())
        return 0;
    // Hamlib's "feature not available" (RPRT -11): the rotator has no such
    // axis, which is not a position out of range (RPRT -1).
    logClient(c, tr("rotctld client %1: '%2' refused: this rotator turns azimuth only (send elevation 0)")
                     .arg(c.info.peer, c.info.lastCommand));
    return int(HamlibError::NotAvailable);
}

int RotctldServer::steered(const Client &c, int status)
{
    if (status == 0) {
        m_lastSteering = c.info.peer;
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
