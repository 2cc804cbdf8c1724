#pragma once
// A scripted rotator controller on a real local socket (QTcpServer on
// 127.0.0.1, port 0), for the session's unit tests. By default it answers like
// a small SatNOGS-style controller; a test can replace the answer for any
// line, stay silent, echo what it hears, or drop the connection.

#include <QByteArray>
#include <QHostAddress>
#include <QList>
#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>

#include <functional>

class FakeDevice : public QObject {
    Q_OBJECT
public:
    double az = 10.0;
    double el = 20.0;
    bool echo = false;          // send every received line back first
    bool oneLinePosition = true; // `AZx ELy` on one line (Hamlib 4.5) or two lines
    int ignoreNext = 0;         // stay silent for this many lines
    bool silent = false;        // never answer
    QList<QByteArray> received; // every line, without terminator
    // Return a non-empty answer to override the default for a line.
    std::function<QByteArray(const QByteArray &line)> script;

    FakeDevice()
    {
        m_server.listen(QHostAddress::LocalHost, 0);
        connect(&m_server, &QTcpServer::newConnection, this, [this] {
            while (QTcpSocket *s = m_server.nextPendingConnection()) {
                if (m_socket)
                    m_socket->deleteLater();
                m_socket = s;
                connect(s, &QTcpSocket::readyRead, this, [this, s] { onRead(s); });
                emit clientConnected();
            }
        });
    }

    QString uri() const { return QStringLiteral("tcp://127.0.0.1:%1").arg(m_server.serverPort()); }
    quint16 port() const { return m_server.serverPort(); }
    bool hasClient() const { return m_socket && m_socket->state() == QAbstractSocket::ConnectedState; }

    void push(const QByteArray &bytes)
    {
        if (m_socket)
            m_socket->write(bytes);
    }
    void dropClient()
    {
        if (m_socket)
            m_socket->abort();
    }
    void stopListening() { m_server.close(); }
    void listenAgain(quint16 port) { m_server.listen(QHostAddress::LocalHost, port); }
    int count(const QByteArray &line) const { return int(received.count(line)); }

signals:
    void clientConnected();
    void lineReceived(const QByteArray &line);

private:
    void onRead(QTcpSocket *s)
    {
        m_buffer += s->readAll();
        qsizetype end;
        while ((end = m_buffer.indexOf('\n')) >= 0) {
            const QByteArray line = m_buffer.left(end).trimmed();
            m_buffer.remove(0, end + 1);
            received << line;
            emit lineReceived(line);
            if (echo)
                s->write(line + "\n");
            if (silent)
                continue;
            if (ignoreNext > 0) {
                --ignoreNext;
                continue;
            }
            QByteArray answer = script ? script(line) : QByteArray();
            if (answer.isEmpty())
                answer = defaultAnswer(line);
            s->write(answer);
        }
    }

    QByteArray defaultAnswer(const QByteArray &line)
    {
        const QByteArray a = QByteArray::number(az, 'f', 1);
        const QByteArray e = QByteArray::number(el, 'f', 1);
        if (line == "AZ EL")
            return oneLinePosition ? "AZ" + a + " EL" + e + "\n" : "AZ" + a + "\nEL" + e + "\n";
        if (line == "AZ")
            return "AZ" + a + "\n";
        if (line == "EL")
            return "EL" + e + "\n";
        if (line == "VE")
            return "VEFake-1.0\n";
        if (line == "GS")
            return "GS1\n";
        if (line == "GE")
            return "GE1\n";
        if (line.startsWith("IP"))
            return line + ",1.5\n";
        if (line.startsWith("CR "))
            return line.mid(3) + ",0.80\n";
        if (line.startsWith("CR"))
            return line + ",0.80\n";
        if (line.startsWith("AZ") && line.contains(" EL")) {
            const QList<QByteArray> parts = line.split(' ');
            az = parts[0].mid(2).toDouble();
            el = parts[1].mid(2).toDouble();
        }
        return {};
    }

    QTcpServer m_server;
    QPointer<QTcpSocket> m_socket;
    QByteArray m_buffer;
};
