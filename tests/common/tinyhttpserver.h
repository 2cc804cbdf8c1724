// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A web server for tests, on 127.0.0.1 only: element-set sources are
// fetched from it, never from the internet.

#include <QByteArray>
#include <QHash>
#include <QTcpServer>
#include <QTcpSocket>
#include <QUrl>

// Answers GET /PATH from a table; anything else is a 404. Counts requests.
class TinyHttpServer : public QTcpServer {
public:
    QHash<QByteArray, QByteArray> pages;
    int requests = 0;

    TinyHttpServer()
    {
        connect(this, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *socket = nextPendingConnection()) {
                connect(socket, &QTcpSocket::readyRead, socket, [this, socket] {
                    const QByteArray request = socket->readAll();
                    if (!request.contains("\r\n\r\n"))
                        return;
                    ++requests;
                    const QByteArray path = request.split(' ').value(1);
                    const bool found = pages.contains(path);
                    const QByteArray body = found ? pages.value(path) : QByteArray("not here");
                    socket->write((found ? "HTTP/1.1 200 OK\r\n" : "HTTP/1.1 404 Not Found\r\n")
                                  + QByteArray("Content-Type: text/plain\r\nConnection: close\r\nContent-Length: ")
                                  + QByteArray::number(body.size()) + "\r\n\r\n" + body);
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

