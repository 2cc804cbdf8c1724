#pragma once
// A scripted rotator controller behind an in-process link (`fake:N`), for
// the session's unit tests: no socket and no simulator, and a clock of its
// own that moves 5 ms each time the event loop comes round, so polling,
// reply timeouts and the stop hold run on it (session/linktimer.h) and a
// busy machine changes nothing. By default it answers like a small
// SatNOGS-style controller; a test can replace the answer for any line,
// stay silent, echo what it hears, drop the connection or refuse new ones.
//
// Wait with runEventLoopUntil (tests/common/simulatorpump.h), not QTRY_*:
// those sleep 10 ms between looks, and the clock would crawl.

#include "transport/link.h"
#include "transport/linkfactory.h"
#include "../common/queuedreaddevice.h"

#include <QByteArray>
#include <QIODevice>
#include <QList>
#include <QMap>
#include <QPointer>
#include <QTimer>

#include <cmath>
#include <functional>
#include <memory>

class FakeDevice;

// The controller's end of the line, as the session's link sees it: what is
// written goes to the FakeDevice, what it answers is read back.
class FakePort : public QueuedReadDevice {
public:
    explicit FakePort(FakeDevice *device) : m_device(device) {}

protected:
    qint64 writeData(const char *data, qint64 size) override;

private:
    QPointer<FakeDevice> m_device;
};

class FakeLink : public slew::transport::Link {
public:
    FakeLink(const QString &uri, FakeDevice *device);
    QIODevice *device() override { return &m_port; }
    void open() override;
    void close() override { m_port.close(); }
    bool isOpen() const override { return m_port.isOpen(); }
    std::optional<double> clockSeconds() const override;
    bool clockIsStepped() const override { return true; }
    void dropped() // the controller hung up
    {
        m_port.close();
        emit lost(QStringLiteral("%1: connection closed by the controller").arg(uri()));
    }
    void stepped(double seconds) { emit clockStepped(seconds); }
    FakePort &port() { return m_port; }

private:
    QPointer<FakeDevice> m_device;
    FakePort m_port;
};

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
    // A binary dialect (SPID frames) has no lines: when set, every write is
    // handed over whole, and what it returns is the answer.
    std::function<QByteArray(const QByteArray &bytes)> binary;

    static constexpr double kSliceSeconds = 0.005;

    FakeDevice() : m_id(++lastId())
    {
        registerScheme();
        devices().insert(m_id, this);
        m_pump.setInterval(0);
        connect(&m_pump, &QTimer::timeout, this, [this] {
            m_now += kSliceSeconds;
            if (m_link)
                m_link->stepped(m_now);
        });
        m_pump.start();
    }
    ~FakeDevice() override { devices().remove(m_id); }

    QString uri() const { return QStringLiteral("fake:%1").arg(m_id); }
    double now() const { return m_now; }
    bool hasClient() const { return m_link && m_link->isOpen(); }

    void push(const QByteArray &bytes)
    {
        if (hasClient())
            m_link->port().deliver(bytes);
    }
    void dropClient()
    {
        if (hasClient())
            QTimer::singleShot(0, m_link.data(), &FakeLink::dropped);
    }
    // While refusing, a link that opens fails as a refused connection would.
    void refuseConnections(bool refuse) { m_refusing = refuse; }
    int count(const QByteArray &line) const { return int(received.count(line)); }

    // The link side.
    bool accept(FakeLink *link)
    {
        if (m_refusing)
            return false;
        if (m_link && m_link != link)
            m_link->close();
        m_link = link;
        m_buffer.clear();
        emit clientConnected();
        return true;
    }
    void bytesWritten(const QByteArray &bytes)
    {
        if (binary) {
            push(binary(bytes));
            return;
        }
        m_buffer += bytes;
        qsizetype end;
        while ((end = m_buffer.indexOf('\n')) >= 0) {
            const QByteArray line = m_buffer.left(end).trimmed();
            m_buffer.remove(0, end + 1);
            received << line;
            emit lineReceived(line);
            if (echo)
                push(line + "\n");
            if (silent)
                continue;
            if (ignoreNext > 0) {
                --ignoreNext;
                continue;
            }
            QByteArray answer = script ? script(line) : QByteArray();
            if (answer.isEmpty())
                answer = defaultAnswer(line);
            push(answer);
        }
    }

    static FakeDevice *find(int id) { return devices().value(id); }

signals:
    void clientConnected();
    void lineReceived(const QByteArray &line);

private:
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

    static int &lastId()
    {
        static int id = 0;
        return id;
    }
    static QMap<int, FakeDevice *> &devices()
    {
        static QMap<int, FakeDevice *> all;
        return all;
    }
    static void registerScheme()
    {
        static bool done = false;
        if (done)
            return;
        done = true;
        slew::transport::registerLinkScheme(QStringLiteral("fake"), [](const QUrl &url, const QString &uri) {
            FakeDevice *device = find(url.path().toInt());
            if (!device)
                return slew::transport::LinkResult{nullptr, QStringLiteral("%1: no such fake device").arg(uri)};
            return slew::transport::LinkResult{std::make_unique<FakeLink>(uri, device), {}};
        });
    }

    int m_id;
    double m_now = 0.0;
    bool m_refusing = false;
    QTimer m_pump;
    QPointer<FakeLink> m_link;
    QByteArray m_buffer;
};

inline qint64 FakePort::writeData(const char *data, qint64 size)
{
    if (m_device)
        m_device->bytesWritten(QByteArray(data, size));
    return size;
}

inline FakeLink::FakeLink(const QString &uri, FakeDevice *device) : Link(uri), m_device(device), m_port(device) {}

inline void FakeLink::open()
{
    QTimer::singleShot(0, this, [this] {
        if (!m_device || !m_device->accept(this)) {
            emit failed(QStringLiteral("%1: connection refused").arg(uri()));
            return;
        }
        m_port.open(QIODevice::ReadWrite);
        emit opened();
    });
}

inline std::optional<double> FakeLink::clockSeconds() const
{
    return m_device ? std::optional<double>(m_device->now()) : std::nullopt;
}

// K3NG's Easycom firmware, as its own source answers (docs/protocol.md,
// "Controllers in the field"): bare numbers for `AZ EL`, the separators
// alone for a set, `?` for a command it lacks. It lets go of the azimuth
// `stopsShortDeg` before the target, inside its tolerance (2.3° of its 3°
// is what its relays leave; 0: on the target).
inline QByteArray k3ngEasycom(FakeDevice &d, const QByteArray &line, double stopsShortDeg = 0.0)
{
    if (line == "AZ EL")
        return "+" + QByteArray::number(d.az, 'f', 1) + " +" + QByteArray::number(d.el, 'f', 1) + "\n";
    if (line == "VE")
        return "VE002\n";
    if (line.startsWith("AZ") && line.contains(" EL")) {
        const QList<QByteArray> parts = line.split(' ');
        const double az = parts[0].mid(2).toDouble();
        d.az = az - std::copysign(stopsShortDeg, az - d.az);
        d.el = parts[1].mid(2).toDouble();
        return " \n";
    }
    if (line == "SA SE" || line == "ML" || line == "MR" || line == "MU" || line == "MD")
        return " \n";
    return "?\n"; // PARK, GS, GE, IP0, CR 1, VL...
}
