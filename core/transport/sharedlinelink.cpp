#include "sharedlinelink.h"

#include "sharedline.h"

#include <QTimer>

#include <cstring>

namespace slew::transport {

bool SharedLineDevice::deliver(const QByteArray &bytes)
{
    if (!isOpen())
        return false;
    if (bytes.isEmpty())
        return true;
    if (m_received.size() + bytes.size() > kMaxUnread)
        return false;
    m_received.append(bytes);
    emit readyRead();
    return true;
}

qint64 SharedLineDevice::bytesToWrite() const
{
    const SharedLine *line = m_link->sharedLine();
    return line && line->line() && line->isOpen() ? line->line()->device()->bytesToWrite() : 0;
}

qint64 SharedLineDevice::readData(char *data, qint64 maxSize)
{
    const qint64 n = std::min<qint64>(maxSize, m_received.size());
    std::memcpy(data, m_received.constData(), size_t(n));
    m_received.remove(0, n);
    return n;
}

qint64 SharedLineDevice::writeData(const char *data, qint64 size)
{
    if (!m_link->isOpen())
        return -1;
    m_link->send(QByteArray(data, size));
    return size;
}

SharedLineLink::SharedLineLink(const QString &uri, int rotor, SharedLine *line, QObject *parent)
    : Link(uri, parent), m_rotor(rotor), m_line(line), m_device(this)
{
    if (Link *real = line->line()) {
        // A stepped simulator clock paces the session's timers through this
        // link as it would through the real one.
        connect(real, &Link::clockStepped, this, &Link::clockStepped);
        connect(real, &Link::notice, this, &Link::notice);
        connect(real, &Link::limitsReported, this, &Link::limitsReported);
        connect(real->device(), &QIODevice::bytesWritten, &m_device, [this](qint64 n) {
            if (m_open)
                emit m_device.bytesWritten(n);
        });
    }
}

SharedLineLink::~SharedLineLink()
{
    if (m_line)
        m_line->forget(this);
}

void SharedLineLink::open()
{
    if (m_open)
        return;
    if (!m_line || !m_line->isValid()) {
        const QString reason = m_line ? m_line->error() : tr("%1: the shared line is gone").arg(uri());
        // Opening is asynchronous for every link: failed() never comes
        // from inside open().
        QTimer::singleShot(0, this, [this, reason] { emit failed(reason); });
        return;
    }
    m_line->openFor(this);
}

void SharedLineLink::close()
{
    m_open = false;
    m_nextWriteIsQuery = false;
    m_device.close();
    if (m_line)
        m_line->closeFor(this);
}

LinkHints SharedLineLink::hints() const
{
    LinkHints h = m_line && m_line->line() ? m_line->line()->hints() : LinkHints{};
    h.rotor = m_rotor;
    return h;
}

std::optional<double> SharedLineLink::clockSeconds() const
{
    return m_line && m_line->line() ? m_line->line()->clockSeconds() : std::nullopt;
}

bool SharedLineLink::clockIsStepped() const
{
    return m_line && m_line->line() && m_line->line()->clockIsStepped();
}

bool SharedLineLink::setTimeScale(double scale)
{
    // The line's clock is every rotor's on it: a simulated multi-rotor
    // controller speeds up as one.
    return m_line && m_line->line() && m_line->line()->setTimeScale(scale);
}

double SharedLineLink::timeScale() const
{
    return m_line && m_line->line() ? m_line->line()->timeScale() : 1.0;
}

void SharedLineLink::setAwaitingReply(bool awaiting)
{
    // The session says so just before it writes the query; anything it
    // writes after that (a stop) is a command and must not wait.
    m_nextWriteIsQuery = awaiting;
    if (!awaiting && m_line)
        m_line->queryDone(this);
}

void SharedLineLink::send(const QByteArray &bytes)
{
    if (!m_line)
        return;
    if (m_nextWriteIsQuery) {
        m_nextWriteIsQuery = false;
        m_line->sendQuery(this, bytes);
    } else {
        m_line->sendCommand(this, bytes);
    }
}

void SharedLineLink::lineOpened()
{
    m_open = true;
    m_device.open(QIODevice::ReadWrite | QIODevice::Unbuffered);
    emit opened();
}

void SharedLineLink::lineDown(const QString &reason, bool opening)
{
    m_open = false;
    m_nextWriteIsQuery = false;
    m_device.close();
    if (opening)
        emit failed(reason);
    else
        emit lost(reason);
}

void SharedLineLink::lineGone()
{
    const bool wasOpen = m_open;
    m_line = nullptr;
    m_open = false;
    m_device.close();
    // From the event loop: the line goes while its owner is being torn down
    // (a window closing), and whoever listens to this link's session may be
    // half destroyed by then. If the link itself goes first, nothing is said.
    if (wasOpen)
        QTimer::singleShot(0, this, [this] { emit lost(tr("%1: the shared line was closed").arg(uri())); });
}

} // namespace slew::transport
