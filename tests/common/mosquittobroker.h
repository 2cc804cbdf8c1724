// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A real Mosquitto broker of the test's own, on a free loopback port, with
// everything a station's broker has: TLS with a certificate authority and
// a server certificate made here by openssl (for "localhost" and
// 127.0.0.1), a password file made by mosquitto_passwd, and an access list:
//
//   station-NAME  reads and writes slew/NAME/#, for each station name given
//   operator      reads slew/#, writes slew/+/command
//   watcher       reads slew/#, writes nothing
//
// and mosquitto_pub / mosquitto_sub as independent peers. Nothing here
// uses a broker the machine runs: each test starts its own in a temporary
// directory and stops it at the end. Waits only on signals and conditions.

#include <QFile>
#include <QHostAddress>
#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

class MosquittoBroker {
public:
    static QString program(const char *name)
    {
        // mosquitto itself lives in /usr/sbin, which a test's PATH may lack.
        QString found = QStandardPaths::findExecutable(QString::fromLatin1(name));
        if (found.isEmpty())
            found = QStandardPaths::findExecutable(QString::fromLatin1(name), {QStringLiteral("/usr/sbin"), QStringLiteral("/usr/bin")});
        return found;
    }

    // Runs a program to its end; its standard output, or nothing (and why
    // in *error) when it failed.
    static std::optional<QByteArray> run(const QString &program, const QStringList &arguments, QString *error,
                                         int timeoutMs = 30000)
    {
        QProcess p;
        QSignalSpy finished(&p, &QProcess::finished);
        p.start(program, arguments);
        if (!finished.wait(timeoutMs) && p.state() != QProcess::NotRunning) {
            p.kill();
            finished.wait(5000);
            *error = QStringLiteral("%1 did not finish").arg(program);
            return std::nullopt;
        }
        if (p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
            *error = QStringLiteral("%1 %2 failed: %3")
                         .arg(program, arguments.join(u' '), QString::fromLocal8Bit(p.readAllStandardError()));
            return std::nullopt;
        }
        return p.readAllStandardOutput();
    }

    static quint16 freePort()
    {
        QTcpServer s;
        s.listen(QHostAddress::LocalHost, 0);
        return s.serverPort();
    }

    explicit MosquittoBroker(const QStringList &stationNames = {QStringLiteral("mast")}) : m_stations(stationNames) {}
    ~MosquittoBroker() { stop(); }

    // Makes the certificates, the accounts and the configuration, starts
    // the broker, and returns once it takes connections. Started again
    // (after stop()), it keeps its certificates and accounts; `port` and
    // `plainPort` then bring it back where it was.
    bool start(QString *error, quint16 port = 0, quint16 plainPort = 0)
    {
        if (!m_dir.isValid()) {
            *error = QStringLiteral("no temporary directory");
            return false;
        }
        for (const char *needed : {"mosquitto", "mosquitto_passwd", "mosquitto_pub", "mosquitto_sub", "openssl"}) {
            if (program(needed).isEmpty()) {
                *error = QStringLiteral("%1 is not installed (packaging/debian-packages.txt: mosquitto, "
                                        "mosquitto-clients, openssl)")
                             .arg(QLatin1String(needed));
                return false;
            }
        }
        if (!QFile::exists(caFile()) && (!makeCertificates(error) || !makeAccounts(error)))
            return false;
        m_port = port ? port : freePort();
        m_plainPort = plainPort ? plainPort : freePort();
        writeFile(QStringLiteral("mosquitto.conf"),
                  QStringLiteral("per_listener_settings false\n"
                                 "allow_anonymous false\n"
                                 "password_file %1\n"
                                 "acl_file %2\n"
                                 "persistence false\n"
                                 "user root\n"
                                 "log_dest stdout\n"
                                 "log_type error\nlog_type warning\nlog_type notice\nlog_type information\n"
                                 "max_packet_size 65536\n"
                                 "listener %3 127.0.0.1\n"
                                 "cafile %4\ncertfile %5\nkeyfile %6\n"
                                 "listener %7 127.0.0.1\n")
                      .arg(path("passwd"), path("acl"))
                      .arg(m_port)
                      .arg(caFile(), path("server.pem"), path("server.key"))
                      .arg(m_plainPort)
                      .toUtf8());
        m_process.setProcessChannelMode(QProcess::MergedChannels);
        m_process.start(program("mosquitto"), {QStringLiteral("-c"), path("mosquitto.conf")});
        const bool up = QTest::qWaitFor(
            [&] {
                if (m_process.state() == QProcess::NotRunning)
                    return true;
                QTcpSocket probe;
                QSignalSpy connected(&probe, &QTcpSocket::connected);
                probe.connectToHost(QHostAddress::LocalHost, m_plainPort);
                return connected.wait(200);
            },
            20000);
        if (!up || m_process.state() == QProcess::NotRunning) {
            *error = QStringLiteral("mosquitto did not start: %1").arg(QString::fromLocal8Bit(log()));
            return false;
        }
        return true;
    }

