// SPDX-License-Identifier: GPL-3.0-or-later
// Remote operation over MQTT, measured on loopback with a real Mosquitto
// and TLS (a broker of the benchmark's own, as the tests make it):
//
//   bench_remote [stop|updates|watchers|network|all] [--trials N] [--seconds S] [path/to/slew]
//
//   stop      Stop from a remote window (RemoteStation::stop, what its Stop
//             button calls) to the simulator receiving SA SE from the
//             station service: N trials (100) while the rotator slews;
//             median, p90, p99, worst. The simulator runs in this process
//             behind a tap that stamps the stop's arrival on the same clock.
//   updates   State updates a second a remote window keeps up with: a
//             publisher (mosquitto_pub -l, fed lines at a paced rate) sends
//             states to a StationWindow drawn offscreen in this
//             process; at each rate for S seconds (5): received a second,
//             dropped, and the lag from sending to the window having it.
//   watchers  A station's CPU (utime + stime from /proc) over S seconds
//             (30) with no remote window and with 10 (`slew --remote`,
//             offscreen), at rest and while it slews.
//   network   20 station services publishing to one broker, and the station
//             network window (`slew --remote` without a name, offscreen):
//             its CPU and RSS over S seconds (30) at rest and while all 20
//             slew.
//
// Slew is the one built beside this benchmark unless a path or SLEW_BIN
// names another. A benchmark may wait: it is a measuring client.

#include "../../common/mosquittobroker.h"
#include "../../common/stationprocess.h"

#include "linkschemes.h"
#include "remote/remotestation.h"
#include "stationwindow.h"
#include "sim/simulator.h"
#include "sim/simulatoroptions.h"
#include "sim/simulatortcpserver.h"

#include <QApplication>
#include <QDateTime>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRandomGenerator>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <memory>
#include <unistd.h>
#include <vector>

using slew::remote::RemoteStation;

namespace {

QString g_slew;

// Runs the event loop until `done` or `ms` pass. Not QTest::qWaitFor, which
// sleeps 10 ms between looks: a socket's bytes would wait out the sleep and
// be stamped late. Here the loop blocks in poll and wakes for them at once.
// `lookMs`: how often `done` is asked (a look costs a wake-up of this
// process, which the updates figure counts as the window's).
bool waitUntil(const std::function<bool()> &done, int ms, int lookMs = 1)
{
    if (done())
        return true;
    QEventLoop loop;
    QTimer look;
    look.setTimerType(Qt::PreciseTimer);
    look.setInterval(lookMs);
    QObject::connect(&look, &QTimer::timeout, &loop, [&] {
        if (done())
            loop.quit();
    });
    QTimer giveUp;
    giveUp.setSingleShot(true);
    QObject::connect(&giveUp, &QTimer::timeout, &loop, &QEventLoop::quit);
    look.start();
    giveUp.start(ms);
    loop.exec();
    return done();
}

double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    const double at = p * double(v.size() - 1);
    const size_t lo = size_t(at);
    const size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (v[hi] - v[lo]) * (at - double(lo));
}

// CPU seconds (utime + stime) and RSS of a process, from /proc.
struct Usage {
    double cpuSeconds = 0;
    double rssMiB = 0;
};

Usage usage(qint64 pid)
{
    Usage u;
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (stat.open(QIODevice::ReadOnly)) {
        const QByteArray text = stat.readAll();
        const QList<QByteArray> fields = text.mid(text.lastIndexOf(')') + 2).split(' ');
        // After the name: state is field 3; utime 14 and stime 15 (1-based).
        if (fields.size() > 13)
            u.cpuSeconds = (fields[11].toDouble() + fields[12].toDouble()) / double(sysconf(_SC_CLK_TCK));
    }
    QFile status(QStringLiteral("/proc/%1/status").arg(pid));
    if (status.open(QIODevice::ReadOnly)) {
        for (const QByteArray &line : status.readAll().split('\n')) {
            if (line.startsWith("VmRSS:"))
                u.rssMiB = line.mid(6).trimmed().split(' ').first().toDouble() / 1024.0;
        }
    }
    return u;
}

double loadAverage()
{
    QFile f(QStringLiteral("/proc/loadavg"));
    return f.open(QIODevice::ReadOnly) ? f.readAll().split(' ').first().toDouble() : -1;
}

