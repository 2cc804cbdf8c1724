// Figures for slew-sim: query round trip over TCP loopback (median, p99),
// polls per second over the pseudo-terminal at 19200 baud as a share of what
// the line allows, and the simulator's CPU use while serving 10 Hz polling.
//
//   bench_slewsim [path/to/slew-sim]      (default: the one built beside it)
//
// A benchmark may block: it is a measuring client, not product code.
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QTcpSocket>
#include <QTemporaryDir>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>
#include <vector>

namespace {

QString g_program;

struct Server {
    QProcess process;
    QString readyLine;
    quint16 port = 0;

    bool start(const QStringList &arguments)
    {
        process.start(g_program, arguments);
        if (!process.waitForStarted(5000))
            return false;
        while (!process.canReadLine()) {
            if (!process.waitForReadyRead(5000))
                return false;
        }
        readyLine = QString::fromLocal8Bit(process.readLine()).trimmed();
        const QStringList words = readyLine.split(' ');
        if (const qsizetype tcp = words.indexOf("tcp"); tcp >= 0)
            port = quint16(words[tcp + 1].section(':', -1).toUInt());
        return true;
    }
    ~Server()
    {
        process.terminate();
        process.waitForFinished(5000);
    }
};

// user + system CPU seconds of a process, from /proc.
double cpuSeconds(qint64 pid)
{
    FILE *f = std::fopen(QStringLiteral("/proc/%1/stat").arg(pid).toLocal8Bit().constData(), "r");
    if (!f)
        return -1;
    char buffer[1024];
    const size_t n = std::fread(buffer, 1, sizeof buffer - 1, f);
    std::fclose(f);
    buffer[n] = 0;
    const char *p = std::strrchr(buffer, ')');
    if (!p)
        return -1;
    unsigned long utime = 0, stime = 0;
    // Fields after the command: state(3) ... utime(14) stime(15).
    std::sscanf(p + 2, "%*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %lu %lu", &utime, &stime);
    return double(utime + stime) / double(sysconf(_SC_CLK_TCK));
}

double percentile(std::vector<double> v, double p)
{
    std::sort(v.begin(), v.end());
    const size_t i = std::min(v.size() - 1, size_t(p * double(v.size() - 1) + 0.5));
    return v[i];
}

bool askTcp(QTcpSocket &s, const QByteArray &query)
{
    s.write(query);
    s.flush();
    while (!s.canReadLine()) {
        if (!s.waitForReadyRead(2000))
            return false;
    }
    s.readLine();
    return true;
}

void tcpRoundTrip()
{
    Server server;
    if (!server.start({"--listen", "127.0.0.1:0", "--dialect", "easycomm3"})) {
        std::printf("tcp round trip: slew-sim did not start\n");
        return;
    }
    QTcpSocket s;
    s.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    s.connectToHost(QHostAddress::LocalHost, server.port);
    if (!s.waitForConnected(5000))
        return;
    for (int i = 0; i < 200; ++i)
        askTcp(s, "AZ EL\n"); // warm up
    std::vector<double> micros;
    QElapsedTimer t;
    for (int i = 0; i < 5000; ++i) {
        t.start();
        if (!askTcp(s, "AZ EL\n"))
            break;
        micros.push_back(double(t.nsecsElapsed()) / 1000.0);
    }
    std::printf("tcp loopback round trip of `AZ EL` (%zu queries): median %.0f us, p99 %.0f us\n", micros.size(),
                percentile(micros, 0.5), percentile(micros, 0.99));
}

void ptyPollRate()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("rotator");
    Server server;
    if (!server.start({"--pty", path, "--baud", "19200", "--dialect", "easycomm3"})) {
        std::printf("pty poll rate: slew-sim did not start\n");
        return;
    }
    const int fd = ::open(path.toLocal8Bit().constData(), O_RDWR | O_NOCTTY);
    if (fd < 0)
        return;
    termios tio{};
    tcgetattr(fd, &tio);
    cfmakeraw(&tio);
    tcsetattr(fd, TCSANOW, &tio);
    const QByteArray query = "AZ EL\n";
    const qsizetype replySize = qsizetype(sizeof "AZ0.00 EL0.00\n") - 1;
    int polls = 0;
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < 5000) {
        if (::write(fd, query.constData(), size_t(query.size())) != query.size())
            break;
        qsizetype got = 0;
        char buffer[256];
        bool line = false;
        while (!line) {
            pollfd p{fd, POLLIN, 0};
            if (::poll(&p, 1, 2000) <= 0)
                break;
            const ssize_t n = ::read(fd, buffer, sizeof buffer);
            if (n <= 0)
                break;
            got += n;
            line = std::memchr(buffer, '\n', size_t(n)) != nullptr;
        }
        if (!line)
            break;
        ++polls;
    }
    ::close(fd);
    const double seconds = double(t.nsecsElapsed()) / 1e9;
    const double rate = polls / seconds;
    const double lineLimit = 19200.0 / 10.0 / double(query.size() + replySize); // 8N1, both directions in turn
    std::printf("pty at 19200 baud: %.1f polls/s of `AZ EL`; the line allows %.1f/s (%lld + %lld bytes): %.0f %%\n",
                rate, lineLimit, (long long)query.size(), (long long)replySize, 100.0 * rate / lineLimit);
}

void cpuAtTenHertz()
{
    Server server;
    if (!server.start({"--listen", "127.0.0.1:0", "--dialect", "easycomm3"}))
        return;
    QTcpSocket s;
    s.connectToHost(QHostAddress::LocalHost, server.port);
    if (!s.waitForConnected(5000))
        return;
    const qint64 pid = server.process.processId();
    const double before = cpuSeconds(pid);
    QElapsedTimer t;
    t.start();
    int polls = 0;
    // The session's usual poll: position, status, errors, temperature and speeds.
    while (t.elapsed() < 20000) {
        askTcp(s, "AZ EL\n");
        askTcp(s, "GS\n");
        askTcp(s, "GE\n");
        ++polls;
        const qint64 next = polls * 100;
        if (const qint64 wait = next - t.elapsed(); wait > 0)
            ::usleep(useconds_t(wait * 1000));
    }
    const double used = cpuSeconds(pid) - before;
    const double seconds = double(t.nsecsElapsed()) / 1e9;
    std::printf("slew-sim CPU serving 10 Hz polling (AZ EL, GS, GE) for %.0f s: %.2f %% of one core\n", seconds,
                100.0 * used / seconds);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    g_program = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QStringLiteral(SLEW_SIM_DEFAULT_PATH);
    tcpRoundTrip();
    ptyPollRate();
    cpuAtTenHertz();
    return 0;
}
