// SPDX-License-Identifier: GPL-3.0-or-later
// SPID reader throughput on binary frames (12-byte replies with MD-01 text
// lines and a little garbage among them), through spid::Parser alone and
// through the message Parser, and what a serial line lets a host poll: a
// poll is a 13-byte status request and its 12-byte reply (Rot1Prog: 5), ten
// bit times a byte at 8N1. Prints its figures; not a pass/fail test.
//
//   build/tests/bench/protocol/bench_spidparser

#include "model/rotatorprofile.h"
#include "protocol/parser.h"
#include "protocol/spidcodec.h"
#include "protocol/spidparser.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QRandomGenerator>

#include <cstdio>

using namespace slew::protocol;

namespace {

QByteArray traffic(qsizetype bytes)
{
    QRandomGenerator random(14);
    QByteArray out;
    out.reserve(bytes + 64);
    while (out.size() < bytes) {
        const int pick = random.bounded(100);
        if (pick == 0)
            out += "Warning: limit switch W\r\n"; // an MD-01 log line
        else if (pick == 1)
            out += "\xFF\x57\x03"; // garbage with a false start
        else
            out += spid::encodeReply(random.bounded(-1800, 5400) / 10.0, random.bounded(-200, 2100) / 10.0,
                                     Dialect::Md01, 2, 2);
    }
    return out;
}

// Feeds data in 256-byte chunks, as reads from a serial port arrive;
// returns the nanoseconds taken.
template <typename Reader, typename Sink>
qint64 timeFeeding(Reader &reader, const QByteArray &data, Sink &&sink)
{
    reader.feed(QByteArrayView(data).first(64 * 1024), sink); // warm up
    QElapsedTimer timer;
    timer.start();
    for (qsizetype at = 0; at < data.size(); at += 256)
        reader.feed(QByteArrayView(data).sliced(at, std::min<qsizetype>(256, data.size() - at)), sink);
    return timer.nsecsElapsed();
}

void printLine(int baud, int requestBytes, int replyBytes, const char *what)
{
    const double pollsPerSecond = baud / (10.0 * (requestBytes + replyBytes));
    const int pollHz = slew::model::RotatorProfile{}.pollHz;
    std::printf("line: %s at %d baud carries %.2f polls/s (%d + %d bytes); the profile's default %d Hz would need "
                "%.0f%% of it\n",
                what, baud, pollsPerSecond, requestBytes, replyBytes, pollHz, 100.0 * pollHz / pollsPerSecond);
}

} // namespace

int main()
{
    const QByteArray data = traffic(8 * 1024 * 1024);
    const double mb = double(data.size()) / (1024.0 * 1024.0);

    spid::Parser frames(Dialect::Md01);
    long long replies = 0;
    double checksum = 0;
    const qint64 frameNs = timeFeeding(frames, data, [&](const spid::Frame &f) {
        replies += f.kind == spid::Frame::Kind::Reply;
        checksum += f.azimuth;
    });
    std::printf("spid::Parser: %.1f MiB, %lld replies: %.1f MiB/s, %.0f ns per reply\n", mb, replies,
                mb / (frameNs / 1e9), double(frameNs) / double(replies));

    Parser messages(Dialect::Md01);
    long long positions = 0;
    const qint64 messageNs = timeFeeding(messages, data, [&](const Message &m) {
        positions += m.op == Op::Azimuth;
        checksum += m.value;
    });
    std::printf("Parser (messages): %.1f MiB/s, %.0f ns per reply\n", mb / (messageNs / 1e9),
                double(messageNs) / double(positions));

    printLine(600, spid::kCommandSize, spid::kReplySize, "Rot2Prog");
    printLine(1200, spid::kCommandSize, spid::kRot1ReplySize, "Rot1Prog");
    printLine(9600, spid::kCommandSize, spid::kReplySize, "MD-01/02");
    const double pollsAt600 = 600.0 / (10.0 * (spid::kCommandSize + spid::kReplySize));
    std::printf("cpu: reading the replies of %.2f polls/s takes %.5f%% of one core\n", pollsAt600,
                100.0 * pollsAt600 * double(frameNs) / double(replies) / 1e9);
    std::printf("(checksum %.1f)\n", checksum);
    return 0;
}
