// Parser throughput over a few MB of mixed controller traffic, and heap
// allocations per reply in steady state (counted by replacing the global
// operator new in this executable). Prints its figures; not a pass/fail test.
//
// Beside it, in the same run over the same bytes, the least any reader must
// do: split the lines with memchr. The ratio says how much the parser costs
// over that floor whatever the machine's load. Each is timed five times
// and the best run is kept, as the load only ever adds time.
//
//   build/tests/bench/protocol/bench_parser

#include "protocol/parser.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QRandomGenerator>

#include <atomic>
#include <cstring>
#include <limits>
#include <cstdio>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long long> g_allocations{0};
}

void *operator new(std::size_t size)
{
    ++g_allocations;
    if (void *p = std::malloc(size ? size : 1))
        return p;
    throw std::bad_alloc();
}
void operator delete(void *p) noexcept
{
    std::free(p);
}
void operator delete(void *p, std::size_t) noexcept
{
    std::free(p);
}

static QByteArray traffic(qsizetype bytes)
{
    // What a polled Easycomm III derivative controller sends back, plus SatNOGS forms,
    // Easycomm I lines and a little garbage.
    static const char *lines[] = {
        "AZ123.45 EL45.67\n", "AZ10.0\nEL20.0\n", "GS1030\n",       "GE1\n",
        "IP0,25.31\n",         "IP7,-1.50\n",      "CR10,123.45\n",  "1,0.80\n",
        "\\?ENC123450,45000,-5,0\r\n", "VESatNOGS-v2.2\r\n",
        "AZ123.1 EL123.1 UP1231231231 LSB DN1231231231 USB\n", "XY12 ;junk\n",
    };
    QRandomGenerator random(1);
    QByteArray out;
    out.reserve(bytes + 64);
    while (out.size() < bytes)
        out += lines[random.bounded(int(std::size(lines)))];
    return out;
}

// The floor: every line found, nothing read in it.
static long long splitLines(const QByteArray &data)
{
    long long lines = 0;
    const char *at = data.constData();
    const char *end = at + data.size();
    while (at < end) {
        const void *newline = std::memchr(at, '\n', size_t(end - at));
        if (!newline)
            break;
        ++lines;
        at = static_cast<const char *>(newline) + 1;
    }
    return lines;
}

int main()
{
    const QByteArray data = traffic(8 * 1024 * 1024);
    constexpr int kRuns = 5;
    long long replies = 0;
    double checksum = 0;
    auto sink = [&](const slew::protocol::Message &m) {
        ++replies;
        checksum += m.value;
    };

    qint64 bestNs = std::numeric_limits<qint64>::max();
    long long allocations = 0;
    for (int run = 0; run < kRuns; ++run) {
        slew::protocol::Parser parser(slew::protocol::Dialect::SatNogs);
        parser.feed(QByteArrayView(data).first(64 * 1024), sink); // warm up
        replies = 0;
        // Fed in 256-byte chunks, as reads from a socket or serial port arrive.
        const long long allocationsBefore = g_allocations.load();
        QElapsedTimer timer;
        timer.start();
        for (qsizetype at = 0; at < data.size(); at += 256)
            parser.feed(QByteArrayView(data).sliced(at, std::min<qsizetype>(256, data.size() - at)), sink);
        bestNs = std::min(bestNs, timer.nsecsElapsed());
        allocations = std::max(allocations, g_allocations.load() - allocationsBefore);
    }

    qint64 splitNs = std::numeric_limits<qint64>::max();
    long long lines = 0;
    for (int run = 0; run < kRuns; ++run) {
        QElapsedTimer timer;
        timer.start();
        lines = splitLines(data);
        splitNs = std::min(splitNs, timer.nsecsElapsed());
    }

    const double mb = double(data.size()) / (1024.0 * 1024.0);
    const double parserRate = mb / (double(bestNs) / 1e9);
    const double splitRate = mb / (double(std::max<qint64>(splitNs, 1)) / 1e9);
    std::printf("parser: %.1f MiB of mixed traffic, %lld replies (best of %d runs)\n", mb, replies, kRuns);
    std::printf("parser: throughput %.1f MiB/s, %.0f ns per reply\n", parserRate, double(bestNs) / double(replies));
    std::printf("memchr line splitter, same bytes: %.1f MiB/s (%lld lines); the parser is %.1fx slower\n", splitRate,
                lines, splitRate / parserRate);
    std::printf("parser: heap allocations in steady state: %lld (%.4f per reply)\n", allocations,
                double(allocations) / double(replies));
    std::printf("(checksum %.1f)\n", checksum);
    return 0;
}
