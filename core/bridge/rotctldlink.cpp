#include "rotctldlink.h"

#include "input/finitenumber.h"

#include "protocol/dialect.h"
#include "rotctldrequest.h"
#include "transport/linkfactory.h"

namespace slew::bridge {

RotctldLink::RotctldLink(const QString &uri, QString host, quint16 port, QObject *parent)
    : Link(uri, parent), m_host(std::move(host)), m_port(port)
{
    connect(&m_socket, &QTcpSocket::connected, this, &RotctldLink::onConnected);
    connect(&m_socket, &QTcpSocket::errorOccurred, this, &RotctldLink::onSocketError);
    // First of the socket's readers: see the header.
    connect(&m_socket, &QTcpSocket::readyRead, this, &RotctldLink::onHandshakeBytes);
    m_handshakeTimer.setSingleShot(true);
    m_handshakeTimer.setInterval(kHandshakeTimeoutMs);
    connect(&m_handshakeTimer, &QTimer::timeout, this,
            [this] { fail(tr("%1: rotctld did not answer \\dump_state").arg(this->uri())); });
}

void RotctldLink::registerScheme()
{
    transport::registerLinkScheme(QStringLiteral("rotctld"), [](const QUrl &url, const QString &uri) {
        if (url.host().isEmpty())
            return transport::LinkResult{nullptr, QObject::tr("%1: no host named (expected rotctld://host:port)").arg(uri)};
        const int port = url.port(4533); // rotctld's default port
        return transport::LinkResult{std::make_unique<RotctldLink>(uri, url.host(), quint16(port)), {}};
    });
}

transport::LinkHints RotctldLink::hints() const
{
    transport::LinkHints h;
    h.dialect = protocol::dialectName(protocol::Dialect::Rotctld);
    h.dialectFixed = true;
    return h;
}

void RotctldLink::open()
{
    m_open = false;
    m_opening = true;
    m_handshake.clear();
    m_socket.abort();
    m_socket.connectToHost(m_host, m_port);
}

void RotctldLink::close()
{
    m_opening = false;
    m_open = false;
    m_handshakeTimer.stop();
    // `q` tells rotctld this client is done, as Hamlib's own client says it.
    if (m_socket.state() == QAbstractSocket::ConnectedState)
        m_socket.write("q\n");
    m_socket.disconnectFromHost();
}

void RotctldLink::onConnected()
{
    m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    m_handshakeTimer.start();
    m_socket.write("\\dump_state\n");
}

void RotctldLink::fail(const QString &reason)
{
    const bool wasOpen = m_open;
    const bool wasOpening = m_opening;
    m_open = m_opening = false;
    m_handshakeTimer.stop();
    m_socket.abort();
    if (wasOpen)
        emit lost(reason);
    else if (wasOpening)
        emit failed(reason);
}

void RotctldLink::onSocketError()
{
    if (m_socket.error() == QAbstractSocket::RemoteHostClosedError && m_open)
        fail(tr("%1: rotctld closed the connection").arg(uri()));
    else
        fail(tr("%1: %2").arg(uri(), m_socket.errorString()));
}

void RotctldLink::onHandshakeBytes()
{
    if (!m_opening || m_socket.state() != QAbstractSocket::ConnectedState)
        return; // open: the bytes are the session's
    m_handshake += m_socket.readAll();
    // The answer ends with a line `done`; an error instead is one RPRT line.
    if (m_handshake.startsWith("RPRT ") && m_handshake.contains('\n')) {
        const int code = m_handshake.mid(5, m_handshake.indexOf('\n') - 5).trimmed().toInt();
        fail(tr("%1: rotctld refused \\dump_state: %2").arg(uri(), describeHamlibError(code)));
        return;
    }
    if (m_handshake.startsWith("done\n") || m_handshake.contains("\ndone\n")) {
        finishHandshake();
        return;
    }
    if (m_handshake.size() > kMaxHandshakeBytes)
        fail(tr("%1: \\dump_state did not end within %2 bytes").arg(uri()).arg(kMaxHandshakeBytes));
}

void RotctldLink::finishHandshake()
{
    // Only the limits matter to Slew; the rest (protocol version, model,
    // south_zero, rot_type) is left. A rotctld that leaves a limit out
    // gets Hamlib's own defaults for a rotator.
    double azMin = 0, azMax = 360, elMin = 0, elMax = 90;
    for (const QByteArray &line : m_handshake.split('\n')) {
        const qsizetype eq = line.indexOf('=');
        if (eq < 0)
            continue;
        const QByteArray key = line.left(eq).trimmed();
        // A peer's limits are numbers from outside: finite ones only.
        const std::optional<double> value = input::finiteNumber(QString::fromLatin1(line.mid(eq + 1)));
        if (!value)
            continue;
        const double v = *value;
        if (key == "min_az")
            azMin = v;
        else if (key == "max_az")
            azMax = v;
        else if (key == "min_el")
            elMin = v;
        else if (key == "max_el")
            elMax = v;
    }
    // Nothing follows `done` before the session writes: rotctld answers
    // only what it is asked, and the link asked only \dump_state.
    m_handshake.clear();
    m_handshakeTimer.stop();
    m_opening = false;
    m_open = true;
    emit limitsReported(azMin, azMax, elMin, elMax);
    emit opened();
}

} // namespace slew::bridge
