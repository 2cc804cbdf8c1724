// SPDX-License-Identifier: GPL-3.0-or-later
#include "rotctldclient.h"

#include "protocol/hamliberrors.h"

#include <QMetaObject>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <fcntl.h>
#include <pthread.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>
#include <system_error>
#include <utility>

namespace slew::bridge {

namespace {

constexpr qsizetype kReadChunk = 16 * 1024;

bool isQuit(QByteArrayView line)
{
    return line == "q" || line == "Q" || line == "\\quit";
}

qint64 monotonicMs()
{
    using namespace std::chrono;
    return duration_cast<milliseconds>(steady_clock::now().time_since_epoch()).count();
}

} // namespace

RotctldClient::RotctldClient(quint64 id, int descriptor, const QString &peer, Shared *shared, QObject *home, Hooks hooks)
    : m_id(id), m_peer(peer), m_shared(shared), m_home(home), m_hooks(std::move(hooks)), m_fd(descriptor)
{
    m_info.peer = peer;
    m_info.lastSeen = QDateTime::currentDateTimeUtc();
    // Blocking: the thread sleeps in read() until the client asks. A send
    // the kernel cannot take for kSendTimeoutMs gives up (a client that
    // does not read its answers), as does one to a peer that reset.
    const int flags = ::fcntl(m_fd, F_GETFL);
    if (flags >= 0)
        ::fcntl(m_fd, F_SETFL, flags & ~O_NONBLOCK);
    const int timeoutMs = std::max(1, m_shared->sendTimeoutMs.load());
    timeval timeout{};
    timeout.tv_sec = timeoutMs / 1000;
    timeout.tv_usec = (timeoutMs % 1000) * 1000;
    ::setsockopt(m_fd, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
}

RotctldClient::~RotctldClient()
{
    stop();
    wait();
    closeSocket(false);
}

bool RotctldClient::start()
{
    try {
        m_thread = std::thread([this] { run(); });
    } catch (const std::system_error &) {
        closeSocket(false); // out of threads: the client is refused by closing
        return false;
    }
    return true;
}

void RotctldClient::wait()
{
    if (m_thread.joinable())
        m_thread.join();
}

RotctldClient::Info RotctldClient::info() const
{
    const std::lock_guard lock(m_mutex);
    return m_info;
}

void RotctldClient::deliver(const QByteArray &answer)
{
    {
        const std::lock_guard lock(m_mutex);
        m_answer = answer;
    }
    m_answered.notify_one();
}

void RotctldClient::stop()
{
    {
        const std::lock_guard lock(m_mutex);
        m_stopping = true;
        // Wakes a read() or send() in progress. Under the lock: the thread
        // closes the descriptor under it too, so this never reaches a number
        // the kernel has since given to somebody else.
        if (m_fd >= 0)
            ::shutdown(m_fd, SHUT_RDWR);
    }
    m_answered.notify_one();
}

void RotctldClient::closeSocket(bool graceful)
{
    const std::lock_guard lock(m_mutex);
    if (m_fd < 0)
        return;
    // Our end of the stream first: the peer reads every answer, then its end.
    if (graceful)
        ::shutdown(m_fd, SHUT_WR);
    ::close(m_fd);
    m_fd = -1;
}

void RotctldClient::run()
{
    // Named for ps and gdb: "rotctld client".
    ::pthread_setname_np(::pthread_self(), "rotctld client");
    char bytes[kReadChunk];
    bool graceful = false;
    for (;;) {
        {
            const std::lock_guard lock(m_mutex);
            if (m_stopping)
                break;
        }
        const ssize_t n = ::read(m_fd, bytes, sizeof bytes);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            break; // reset: nobody to answer
        {
            const std::lock_guard lock(m_mutex);
            if (m_stopping)
                break; // the server shut the socket to end this
        }
        if (n == 0) {
            // The client sent its last byte (a one-shot `printf 'p\n' | nc -N`):
            // its unterminated last line is answered too, as Hamlib's rotctld does.
            const QByteArray last = std::exchange(m_buffer, {}).trimmed();
            if (!m_discarding && !last.isEmpty() && !isQuit(last))
                graceful = sendAll(answer(last));
            else
                graceful = true;
            break;
        }
        bool quit = false;
        // Every answer to this read leaves in one write: Gpredict reads a
        // `p` answer with a single recv.
        const QByteArray out = consume(bytes, n, &quit);
        if (!sendAll(out))
            break;
        if (quit) {
            graceful = true;
            break;
        }
    }
    closeSocket(graceful);
    QMetaObject::invokeMethod(
        m_home, [hook = m_hooks.finished, id = m_id] { hook(id); }, Qt::QueuedConnection);
}

QByteArray RotctldClient::consume(const char *data, qsizetype size, bool *quit)
{
    QByteArray out;
    QByteArrayView bytes(data, size);
    *quit = false;
    while (!bytes.isEmpty()) {
        // Up to the next line end, or all there is.
        const qsizetype end = std::find_if(bytes.begin(), bytes.end(), [](char ch) { return ch == '\n' || ch == '\r'; })
                              - bytes.begin();
        const bool ended = end < bytes.size();
        const QByteArrayView part = bytes.first(end);
        bytes = bytes.sliced(ended ? end + 1 : end);
        if (!m_discarding && m_buffer.size() + part.size() > kMaxLine) {
            // Refused once, then everything up to the line end is dropped.
            m_buffer.clear();
            m_discarding = true;
            out += "RPRT -1\n";
            log(tr("rotctld client %1 sent a line over %2 bytes; refused").arg(m_peer).arg(kMaxLine));
        }
        if (m_discarding) {
            m_discarding = !ended;
            continue;
        }
        if (!ended) {
            m_buffer += part;
            continue;
        }
        if (m_buffer.isEmpty() && part.isEmpty())
            continue; // the \n of \r\n, or an empty line
        // A line read whole is answered from where it was read.
        QByteArray joined;
        QByteArrayView line = part;
        if (!m_buffer.isEmpty()) {
            joined = std::exchange(m_buffer, {}).append(part);
            line = joined;
        }
        line = line.trimmed();
        if (isQuit(line)) {
            *quit = true;
            return out;
        }
        out += answer(line);
        const std::lock_guard lock(m_mutex);
        if (m_stopping)
            return out;
    }
    return out;
}

QByteArray RotctldClient::answer(QByteArrayView line)
{
    // Trackers send the same line over and over (`p`): it is read once.
    const bool repeated = m_lastRequest && line == QByteArrayView(m_lastLine);
    if (!repeated) {
        m_lastLine = line.toByteArray();
        m_lastRequest = parseRotctldLine(line);
    }
    const RotctldRequest &r = *m_lastRequest;
    {
        const std::lock_guard lock(m_mutex);
        if (!repeated)
            m_info.lastCommand = QString::fromLatin1(line.first(std::min<qsizetype>(line.size(), 80))).trimmed();
        // UTC: the local time would look up the time zone (a file) for every
        // answer; the Trackers tab shows it in local time.
        m_info.lastSeen = QDateTime::currentDateTimeUtc();
        ++m_info.commands;
    }
    if (r.kind != RotctldRequest::Kind::GetPosition)
        return askHome(r).value_or(QByteArray());
    noteActivity();
    const SharedPosition::Reading reading = m_shared->position.get();
    if (!reading.known)
        return formatStatus(r, int(HamlibError::Io));
    return m_positionAnswer.answer(r, reading.azimuth, reading.elevation);
}

std::optional<QByteArray> RotctldClient::askHome(const RotctldRequest &request)
{
    {
        const std::lock_guard lock(m_mutex);
        m_answer.reset();
    }
    QMetaObject::invokeMethod(
        m_home, [hook = m_hooks.answer, id = m_id, request] { hook(id, request); }, Qt::QueuedConnection);
    std::unique_lock lock(m_mutex);
    m_answered.wait(lock, [this] { return m_answer.has_value() || m_stopping; });
    if (m_stopping)
        return std::nullopt;
    return std::exchange(m_answer, std::nullopt);
}

bool RotctldClient::sendAll(const QByteArray &bytes)
{
    qsizetype sent = 0;
    while (sent < bytes.size()) {
        const ssize_t n = ::send(m_fd, bytes.constData() + sent, size_t(bytes.size() - sent), MSG_NOSIGNAL);
        if (n > 0) {
            sent += n;
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
            bool stopping = false;
            {
                const std::lock_guard lock(m_mutex);
                stopping = m_stopping;
            }
            if (!stopping)
                log(tr("rotctld client %1 is not reading its answers; disconnected").arg(m_peer));
        }
        return false;
    }
    return true;
}

void RotctldClient::log(const QString &text)
{
    QMetaObject::invokeMethod(
        m_home, [hook = m_hooks.log, id = m_id, text] { hook(id, text); }, Qt::QueuedConnection);
}

void RotctldClient::noteActivity()
{
    if (!m_shared->activityWatched.load(std::memory_order_relaxed))
        return;
    const qint64 now = monotonicMs();
    if (now - m_lastActivityMs < kActivityIntervalMs)
        return;
    m_lastActivityMs = now;
    QMetaObject::invokeMethod(
        m_home, [hook = m_hooks.activity, id = m_id] { hook(id); }, Qt::QueuedConnection);
}

} // namespace slew::bridge
