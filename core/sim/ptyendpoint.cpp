#include "ptyendpoint.h"

#include "ptymasterdevice.h"

#include <QFile>
#include <QFileInfo>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace slew::sim {

PtyEndpoint::PtyEndpoint(Simulator &simulator, const ConnectionSettings &settings, QObject *parent)
    : QObject(parent), m_simulator(simulator), m_settings(settings)
{
}

PtyEndpoint::~PtyEndpoint()
{
    close();
}

bool PtyEndpoint::fail(const QString &what)
{
    m_error = QStringLiteral("pseudo-terminal %1: %2: %3").arg(m_linkPath, what, QString::fromLocal8Bit(std::strerror(errno)));
    close();
    return false;
}

bool PtyEndpoint::open(const QString &linkPath)
{
    close();
    m_linkPath = linkPath;
    const QByteArray link = QFile::encodeName(linkPath);
    const QFileInfo existing(linkPath);
    if (existing.exists() && !existing.isSymLink()) {
        errno = EEXIST;
        return fail(QStringLiteral("a file that is not a symlink is in the way"));
    }

    const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0)
        return fail(QStringLiteral("posix_openpt"));
    if (::grantpt(master) != 0 || ::unlockpt(master) != 0) {
        ::close(master);
        return fail(QStringLiteral("grantpt/unlockpt"));
    }
    char name[PATH_MAX];
    if (::ptsname_r(master, name, sizeof name) != 0) {
        ::close(master);
        return fail(QStringLiteral("ptsname"));
    }
    ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);
    ::fcntl(master, F_SETFD, FD_CLOEXEC);
    m_device = new PtyMasterDevice(master, this);
    m_terminalPath = QString::fromLocal8Bit(name);

    m_slaveFd = ::open(name, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (m_slaveFd < 0)
        return fail(QStringLiteral("opening %1").arg(m_terminalPath));
    // Raw: no echo, no line editing, no CR/LF translation; the peer sets its
    // own speed, which a pseudo-terminal ignores (--baud paces instead).
    termios tio{};
    if (::tcgetattr(m_slaveFd, &tio) == 0) {
        ::cfmakeraw(&tio);
        tio.c_cc[VMIN] = 1;
        tio.c_cc[VTIME] = 0;
        ::tcsetattr(m_slaveFd, TCSANOW, &tio);
    }

    ::unlink(link.constData());
    if (::symlink(name, link.constData()) != 0)
        return fail(QStringLiteral("symlink to %1").arg(m_terminalPath));

    m_connection = new SimulatorConnection(m_simulator, m_device, m_settings, this);
    connect(m_connection, &SimulatorConnection::dropRequested, this, &PtyEndpoint::replug, Qt::QueuedConnection);
    return true;
}

void PtyEndpoint::replug()
{
    // A dropped serial line is an adapter unplugged and plugged back: the
    // peer's open terminal goes dead, and a fresh one appears at the same path.
    const QString path = m_linkPath;
    open(path);
}

void PtyEndpoint::close()
{
    delete m_connection;
    m_connection = nullptr;
    delete m_device;
    m_device = nullptr;
    if (m_slaveFd >= 0) {
        ::close(m_slaveFd);
        m_slaveFd = -1;
    }
    if (!m_linkPath.isEmpty()) {
        const QFileInfo info(m_linkPath);
        if (info.isSymLink() && info.symLinkTarget() == m_terminalPath)
            ::unlink(QFile::encodeName(m_linkPath).constData());
    }
    m_terminalPath.clear();
}

} // namespace slew::sim
