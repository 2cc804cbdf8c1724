// What a station costs when nothing happens, and per answer when trackers
// ask: `slew --headless --connect sim:` beside Hamlib's `rotctld -m 1` (its
// dummy rotator), measured from /proc in one run.
//
//   bench_idle [--seconds S] [--clients N] [--rate HZ] [path/to/slew]
//
// Slew is the one built beside this benchmark unless a path or SLEW_BIN
// names another; rotctld is found on PATH (Debian: libhamlib-utils).
//
// At rest (after both have settled), over S seconds (10): wake-ups a
// second (voluntary and involuntary context switches of every thread), CPU
// time (utime + stime) and RSS. Then, for each server in turn, N clients
// (10) on their own TCP connections each ask `p` at HZ (10) for S seconds:
// the server's CPU per answer (on-CPU nanoseconds of every thread, from
// schedstat). Then the same for both servers at once, measured over the
// same S seconds: on a machine that is busy with other work, what that work
// costs a server (its caches, a core to wait for) changes from one ten
// seconds to the next, and weighs on both alike only when they are measured
// together. A benchmark may block: it is a measuring client, not product
// code.
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QStandardPaths>
#include <QTcpServer>

#include <arpa/inet.h>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>
#include <vector>

namespace {

struct Settings {
    double seconds = 10.0;
    int clients = 10;
    double rate = 10.0;
    double settleSeconds = 8.0; // Slew polls at the full rate for a while after it connects
};

// What /proc says of a process, summed over its threads.
struct Sample {
    double cpuSeconds = 0;   // utime + stime, clock ticks
    double onCpuSeconds = 0; // schedstat, nanoseconds
    long long switches = 0;  // voluntary + involuntary
    double rssMiB = 0;
    int threads = 0;
};

QByteArray readProc(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

long long statusField(const QByteArray &status, const char *name)
{
    const QByteArray key = QByteArray(name) + ':';
    const qsizetype at = status.indexOf(key);
    if (at < 0)
        return 0;
    const qsizetype end = status.indexOf('\n', at);
    return status.mid(at + key.size(), end - at - key.size()).trimmed().split(' ').front().toLongLong();
}

Sample sample(qint64 pid)
{
    Sample s;
    const QString dir = QStringLiteral("/proc/%1").arg(pid);
    const QByteArray stat = readProc(dir + "/stat");
    if (const qsizetype close = stat.lastIndexOf(')'); close > 0) {
        // After the command: state(3) ... utime(14) stime(15).
        const QList<QByteArray> fields = stat.mid(close + 2).split(' ');
        if (fields.size() > 12)
            s.cpuSeconds = double(fields[11].toLongLong() + fields[12].toLongLong()) / double(sysconf(_SC_CLK_TCK));
    }
    s.rssMiB = double(statusField(readProc(dir + "/status"), "VmRSS")) / 1024.0;
    const QStringList tasks = QDir(dir + "/task").entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    for (const QString &task : tasks) {
        const QString t = dir + "/task/" + task;
        const QByteArray status = readProc(t + "/status");
        s.switches += statusField(status, "voluntary_ctxt_switches") + statusField(status, "nonvoluntary_ctxt_switches");
        s.onCpuSeconds += double(readProc(t + "/schedstat").split(' ').front().toLongLong()) / 1e9;
    }
    s.threads = int(tasks.size());
    return s;
}

quint16 freeTcpPort()
{
    QTcpServer s;
    s.listen(QHostAddress::LocalHost, 0);
    return s.serverPort();
}

int connectTo(quint16 port)
{
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<sockaddr *>(&a), sizeof a) != 0) {
        ::close(fd);
        return -1;
    }
    const int one = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    return fd;
}