QStringList stationArguments(const MosquittoBroker &broker, const QString &name, const QString &uri)
{
    return {QStringLiteral("--connect"), uri, QStringLiteral("--limits"), QStringLiteral("0:450,0:180"),
            QStringLiteral("--mqtt"), broker.url(QStringLiteral("station-") + name), QStringLiteral("--station-name"),
            name, QStringLiteral("--mqtt-password-file"), broker.passwordFile(QStringLiteral("station-") + name)};
}

std::unique_ptr<RemoteStation> operatorStation(const MosquittoBroker &broker, const QString &name)
{
    QString error;
    slew::remote::MqttSettings settings;
    settings.broker = *slew::remote::parseBrokerAddress(broker.url(QStringLiteral("operator")), &error);
    settings.password = MosquittoBroker::password(QStringLiteral("operator"));
    auto station = std::make_unique<RemoteStation>(settings, name);
    if (!station->open(&error))
        std::fprintf(stderr, "bench_remote: %s\n", qPrintable(error));
    return station;
}

// A TCP tap between the station and the simulator: passes every byte, and
// stamps the moment a stop (Easycomm `SA`) arrives from the station.
class StopTap : public QObject {
public:
    StopTap(quint16 simulatorPort) : m_simulatorPort(simulatorPort)
    {
        m_server.listen(QHostAddress::LocalHost, 0);
        connect(&m_server, &QTcpServer::newConnection, this, [this] {
            QTcpSocket *station = m_server.nextPendingConnection();
            auto *sim = new QTcpSocket(station);
            sim->connectToHost(QHostAddress::LocalHost, m_simulatorPort);
            sim->setSocketOption(QAbstractSocket::LowDelayOption, 1);
            station->setSocketOption(QAbstractSocket::LowDelayOption, 1);
            connect(station, &QTcpSocket::readyRead, this, [this, station, sim] {
                const QByteArray bytes = station->readAll();
                if (bytes.contains("SA"))
                    m_stopAt = m_clock.nsecsElapsed();
                // A set position, "AZ123.4 EL…" (a poll is a bare "AZ EL").
                for (qsizetype at = bytes.indexOf("AZ"); at >= 0; at = bytes.indexOf("AZ", at + 2)) {
                    if (at + 2 < bytes.size() && (std::isdigit(static_cast<unsigned char>(bytes[at + 2])) || bytes[at + 2] == '-'))
                        m_moveAt = m_clock.nsecsElapsed();
                }
                sim->write(bytes);
            });
            connect(sim, &QTcpSocket::readyRead, station, [station, sim] { station->write(sim->readAll()); });
            connect(station, &QTcpSocket::disconnected, station, &QObject::deleteLater);
        });
        m_clock.start();
    }
    quint16 port() const { return m_server.serverPort(); }
    qint64 now() const { return m_clock.nsecsElapsed(); }
    qint64 m_stopAt = -1;
    qint64 m_moveAt = -1;

private:
    QTcpServer m_server;
    quint16 m_simulatorPort;
    QElapsedTimer m_clock;
};

void benchStop(int trials)
{
    std::printf("\n== Stop from a remote window to the simulator receiving it (loopback, TLS) ==\n");
    MosquittoBroker broker;
    QString error;
    if (!broker.start(&error)) {
        std::fprintf(stderr, "bench_remote: %s\n", qPrintable(error));
        return;
    }
    slew::sim::SimulatorOptions simOptions;
    slew::sim::Simulator simulator(simOptions);
    slew::sim::SimulatorTcpServer simServer(simulator, {});
    simServer.listen(QHostAddress::LocalHost, 0);
    StopTap tap(simServer.serverPort());
    StationProcess station(stationArguments(broker, QStringLiteral("mast"),
                                            QStringLiteral("tcp://127.0.0.1:%1").arg(tap.port())));
    if (!station.logged("remote: connected to", 20000)) {
        std::fprintf(stderr, "bench_remote: the station did not connect: %s\n", station.said().constData());
        return;
    }
    auto remote = operatorStation(broker, QStringLiteral("mast"));
    waitUntil([&] { return remote->isLive(); }, 20000);
    std::vector<double> ms;
    int lost = 0;
    for (int i = 0; i < trials; ++i) {
        tap.m_moveAt = -1;
        remote->gotoPosition(i % 2 ? 60 : 300, i % 2 ? 20 : 60);
        if (!waitUntil([&] { return tap.m_moveAt >= 0; }, 5000)) {
            ++lost;
            continue;
        }
        // Somewhere in the slew, not in step with the station's polling.
        const int into = 150 + int(QRandomGenerator::global()->bounded(400));
        waitUntil([&] { return tap.now() - tap.m_moveAt > qint64(into) * 1000000; }, 5000);
        tap.m_stopAt = -1;
        const qint64 sent = tap.now();
        remote->stop();
        if (!waitUntil([&] { return tap.m_stopAt >= 0; }, 5000)) {
            ++lost;
            continue;
        }
        ms.push_back(double(tap.m_stopAt - sent) / 1e6);
    }
    std::printf("trials %zu (not measured: %d); load average %.2f\n", ms.size(), lost, loadAverage());
    std::printf("Stop, window to simulator: median %.1f ms, p90 %.1f ms, p99 %.1f ms, worst %.1f ms (goal: p99 under 250 ms)\n",
                percentile(ms, 0.5), percentile(ms, 0.9), percentile(ms, 0.99), percentile(ms, 1.0));
    station.stop(SIGTERM);
}

