// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Two pseudo-terminals joined by socat, like a null-modem cable between two
// serial ports: what is written to one end is read at the other. For the
// tests that put a real serial driver (Hamlib's, Slew's) on one end.

#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QString>
#include <QTemporaryDir>
#include <QTest>

class PtyPair {
public:
    PtyPair() : m_near(m_dir.filePath("near")), m_far(m_dir.filePath("far")) {}
    ~PtyPair()
    {
        if (m_socat.state() == QProcess::NotRunning)
            return;
        m_socat.terminate();
        if (!m_socat.waitForFinished(5000)) {
            m_socat.kill();
            m_socat.waitForFinished(5000);
        }
    }
    PtyPair(const PtyPair &) = delete;
    PtyPair &operator=(const PtyPair &) = delete;

    // Starts socat; true once both ends exist, else *why says why not.
    bool start(QString *why)
    {
        const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
        if (socat.isEmpty()) {
            *why = QStringLiteral("socat is not installed: packaging/dev.sh installs it");
            return false;
        }
        m_socat.start(socat, {QStringLiteral("pty,raw,echo=0,link=") + m_near,
                              QStringLiteral("pty,raw,echo=0,link=") + m_far});
        if (QTest::qWaitFor([&] { return QFile::exists(m_near) && QFile::exists(m_far); }, 10000))
            return true;
        *why = QStringLiteral("socat made no pseudo-terminals: %1").arg(QString::fromLocal8Bit(m_socat.readAllStandardError()));
        return false;
    }

    // The device names: the driver under test opens the near end, the test the far one.
    QString nearEnd() const { return m_near; }
    QString farEnd() const { return m_far; }

private:
    QTemporaryDir m_dir;
    QString m_near;
    QString m_far;
    QProcess m_socat;
};