// Asks `p` once on a fresh connection; true on a position answer.
bool answersPosition(quint16 port)
{
    const int fd = connectTo(port);
    if (fd < 0)
        return false;
    QByteArray got;
    bool ok = ::write(fd, "p\n", 2) == 2;
    while (ok && got.count('\n') < 2 && !got.startsWith("RPRT")) {
        pollfd p{fd, POLLIN, 0};
        char buffer[256];
        const ssize_t n = ::poll(&p, 1, 2000) > 0 ? ::read(fd, buffer, sizeof buffer) : -1;
        ok = n > 0;
        if (ok)
            got.append(buffer, n);
    }
    ::close(fd);
    return ok && !got.startsWith("RPRT");
}

bool waitForPosition(quint16 port, int timeoutMs)
{
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < timeoutMs) {
        if (answersPosition(port))
            return true;
        ::usleep(100 * 1000);
    }
    return false;
}

struct Server {
    explicit Server(const char *n) : name(n) {}
    const char *name;
    QProcess process;
    quint16 port = 0;
    qint64 pid() const { return process.processId(); }
    ~Server()
    {
        process.terminate();
        if (!process.waitForFinished(5000))
            process.kill();
    }
};

bool start(Server &server, const QString &program, const QStringList &arguments)
{
    server.process.setStandardOutputFile(QProcess::nullDevice());
    server.process.setStandardErrorFile(QProcess::nullDevice());
    server.process.start(program, arguments);
    if (!server.process.waitForStarted(5000)) {
        std::printf("%s did not start: %s\n", server.name, qPrintable(server.process.errorString()));
        return false;
    }
    if (!waitForPosition(server.port, 15000)) {
        std::printf("%s does not answer `p` on port %u\n", server.name, server.port);
        return false;
    }
    return true;
}

struct Load {
    long long answers = 0;
    long long refused = 0; // RPRT answers
    long long late = 0;    // a request not sent: the last was not answered yet
    double worstMs = 0;
    // The server, with every client connected: a thread per client
    // (rotctld) counts only while it lives.
    Sample before, after;
};

// N clients for each server, on their own connections, each asking `p` at
// `rate`, for `seconds`: one Load a server. Given several servers, they are
// asked at the same time and measured over the same window, so that what
// else the machine does weighs on each alike.
std::vector<Load> askFromClients(const std::vector<const Server *> &servers, const Settings &settings)
{
    struct Client {
        size_t server = 0;
        int fd = -1;
        QByteArray pending;
        int lines = 0;
        bool waiting = false;
        qint64 sentNs = 0;
        qint64 nextNs = 0;
    };
    std::vector<Load> loads(servers.size());
    std::vector<Client> clients;
    const qint64 periodNs = qint64(1e9 / settings.rate);
    const auto closeAll = [&] {
        for (Client &c : clients)
            ::close(c.fd);
    };
    for (size_t s = 0; s < servers.size(); ++s) {
        for (int i = 0; i < settings.clients; ++i) {
            Client c;
            c.server = s;
            c.fd = connectTo(servers[s]->port);
            if (c.fd < 0) {
                std::printf("client %d of %s could not connect\n", i, servers[s]->name);
                closeAll();
                return {};
            }
            ::fcntl(c.fd, F_SETFL, O_NONBLOCK);
            // Spread over the period, as trackers started at different times
            // are; the servers' clients in turn, so that no two ask at once.
            const qint64 slot = qint64(i) * qint64(servers.size()) + qint64(s);
            c.nextNs = slot * periodNs / (qint64(settings.clients) * qint64(servers.size()));
            clients.push_back(c);
        }
    }
    ::usleep(200 * 1000); // every client accepted, its thread (rotctld) started
    for (size_t s = 0; s < servers.size(); ++s)
        loads[s].before = sample(servers[s]->pid());
    QElapsedTimer clock;
    clock.start();
    const qint64 endNs = qint64(settings.seconds * 1e9);
    std::vector<pollfd> fds(clients.size());
    while (clock.nsecsElapsed() < endNs) {
        qint64 now = clock.nsecsElapsed();
        qint64 nextDue = endNs;
        for (Client &c : clients) {
            if (now >= c.nextNs) {
                if (c.waiting) {
                    ++loads[c.server].late;
                } else if (::write(c.fd, "p\n", 2) == 2) {
                    c.waiting = true;
                    c.sentNs = now;
                }
                // A stall of the benchmark itself is not made up for in a burst.
                while (c.nextNs <= now)
                    c.nextNs += periodNs;
            }
            nextDue = std::min(nextDue, c.nextNs);
        }
        for (size_t i = 0; i < clients.size(); ++i)
            fds[i] = pollfd{clients[i].fd, POLLIN, 0};
        const int waitMs = int(std::max<qint64>(0, (nextDue - clock.nsecsElapsed()) / 1000000));
        if (::poll(fds.data(), nfds_t(fds.size()), waitMs) <= 0)
            continue;
        now = clock.nsecsElapsed();
        for (size_t i = 0; i < clients.size(); ++i) {
            if (!(fds[i].revents & POLLIN))
                continue;
            Client &c = clients[i];
            Load &load = loads[c.server];
            char buffer[512];
            const ssize_t n = ::read(c.fd, buffer, sizeof buffer);
            if (n <= 0)
                continue;
            c.pending.append(buffer, n);
            qsizetype end;
            while ((end = c.pending.indexOf('\n')) >= 0) {
                const QByteArray line = c.pending.left(end);
                c.pending.remove(0, end + 1);
                const bool refusal = line.startsWith("RPRT");
                if (!refusal && ++c.lines < 2)
                    continue; // a position is two lines: azimuth, elevation
                c.lines = 0;
                c.waiting = false;
                ++(refusal ? load.refused : load.answers);
                load.worstMs = std::max(load.worstMs, double(now - c.sentNs) / 1e6);
            }
        }
    }
    for (size_t s = 0; s < servers.size(); ++s)
        loads[s].after = sample(servers[s]->pid());
    closeAll();
    return loads;
}