QByteArray stateLine(int sequence)
{
    slew::face::StationState s;
    s.unixMs = QDateTime::currentMSecsSinceEpoch();
    s.link = QStringLiteral("connected");
    s.position = QPointF(double(sequence % 3600) / 10.0, 30.0 + double(sequence % 300) / 10.0);
    s.stale = false;
    s.target = QPointF(180, 45);
    s.moving = true;
    s.limits = {0, 450, 0, 180};
    s.controllerVersion = QStringLiteral("bench");
    s.slewVersion = QStringLiteral("0.1.0");
    return slew::remote::encodeStationState(s);
}

void benchUpdates(double seconds)
{
    std::printf("\n== State updates a second a remote window keeps up with (window drawn offscreen) ==\n");
    MosquittoBroker broker;
    QString error;
    if (!broker.start(&error)) {
        std::fprintf(stderr, "bench_remote: %s\n", qPrintable(error));
        return;
    }
    auto remote = operatorStation(broker, QStringLiteral("mast"));
    auto *window = new slew::ui::StationWindow(remote.get());
    window->show();
    // The station says it is online, retained, as a station does.
    broker.publish(QStringLiteral("station-mast"), QStringLiteral("slew/mast/online"), "true", true);
    std::vector<double> lags;
    QObject::connect(remote.get(), &RemoteStation::stateChanged, [&](const slew::face::StationState &s) {
        lags.push_back(double(QDateTime::currentMSecsSinceEpoch() - s.unixMs));
    });
    std::printf("%8s %10s %10s %9s %9s %9s %s\n", "rate/s", "sent", "received", "lag p50", "lag p99", "lag max",
                "the window's CPU (this process)");
    for (int rate : {10, 50, 100, 200, 500, 1000, 2000, 5000}) {
        QProcess pub;
        QStringList arguments = broker.clientArguments(QStringLiteral("station-mast"));
        arguments << QStringLiteral("-q") << QStringLiteral("0") << QStringLiteral("-t") << QStringLiteral("slew/mast/state")
                  << QStringLiteral("-l");
        pub.start(MosquittoBroker::program("mosquitto_pub"), arguments);
        pub.waitForStarted();
        lags.clear();
        const int before = remote->statesReceived();
        const Usage cpu0 = usage(QCoreApplication::applicationPid());
        QElapsedTimer clock;
        clock.start();
        int sent = 0;
        QTimer pace;
        pace.setTimerType(Qt::PreciseTimer);
        pace.setInterval(5);
        QObject::connect(&pace, &QTimer::timeout, [&] {
            const int due = int(double(clock.elapsed()) / 1000.0 * rate);
            QByteArray lines;
            while (sent < due)
                lines += stateLine(sent++) + '\n';
            pub.write(lines);
        });
        pace.start();
        waitUntil([&] { return clock.elapsed() >= qint64(seconds * 1000); }, int(seconds * 1000) + 5000, 100);
        pace.stop();
        // What was sent has a second to arrive.
        waitUntil([&] { return remote->statesReceived() - before >= sent; }, 1000, 20);
        const Usage cpu1 = usage(QCoreApplication::applicationPid());
        const int received = remote->statesReceived() - before;
        std::printf("%8d %10d %10d %7.0f ms %7.0f ms %7.0f ms %5.0f %% of a core\n", rate, sent, received,
                    percentile(lags, 0.5), percentile(lags, 0.99), percentile(lags, 1.0),
                    100.0 * (cpu1.cpuSeconds - cpu0.cpuSeconds) / (double(clock.elapsed()) / 1000.0));
        pub.closeWriteChannel();
        pub.waitForFinished(5000);
    }
    std::printf("load average %.2f\n", loadAverage());
    delete window;
}

