#include "rotctldlink.h"

#include "protocol/encoder.h"
#include "rotctldrequest.h"
#include "transport/linkfactory.h"

#include <cmath>

namespace slew::bridge {

using protocol::Message;
using protocol::Op;

namespace {

constexpr qsizetype kMaxAnswerLine = 1024;

QByteArray number(double v)
{
    return protocol::formatNumber(v, 2);
}

} // namespace

RotctldLink::RotctldLink(const QString &uri, QString host, quint16 port, QObject *parent)
    : Link(uri, parent), m_host(std::move(host)), m_port(port)
{
    m_clock.start();
    m_pipe.hostEnd()->open(QIODevice::ReadWrite);
    m_pipe.deviceEnd()->open(QIODevice::ReadWrite);
    connect(m_pipe.deviceEnd(), &QIODevice::readyRead, this, &RotctldLink::onHostBytes);
    connect(&m_socket, &QTcpSocket::connected, this, &RotctldLink::onConnected);
    connect(&m_socket, &QTcpSocket::errorOccurred, this, &RotctldLink::onSocketError);
    connect(&m_socket, &QTcpSocket::readyRead, this, &RotctldLink::onSocketReadyRead);
    m_timeoutTimer.setInterval(500);
    connect(&m_timeoutTimer, &QTimer::timeout, this, &RotctldLink::checkTimeouts);
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

void RotctldLink::open()
{
    m_open = false;
    m_opening = true;
    m_pending.clear();
    m_answerLines.clear();
    m_socketBuffer.clear();
    m_sentAz = m_sentEl = m_seenAz = m_seenEl = qQNaN();
    m_socket.abort();
    m_socket.connectToHost(m_host, m_port);
}

void RotctldLink::close()
{
    m_opening = false;
    m_open = false;
    m_timeoutTimer.stop();
    m_pending.clear();
    if (m_socket.state() == QAbstractSocket::ConnectedState)
        m_socket.write("q\n");
    m_socket.disconnectFromHost();
}

void RotctldLink::onConnected()
{
    m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    m_timeoutTimer.start();
    // netrotctl opens the same way: the limits first.
    send("\\dump_state", Expect::DumpState);
}

void RotctldLink::fail(const QString &reason)
{
    const bool wasOpen = m_open;
    const bool wasOpening = m_opening;
    m_open = m_opening = false;
    m_timeoutTimer.stop();
    m_pending.clear();
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

void RotctldLink::send(const QByteArray &command, Expect expect)
{
    if (int(m_pending.size()) >= kMaxPending) {
        emit notice(tr("%1: rotctld is not keeping up; '%2' not sent").arg(uri(), QString::fromLatin1(command)));
        return;
    }
    m_pending.push_back({command, expect, m_clock.elapsed()});
    m_socket.write(command + '\n');
}

void RotctldLink::checkTimeouts()
{
    if (!m_pending.empty() && m_clock.elapsed() - m_pending.front().sentAtMs > kAnswerTimeoutMs) {
        // rotctld answers every command in order; a missing answer means
        // the stream can no longer be matched up.
        fail(tr("%1: rotctld did not answer '%2'").arg(uri(), QString::fromLatin1(m_pending.front().command)));
    }
}

// --- From the session: Easycomm lines to rotctld commands -------------------

void RotctldLink::onHostBytes()
{
    const QByteArray bytes = m_pipe.deviceEnd()->readAll();
    m_parser.feed(bytes, [this](const Message &m) {
        m_line.append(m);
        if (m.lineEnd) {
            translate();
            m_line.clear();
        }
    });
    if (m_line.size() > 16)
        m_line.clear(); // a line without end is not a command we send on
}

void RotctldLink::translate()
{
    if (!m_open)
        return;
    const Message *az = nullptr;
    const Message *el = nullptr;
    bool stop = false;
    bool drove = false; // park, home or a speed
    for (const Message &m : std::as_const(m_line)) {
        switch (m.op) {
        case Op::Azimuth:
            az = &m;
            break;
        case Op::Elevation:
            el = &m;
            break;
        case Op::StopAzimuth:
        case Op::StopElevation:
            stop = true;
            break;
        case Op::Park:
            drove = true;
            send("K", Expect::Status);
            break;
        case Op::Reset:
            drove = true;
            send("R 1", Expect::Status);
            break;
        case Op::MoveLeft: drove = true; send("M 8 50", Expect::Status); break;
        case Op::MoveRight: drove = true; send("M 16 50", Expect::Status); break;
        case Op::MoveUp: drove = true; send("M 2 50", Expect::Status); break;
        case Op::MoveDown: drove = true; send("M 4 50", Expect::Status); break;
        case Op::VelocityLeft:
        case Op::VelocityRight:
        case Op::VelocityUp:
        case Op::VelocityDown: {
            if (!m.hasValue)
                break;
            if (m.value <= 0) {
                stop = true; // hold: the nearest rotctld has is stop
                break;
            }
            // The inverse of Hamlib's Easycomm III mapping, (speed-1)*100 mdeg/s.
            const int speed = std::clamp(int(std::lround(m.value / 100.0)) + 1, 1, 100);
            const int direction = m.op == Op::VelocityLeft ? 8 : m.op == Op::VelocityRight ? 16
                                : m.op == Op::VelocityUp   ? 2
                                                           : 4;
            drove = true;
            send("M " + QByteArray::number(direction) + ' ' + QByteArray::number(speed), Expect::Status);
            break;
        }
        case Op::Version:
            if (m.isQuery())
                send("_", Expect::Info);
            break;
        default:
            break; // GS, GE, IP, CR, CW, \?ENC: rotctld has nothing like them
        }
    }
    if (stop || drove) {
        // Stopped, parked, homing or driven at a speed: no axis is going
        // where it was last sent any more.
        m_sentAz = m_sentEl = qQNaN();
    }
    if (stop)
        send("S", Expect::Status);
    if ((az && az->isQuery()) || (el && el->isQuery())) {
        send("p", Expect::Position);
    } else if (az || el) {
        // rotctld sets both axes at once. The axis not named keeps going
        // where it was last sent, or stays where it was last seen; never a
        // made-up 0, which would drive it to its stop.
        const double a = az ? az->value : (std::isnan(m_sentAz) ? m_seenAz : m_sentAz);
        const double e = el ? el->value : (std::isnan(m_sentEl) ? m_seenEl : m_sentEl);
        if (std::isnan(a) || std::isnan(e)) {
            emit notice(tr("%1: rotctld moves both axes at once, and the other axis' position is not known yet: "
                           "not sent")
                            .arg(uri()));
        } else {
            m_sentAz = a;
            m_sentEl = e;
            send("P " + number(a) + ' ' + number(e), Expect::Status);
        }
    }
}

// --- From rotctld: answers back to Easycomm ---------------------------------

void RotctldLink::onSocketReadyRead()
{
    m_socketBuffer += m_socket.readAll();
    qsizetype end;
    while ((end = m_socketBuffer.indexOf('\n')) >= 0) {
        const QByteArray line = m_socketBuffer.left(end).trimmed();
        m_socketBuffer.remove(0, end + 1);
        handleLine(line);
        if (m_socket.state() != QAbstractSocket::ConnectedState)
            return;
    }
    if (m_socketBuffer.size() > kMaxAnswerLine)
        fail(tr("%1: rotctld sent a line over %2 bytes").arg(uri()).arg(kMaxAnswerLine));
}

void RotctldLink::handleLine(const QByteArray &line)
{
    if (m_pending.empty()) {
        emit notice(tr("%1: unexpected answer from rotctld: %2").arg(uri(), QString::fromLatin1(line.left(60))));
        return;
    }
    Pending &front = m_pending.front();
    const bool isReport = line.startsWith("RPRT ");
    if (isReport) {
        const int code = line.mid(5).toInt();
        const Pending done = front;
        m_pending.pop_front();
        m_answerLines.clear();
        if (done.expect == Expect::DumpState) {
            fail(tr("%1: rotctld refused \\dump_state: %2").arg(uri(), describeHamlibError(code)));
            return;
        }
        if (code != 0) {
            emit notice(tr("%1: rotctld refused '%2': %3 (RPRT %4)")
                            .arg(uri(), QString::fromLatin1(done.command), describeHamlibError(code))
                            .arg(code));
        }
        return;
    }
    m_answerLines.append(line);
    switch (front.expect) {
    case Expect::Position:
        if (m_answerLines.size() == 2) {
            bool okAz = false, okEl = false;
            const double az = m_answerLines[0].toDouble(&okAz);
            const double el = m_answerLines[1].toDouble(&okEl);
            m_pending.pop_front();
            m_answerLines.clear();
            if (okAz && okEl) {
                m_seenAz = az;
                m_seenEl = el;
                reply("AZ" + number(az) + " EL" + number(el) + '\n');
            }
            else
                emit notice(tr("%1: rotctld sent a position that is not a number").arg(uri()));
        }
        break;
    case Expect::Info: {
        QByteArray info = line.simplified();
        info.replace(' ', '_'); // an Easycomm token holds no spaces
        m_pending.pop_front();
        m_answerLines.clear();
        reply("VE" + info.left(100) + '\n');
        break;
    }
    case Expect::DumpState:
        if (line == "done")
            finishDumpState();
        else if (m_answerLines.size() > 64)
            fail(tr("%1: \\dump_state did not end").arg(uri()));
        break;
    case Expect::Status:
        m_pending.pop_front();
        m_answerLines.clear();
        emit notice(tr("%1: unexpected answer from rotctld: %2").arg(uri(), QString::fromLatin1(line.left(60))));
        break;
    }
}

void RotctldLink::finishDumpState()
{
    double azMin = 0, azMax = 360, elMin = 0, elMax = 90;
    for (const QByteArray &l : std::as_const(m_answerLines)) {
        const qsizetype eq = l.indexOf('=');
        if (eq < 0)
            continue;
        const QByteArray key = l.left(eq);
        const double v = l.mid(eq + 1).toDouble();
        if (key == "min_az")
            azMin = v;
        else if (key == "max_az")
            azMax = v;
        else if (key == "min_el")
            elMin = v;
        else if (key == "max_el")
            elMax = v;
    }
    m_pending.pop_front();
    m_answerLines.clear();
    emit limitsReported(azMin, azMax, elMin, elMax);
    m_opening = false;
    m_open = true;
    emit opened();
}

void RotctldLink::reply(const QByteArray &easycomm)
{
    m_pipe.deviceEnd()->write(easycomm);
}

} // namespace slew::bridge