struct RestFigures {
    double wakeUps = 0, cpuPercent = 0, rssMiB = 0;
    int threads = 0;
};

struct LoadFigures {
    Load load;
    double microsPerAnswer = 0, ticksMicrosPerAnswer = 0;
};

LoadFigures figures(const Load &load)
{
    LoadFigures f;
    f.load = load;
    const Sample &before = f.load.before, &after = f.load.after;
    if (f.load.answers > 0) {
        f.microsPerAnswer = 1e6 * (after.onCpuSeconds - before.onCpuSeconds) / double(f.load.answers);
        f.ticksMicrosPerAnswer = 1e6 * (after.cpuSeconds - before.cpuSeconds) / double(f.load.answers);
    }
    return f;
}

QString slewProgram(const QStringList &arguments)
{
    if (!arguments.isEmpty())
        return arguments.back();
    if (const QByteArray env = qgetenv("SLEW_BIN"); !env.isEmpty())
        return QString::fromLocal8Bit(env);
    return QStringLiteral(SLEW_DEFAULT_PATH);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    Settings settings;
    QStringList rest = app.arguments().mid(1);
    auto option = [&](const char *name, double *value) {
        const qsizetype at = rest.indexOf(QLatin1String(name));
        if (at >= 0 && at + 1 < rest.size()) {
            *value = rest[at + 1].toDouble();
            rest.remove(at, 2);
        }
    };
    double clients = settings.clients;
    option("--seconds", &settings.seconds);
    option("--rate", &settings.rate);
    option("--clients", &clients);
    settings.clients = std::max(1, int(clients));

    Server slew("slew");
    slew.port = freeTcpPort();
    if (!start(slew, slewProgram(rest),
               {"--headless", "--connect", "sim:", "--rotctld-listen", QStringLiteral("127.0.0.1:%1").arg(slew.port)}))
        return 1;
    const QString rotctldPath = QStandardPaths::findExecutable(QStringLiteral("rotctld"));
    Server rotctld("rotctld -m 1");
    bool haveRotctld = !rotctldPath.isEmpty();
    if (!haveRotctld) {
        std::printf("rotctld not found (Debian: libhamlib-utils): Slew alone\n");
    } else {
        rotctld.port = freeTcpPort();
        haveRotctld = start(rotctld, rotctldPath, {"-m", "1", "-T", "127.0.0.1", "-t", QString::number(rotctld.port)});
    }
    std::vector<const Server *> servers{&slew};
    if (haveRotctld)
        servers.push_back(&rotctld);

    std::printf("settling %.0f s, then %.0f s at rest with nobody asking...\n", settings.settleSeconds, settings.seconds);
    std::fflush(stdout);
    ::usleep(useconds_t(settings.settleSeconds * 1e6));
    std::vector<Sample> before, after;
    for (const Server *s : servers)
        before.push_back(sample(s->pid()));
    ::usleep(useconds_t(settings.seconds * 1e6));
    for (const Server *s : servers)
        after.push_back(sample(s->pid()));
    std::vector<RestFigures> restFigures;
    for (size_t i = 0; i < servers.size(); ++i) {
        RestFigures r;
        r.wakeUps = double(after[i].switches - before[i].switches) / settings.seconds;
        r.cpuPercent = 100.0 * (after[i].cpuSeconds - before[i].cpuSeconds) / settings.seconds;
        r.rssMiB = after[i].rssMiB;
        r.threads = after[i].threads;
        restFigures.push_back(r);
    }

    std::printf("%d clients asking `p` at %.0f Hz each for %.0f s, one server at a time, then all at once...\n",
                settings.clients, settings.rate, settings.seconds);
    std::fflush(stdout);
    std::vector<LoadFigures> loadFigures, togetherFigures;
    for (const Server *s : servers) {
        const std::vector<Load> alone = askFromClients({s}, settings);
        loadFigures.push_back(figures(alone.empty() ? Load{} : alone.front()));
    }
    for (const Load &l : askFromClients(servers, settings))
        togetherFigures.push_back(figures(l));
    togetherFigures.resize(servers.size());

    std::printf("\n%-44s", "");
    for (const Server *s : servers)
        std::printf(" %16s", s->name);
    auto row = [&](const char *what, auto value) {
        std::printf("\n%-44s", what);
        for (size_t i = 0; i < servers.size(); ++i)
            std::printf(" %16s", qPrintable(value(i)));
    };
    std::printf("\nat rest (%.0f s):", settings.seconds);
    row("  wake-ups a second (context switches)", [&](size_t i) { return QString::number(restFigures[i].wakeUps, 'f', 1); });
    row("  CPU, % of one core", [&](size_t i) { return QString::number(restFigures[i].cpuPercent, 'f', 2); });
    row("  RSS, MiB", [&](size_t i) { return QString::number(restFigures[i].rssMiB, 'f', 1); });
    row("  threads", [&](size_t i) { return QString::number(restFigures[i].threads); });
    const auto loadRows = [&](const char *how, const std::vector<LoadFigures> &f) {
        std::printf("\n%d clients x %.0f Hz `p` (%.0f s), %s:", settings.clients, settings.rate, settings.seconds, how);
        row("  answers (refused, not asked: still waiting)", [&](size_t i) {
            const Load &l = f[i].load;
            return QStringLiteral("%1 (%2, %3)").arg(l.answers).arg(l.refused).arg(l.late);
        });
        row("  CPU per answer, us (schedstat)", [&](size_t i) { return QString::number(f[i].microsPerAnswer, 'f', 1); });
        row("  CPU per answer, us (utime+stime)", [&](size_t i) { return QString::number(f[i].ticksMicrosPerAnswer, 'f', 1); });
        row("  slowest answer, ms", [&](size_t i) { return QString::number(f[i].load.worstMs, 'f', 1); });
    };
    loadRows("one server at a time", loadFigures);
    loadRows("all at once", togetherFigures);
    std::printf("\n");
    return 0;
}