// `slew --remote URL` windows, offscreen.
struct RemoteWindows {
    std::vector<std::unique_ptr<QProcess>> processes;
    void start(const MosquittoBroker &broker, const QString &user, const QString &station, int count)
    {
        for (int i = 0; i < count; ++i) {
            auto p = std::make_unique<QProcess>();
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
            env.insert(QStringLiteral("SLEW_MQTT_PASSWORD"), MosquittoBroker::password(user));
            p->setProcessEnvironment(env);
            p->start(g_slew, {QStringLiteral("--remote"), broker.url(user, station)});
            processes.push_back(std::move(p));
        }
    }
    ~RemoteWindows()
    {
        for (auto &p : processes) {
            p->terminate();
            p->waitForFinished(5000);
        }
    }
};

// CPU % of a core and RSS of `pid` over `seconds`, while `during` runs.
std::pair<double, double> measure(qint64 pid, double seconds)
{
    const Usage a = usage(pid);
    QElapsedTimer clock;
    clock.start();
    waitUntil([&] { return clock.elapsed() >= qint64(seconds * 1000); }, int(seconds * 1000) + 1000, 100);
    const Usage b = usage(pid);
    return {100.0 * (b.cpuSeconds - a.cpuSeconds) / (double(clock.elapsed()) / 1000.0), b.rssMiB};
}

// The station driven over rotctld with no broker at all: what the station
// costs before MQTT adds anything.
std::pair<double, double> stationWithoutBroker(double seconds, std::pair<double, double> *moving)
{
    StationProcess station({QStringLiteral("--connect"), QStringLiteral("sim:"), QStringLiteral("--limits"),
                            QStringLiteral("0:450,0:180"), QStringLiteral("--rotctld-listen"), QStringLiteral("127.0.0.1:0")});
    station.logged("rotctld listening on", 20000);
    const QByteArray line = station.out.mid(station.out.indexOf("rotctld listening on"));
    const quint16 port = quint16(line.mid(line.indexOf(':', 25) + 1, line.indexOf('\n') - line.indexOf(':', 25) - 1).toUInt());
    QTcpSocket tracker;
    tracker.connectToHost(QHostAddress::LocalHost, port);
    tracker.waitForConnected(5000);
    waitUntil([] { return false; }, 8000);
    const qint64 pid = station.process.processId();
    const auto rest = measure(pid, seconds);
    int n = 0;
    auto slew = [&] { tracker.write(n++ % 2 ? "P 10 45\n" : "P 350 45\n"); };
    QTimer mover;
    mover.setInterval(20000);
    QObject::connect(&mover, &QTimer::timeout, slew);
    slew();
    mover.start();
    *moving = measure(pid, seconds);
    tracker.write("S\n");
    station.stop(SIGTERM);
    return rest;
}

void benchWatchers(double seconds)
{
    std::printf("\n== A station's CPU with remote windows watching ==\n");
    std::pair<double, double> movingAlone;
    const auto restAlone = stationWithoutBroker(seconds, &movingAlone);
    std::printf("no broker (driven over rotctld): the station at rest %.2f %% of a core, slewing %.2f %%; RSS %.1f MiB; "
                "load average %.2f\n",
                restAlone.first, movingAlone.first, movingAlone.second, loadAverage());
    MosquittoBroker broker;
    QString error;
    if (!broker.start(&error)) {
        std::fprintf(stderr, "bench_remote: %s\n", qPrintable(error));
        return;
    }
    StationProcess station(stationArguments(broker, QStringLiteral("mast"), QStringLiteral("sim:")));
    station.logged("remote: connected to", 20000);
    auto remote = operatorStation(broker, QStringLiteral("mast"));
    waitUntil([&] { return remote->isLive(); }, 20000);
    const qint64 pid = station.process.processId();
    int n = 0;
    auto slewing = [&] { remote->gotoPosition(n++ % 2 ? 10 : 350, 45); }; // back and forth across the sky
    QTimer mover;
    mover.setInterval(20000);
    QObject::connect(&mover, &QTimer::timeout, slewing);
    for (int windows : {0, 10}) {
        RemoteWindows watching;
        watching.start(broker, QStringLiteral("watcher"), QStringLiteral("mast"), windows);
        waitUntil([] { return false; }, 8000); // the windows connect, the station settles at rest
        const auto rest = measure(pid, seconds);
        slewing();
        mover.start();
        const auto moving = measure(pid, seconds);
        mover.stop();
        remote->stop();
        std::printf("on the broker, %2d remote windows: the station at rest %.2f %% of a core, slewing %.2f %%; RSS "
                    "%.1f MiB (goal: under 1 %%); load average %.2f\n",
                    windows, rest.first, moving.first, moving.second, loadAverage());
    }
    station.stop(SIGTERM);
}