    void stop()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        QSignalSpy finished(&m_process, &QProcess::finished);
        m_process.terminate();
        if (!finished.wait(5000)) {
            m_process.kill();
            finished.wait(5000);
        }
    }

    quint16 port() const { return m_port; }           // TLS, accounts
    quint16 plainPort() const { return m_plainPort; } // no TLS, loopback, accounts
    QString caFile() const { return path("ca.pem"); }
    QString directory() const { return m_dir.path(); }
    QByteArray log() { return m_log += m_process.readAll(); }

    // "mqtts://USER@localhost:PORT?cafile=…", the address Slew is given.
    QString url(const QString &user, const QString &station = {}) const
    {
        return QStringLiteral("mqtts://%1@localhost:%2%3?cafile=%4")
            .arg(user)
            .arg(m_port)
            .arg(station.isEmpty() ? QString() : u'/' + station, caFile());
    }
    static QString password(const QString &user) { return user + QStringLiteral("-secret"); }
    // A file holding the user's password, readable by its owner only.
    QString passwordFile(const QString &user) const
    {
        const QString file = path((user + QStringLiteral(".password")).toUtf8().constData());
        QFile f(file);
        f.open(QIODevice::WriteOnly | QIODevice::Truncate);
        f.write(password(user).toUtf8() + '\n');
        f.setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner);
        return file;
    }

    // mosquitto_pub/mosquitto_sub's arguments to reach this broker as `user`.
    QStringList clientArguments(const QString &user, const QString &passwordGiven = {}) const
    {
        return {QStringLiteral("-h"), QStringLiteral("localhost"), QStringLiteral("-p"), QString::number(m_port),
                QStringLiteral("--cafile"), caFile(), QStringLiteral("-u"), user, QStringLiteral("-P"),
                passwordGiven.isEmpty() ? password(user) : passwordGiven, QStringLiteral("-V"),
                QStringLiteral("mqttv5")};
    }

    // One message, as mosquitto_pub sends it (QoS 1). Its output and
    // errors together (a refusal by the broker's access list is a warning
    // on stderr); nothing if it could not run.
    struct PubResult {
        int exitCode = -1;
        QByteArray said;
    };
    PubResult publish(const QString &user, const QString &topic, const QByteArray &payload, bool retain = false,
                      const QString &passwordGiven = {}) const
    {
        QProcess p;
        p.setProcessChannelMode(QProcess::MergedChannels);
        QStringList arguments = clientArguments(user, passwordGiven);
        arguments << QStringLiteral("-q") << QStringLiteral("1") << QStringLiteral("-t") << topic
                  << QStringLiteral("-m") << QString::fromUtf8(payload);
        if (retain)
            arguments << QStringLiteral("-r");
        QSignalSpy finished(&p, &QProcess::finished);
        p.start(program("mosquitto_pub"), arguments);
        finished.wait(20000);
        return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAll()};
    }

