// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A web server for tests, on 127.0.0.1 only: element-set sources are
// fetched from it, never from the internet.
//
// Besides plain pages it gives the answers a careless or hostile server
// gives: huge (made as they are sent, so the server itself stays small),
// chunked or delimited by the connection's close, cut short, dripping one
// byte at a time, or silent after the headers. Everything is driven by the
// socket's signals and timers: no sleeps, no waiting.

#include <QByteArray>
#include <QHash>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>
#include <QUrl>

#include <algorithm>

struct TinyHttpAnswer {
    enum class Length {
        Announced, // Content-Length (announcedLength, or the true length)
        Chunked,   // Transfer-Encoding: chunked
        UntilClose // neither: the answer ends when the connection closes
    };
    QByteArray body;
    qint64 generatedBytes = 0; // instead of body: this many bytes of `body` repeated, made as sent
    Length length = Length::Announced;
    qint64 announcedLength = -1;
    qint64 cutAfter = -1; // close the connection after this many bytes of the body
    int dripMs = 0;       // one byte of the body every dripMs
    bool silentAfterHeaders = false;
    QByteArray contentType = "text/plain";
};

// Sends one answer on one connection, as fast as the socket takes it (or
// as the drip timer allows), then closes.
class TinyHttpSender : public QObject {
public:
    TinyHttpSender(QTcpSocket *socket, const TinyHttpAnswer &answer, qint64 *bytesSent)
        : QObject(socket), m_socket(socket), m_answer(answer), m_bytesSent(bytesSent)
    {
        m_total = m_answer.generatedBytes > 0 ? m_answer.generatedBytes : m_answer.body.size();
        if (m_answer.cutAfter >= 0)
            m_end = std::min(m_total, m_answer.cutAfter);
        else
            m_end = m_total;
        QByteArray head = "HTTP/1.1 200 OK\r\nContent-Type: " + m_answer.contentType + "\r\nConnection: close\r\n";
        if (m_answer.length == TinyHttpAnswer::Length::Announced)
            head += "Content-Length: "
                    + QByteArray::number(m_answer.announcedLength >= 0 ? m_answer.announcedLength : m_total) + "\r\n";
        else if (m_answer.length == TinyHttpAnswer::Length::Chunked)
            head += "Transfer-Encoding: chunked\r\n";
        m_socket->write(head + "\r\n");
        if (m_answer.silentAfterHeaders)
            return;
        if (m_answer.dripMs > 0) {
            auto *drip = new QTimer(this);
            connect(drip, &QTimer::timeout, this, [this] { send(1); });
            drip->start(m_answer.dripMs);
            return;
        }
        connect(m_socket, &QTcpSocket::bytesWritten, this, [this] { pump(); });
        pump();
    }

private:
    // Keeps a little in the socket's buffer, never the whole answer.
    void pump()
    {
        while (m_position < m_end && m_socket->bytesToWrite() < 256 * 1024)
            send(64 * 1024);
    }

    void send(qint64 most)
    {
        if (m_position >= m_end || m_socket->state() != QAbstractSocket::ConnectedState) {
            close();
            return;
        }
        const qint64 n = std::min(most, m_end - m_position);
        QByteArray piece;
        piece.reserve(qsizetype(n));
        const QByteArray &pattern = m_answer.body;
        while (piece.size() < n) {
            const qint64 at = (m_position + piece.size()) % pattern.size();
            piece.append(pattern.mid(qsizetype(at), qsizetype(std::min<qint64>(pattern.size() - at, n - piece.size()))));
        }
        if (m_answer.length == TinyHttpAnswer::Length::Chunked)
            piece = QByteArray::number(piece.size(), 16) + "\r\n" + piece + "\r\n";
        m_socket->write(piece);
        m_position += n;
        *m_bytesSent += n;
        if (m_position >= m_end)
            close();
    }

    void close()
    {
        if (m_closed)
            return;
        m_closed = true;
        if (m_answer.length == TinyHttpAnswer::Length::Chunked && m_position >= m_total)
            m_socket->write("0\r\n\r\n");
        m_socket->disconnectFromHost();
    }

    QTcpSocket *m_socket;
    TinyHttpAnswer m_answer;
    qint64 *m_bytesSent;
    qint64 m_total = 0;
    qint64 m_end = 0;
    qint64 m_position = 0;
    bool m_closed = false;
};

// Answers GET /PATH from `answers`, then `pages` (a plain answer with a
// Content-Length); anything else is a 404. Counts requests and body bytes
// sent.
class TinyHttpServer : public QTcpServer {
public:
    QHash<QByteArray, QByteArray> pages;
    QHash<QByteArray, TinyHttpAnswer> answers;
    int requests = 0;
    qint64 bytesSent = 0;

    TinyHttpServer()
    {
        connect(this, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *socket = nextPendingConnection()) {
                connect(socket, &QTcpSocket::readyRead, socket, [this, socket] {
                    // The request so far, kept on the socket (it may come in pieces).
                    const QByteArray request = socket->property("request").toByteArray() + socket->readAll();
                    socket->setProperty("request", request);
                    if (!request.contains("\r\n\r\n") || socket->property("answered").toBool())
                        return;
                    socket->setProperty("answered", true);
                    ++requests;
                    const QByteArray path = request.split(' ').value(1);
                    if (answers.contains(path)) {
                        new TinyHttpSender(socket, answers.value(path), &bytesSent);
                        return;
                    }
                    const bool found = pages.contains(path);
                    const QByteArray body = found ? pages.value(path) : QByteArray("not here");
                    socket->write((found ? "HTTP/1.1 200 OK\r\n" : "HTTP/1.1 404 Not Found\r\n")
                                  + QByteArray("Content-Type: text/plain\r\nConnection: close\r\nContent-Length: ")
                                  + QByteArray::number(body.size()) + "\r\n\r\n" + body);
                    bytesSent += body.size();
                    socket->disconnectFromHost();
                });
                connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
            }
        });
    }
    QUrl url(const char *path) const
    {
        return QUrl(QStringLiteral("http://127.0.0.1:%1%2").arg(serverPort()).arg(QLatin1String(path)));
    }
};