void benchNetwork(double seconds)
{
    std::printf("\n== 20 stations on one broker, and the station network window ==\n");
    QStringList names;
    for (int i = 1; i <= 20; ++i)
        names << QStringLiteral("st%1").arg(i, 2, 10, QLatin1Char('0'));
    MosquittoBroker broker(names);
    QString error;
    if (!broker.start(&error)) {
        std::fprintf(stderr, "bench_remote: %s\n", qPrintable(error));
        return;
    }
    std::vector<std::unique_ptr<StationProcess>> stations;
    for (int i = 0; i < names.size(); ++i)
        stations.push_back(std::make_unique<StationProcess>(stationArguments(
            broker, names[i], QStringLiteral("sim:?start_az=%1&start_el=%2").arg(i * 17 % 360).arg(10 + i * 3))));
    for (auto &s : stations)
        s->logged("remote: connected to", 30000);
    RemoteWindows overview;
    overview.start(broker, QStringLiteral("watcher"), {}, 1);
    waitUntil([] { return false; }, 8000);
    const qint64 pid = overview.processes.front()->processId();
    const auto rest = measure(pid, seconds);
    // All twenty slew at once, as far as they go.
    std::vector<std::unique_ptr<RemoteStation>> operators;
    for (int i = 0; i < names.size(); ++i) {
        operators.push_back(operatorStation(broker, names[i]));
        waitUntil([&] { return operators.back()->isLive(); }, 10000);
        operators.back()->gotoPosition((i * 17 + 180) % 360, 80 - i);
    }
    const auto moving = measure(pid, seconds);
    std::printf("the network window, 20 stations: at rest %.2f %% of a core, RSS %.1f MiB; all slewing %.2f %%, "
                "RSS %.1f MiB; load average %.2f\n",
                rest.first, rest.second, moving.first, moving.second, loadAverage());
    for (auto &o : operators)
        o->stop();
    if (!qEnvironmentVariableIsEmpty("SLEW_BENCH_KEEP_NETWORK")) {
        std::printf("stations kept running: slew --remote %s (password %s)\n", qPrintable(broker.url(QStringLiteral("watcher"))),
                    qPrintable(MosquittoBroker::password(QStringLiteral("watcher"))));
        waitUntil([] { return false; }, qEnvironmentVariableIntValue("SLEW_BENCH_KEEP_NETWORK") * 1000);
    }
    for (auto &s : stations)
        s->stop(SIGTERM);
}

} // namespace

int main(int argc, char **argv)
{
    std::setvbuf(stdout, nullptr, _IOLBF, 0); // each figure as it is measured, into a file too
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    slew::registerLinkSchemes();
    QStringList args = app.arguments().mid(1);
    QString what = QStringLiteral("all");
    int trials = 100;
    double seconds = -1;
    g_slew = qEnvironmentVariable("SLEW_BIN", QStringLiteral(SLEW_DEFAULT_PATH));
    for (int i = 0; i < args.size(); ++i) {
        if (args[i] == u"--trials" && i + 1 < args.size())
            trials = args[++i].toInt();
        else if (args[i] == u"--seconds" && i + 1 < args.size())
            seconds = args[++i].toDouble();
        else if (QStringList{"stop", "updates", "watchers", "network", "all"}.contains(args[i]))
            what = args[i];
        else
            g_slew = args[i];
    }
    qputenv("SLEW_BIN", g_slew.toLocal8Bit());
    std::printf("bench_remote %s, %s, slew %s\n", qPrintable(what),
                qPrintable(QDateTime::currentDateTimeUtc().toString(Qt::ISODate)), qPrintable(g_slew));
    if (what == u"stop" || what == u"all")
        benchStop(trials);
    if (what == u"updates" || what == u"all")
        benchUpdates(seconds > 0 ? seconds : 5);
    if (what == u"watchers" || what == u"all")
        benchWatchers(seconds > 0 ? seconds : 30);
    if (what == u"network" || what == u"all")
        benchNetwork(seconds > 0 ? seconds : 30);
    return 0;
}