private:
    QString path(const char *name) const { return m_dir.filePath(QString::fromLatin1(name)); }
    void writeFile(const QString &name, const QByteArray &bytes) const
    {
        QFile f(m_dir.filePath(name));
        f.open(QIODevice::WriteOnly | QIODevice::Truncate);
        f.write(bytes);
    }

    bool makeCertificates(QString *error)
    {
        const QString openssl = program("openssl");
        const QStringList ec{QStringLiteral("-newkey"), QStringLiteral("ec"), QStringLiteral("-pkeyopt"),
                             QStringLiteral("ec_paramgen_curve:prime256v1"), QStringLiteral("-nodes")};
        writeFile(QStringLiteral("san.cnf"), "subjectAltName=DNS:localhost,IP:127.0.0.1\n");
        return run(openssl,
                   QStringList{QStringLiteral("req"), QStringLiteral("-x509")} + ec
                       + QStringList{QStringLiteral("-keyout"), path("ca.key"), QStringLiteral("-out"), path("ca.pem"),
                                     QStringLiteral("-days"), QStringLiteral("2"), QStringLiteral("-subj"),
                                     QStringLiteral("/CN=Slew test CA")},
                   error)
               && run(openssl,
                      QStringList{QStringLiteral("req")} + ec
                          + QStringList{QStringLiteral("-keyout"), path("server.key"), QStringLiteral("-out"),
                                        path("server.csr"), QStringLiteral("-subj"), QStringLiteral("/CN=localhost")},
                      error)
               && run(openssl,
                      {QStringLiteral("x509"), QStringLiteral("-req"), QStringLiteral("-in"), path("server.csr"),
                       QStringLiteral("-CA"), path("ca.pem"), QStringLiteral("-CAkey"), path("ca.key"),
                       QStringLiteral("-CAcreateserial"), QStringLiteral("-out"), path("server.pem"),
                       QStringLiteral("-days"), QStringLiteral("2"), QStringLiteral("-extfile"), path("san.cnf")},
                      error);
    }

    bool makeAccounts(QString *error)
    {
        const QString passwd = program("mosquitto_passwd");
        QStringList users{QStringLiteral("operator"), QStringLiteral("watcher")};
        QByteArray acl = "user operator\ntopic read slew/#\ntopic write slew/+/command\n\n"
                         "user watcher\ntopic read slew/#\n\n";
        for (const QString &name : m_stations) {
            users << QStringLiteral("station-") + name;
            acl += QStringLiteral("user station-%1\ntopic readwrite slew/%1/#\n\n").arg(name).toUtf8();
        }
        writeFile(QStringLiteral("acl"), acl);
        writeFile(QStringLiteral("passwd"), {});
        for (const QString &user : users) {
            if (!run(passwd, {QStringLiteral("-b"), path("passwd"), user, password(user)}, error))
                return false;
        }
        return true;
    }

    QStringList m_stations;
    QTemporaryDir m_dir;
    QProcess m_process;
    QByteArray m_log;
    quint16 m_port = 0;
    quint16 m_plainPort = 0;
};

// mosquitto_sub as a peer, running while the test goes on: every message it
// receives, one a line (`-v`: the topic, a space, the payload).
class MosquittoSubscriber {
public:
    MosquittoSubscriber(const MosquittoBroker &broker, const QString &user, const QStringList &topics)
    {
        QStringList arguments = broker.clientArguments(user);
        arguments << QStringLiteral("-v");
        for (const QString &t : topics)
            arguments << QStringLiteral("-t") << t;
        m_process.start(MosquittoBroker::program("mosquitto_sub"), arguments);
    }
    ~MosquittoSubscriber()
    {
        QSignalSpy finished(&m_process, &QProcess::finished);
        m_process.terminate();
        if (!finished.wait(5000)) {
            m_process.kill();
            finished.wait(5000);
        }
    }
    // Every line so far.
    QList<QByteArray> lines()
    {
        m_out += m_process.readAllStandardOutput();
        QList<QByteArray> all = m_out.split('\n');
        all.removeLast();
        return all;
    }
    // The payloads received on `topic` so far.
    QList<QByteArray> payloads(const QString &topic)
    {
        QList<QByteArray> out;
        const QByteArray prefix = topic.toUtf8() + ' ';
        for (const QByteArray &line : lines()) {
            if (line.startsWith(prefix))
                out << line.mid(prefix.size());
        }
        return out;
    }
    // Waits until a payload on `topic` satisfies `wanted`; it, or nothing.
    template <typename Wanted>
    std::optional<QByteArray> waitFor(const QString &topic, Wanted wanted, int ms = 15000)
    {
        std::optional<QByteArray> found;
        (void)QTest::qWaitFor(
            [&] {
                for (const QByteArray &p : payloads(topic)) {
                    if (wanted(p)) {
                        found = p;
                        return true;
                    }
                }
                return false;
            },
            ms);
        return found;
    }
    QByteArray errors() { return m_process.readAllStandardError(); }

private:
    QProcess m_process;
    QByteArray m_out;
};
