// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The far end of an in-process link, as the session reads it: a sequential
// QIODevice whose reads come from what deliver() queued, announced by
// readyRead from the event loop, never inside the write that caused them,
// as a serial port's or a socket's would be. Subclasses decide what a write
// means (writeData).

#include <QByteArray>
#include <QIODevice>
#include <QTimer>

#include <algorithm>

class QueuedReadDevice : public QIODevice {
public:
    bool isSequential() const override { return true; }
    qint64 bytesAvailable() const override { return m_pending.size() + QIODevice::bytesAvailable(); }

    void deliver(const QByteArray &bytes)
    {
        m_pending += bytes;
        QTimer::singleShot(0, this, [this] {
            if (isOpen() && !m_pending.isEmpty())
                emit readyRead();
        });
    }

protected:
    qint64 readData(char *data, qint64 maxSize) override
    {
        const qint64 n = std::min<qint64>(maxSize, m_pending.size());
        std::copy_n(m_pending.constData(), n, data);
        m_pending.remove(0, n);
        return n;
    }

private:
    QByteArray m_pending;
};
