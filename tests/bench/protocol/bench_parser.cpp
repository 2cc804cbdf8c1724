// Parser throughput over a few MB of mixed controller traffic, and heap
// allocations per reply in steady state (counted by replacing the global
// operator new in this executable). Prints its figures; not a pass/fail test.
//
//   build/tests/bench/protocol/bench_parser

#include "protocol/parser.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QRandomGenerator>

#include <atomic>
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

int main()
{
    const QByteArray data = traffic(8 * 1024 * 1024);
    slew::protocol::Parser parser(slew::protocol::Dialect::SatNogs);
    long long replies = 0;
    double checksum = 0;
    auto sink = [&](const slew::protocol::Message &m) {
        ++replies;
        checksum += m.value;
    };

    parser.feed(QByteArrayView(data).first(64 * 1024), sink); // warm up
    replies = 0;

    // Fed in 256-byte chunks, as reads from a socket or serial port arrive.
    const long long allocationsBefore = g_allocations.load();
    QElapsedTimer timer;
    timer.start();
    for (qsizetype at = 0; at < data.size(); at += 256)
        parser.feed(QByteArrayView(data).sliced(at, std::min<qsizetype>(256, data.size() - at)), sink);
    const qint64 ns = timer.nsecsElapsed();
    const long long allocations = g_allocations.load() - allocationsBefore;

    const double mb = double(data.size()) / (1024.0 * 1024.0);
    const double seconds = double(ns) / 1e9;
    std::printf("parser: %.1f MiB of mixed traffic, %lld replies\n", mb, replies);
    std::printf("parser: throughput %.1f MiB/s, %.0f ns per reply\n", mb / seconds, double(ns) / double(replies));
    std::printf("parser: heap allocations in steady state: %lld (%.4f per reply)\n", allocations,
                double(allocations) / double(replies));
    std::printf("(checksum %.1f)\n", checksum);
    return 0;
}
