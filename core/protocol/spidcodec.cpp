// SPDX-License-Identifier: GPL-3.0-or-later
#include "spidcodec.h"

#include <algorithm>
#include <cmath>

namespace slew::protocol::spid {

namespace {

// A frame of the three requests that carry no argument: status and stop
// zero every byte between the start and K, as Hamlib does.
QByteArray bareFrame(Command k)
{
    QByteArray frame(kCommandSize, '\0');
    frame[0] = kStart;
    frame[11] = char(k);
    frame[12] = kEnd;
    return frame;
}

// value as `count` digits, most significant first, each digit plus `zero`
// (0x30 for a command's ASCII, 0 for a reply's raw values).
void putDigits(QByteArray &frame, int at, long long value, int count, char zero)
{
    for (int i = count - 1; i >= 0; --i) {
        frame[at + i] = char(zero + value % 10);
        value /= 10;
    }
}

// The largest value `count` decimal digits hold.
long long maxDigits(int count)
{
    long long m = 1;
    for (int i = 0; i < count; ++i)
        m *= 10;
    return m - 1;
}

long long fitDigits(double v, int count)
{
    if (!std::isfinite(v))
        return 0;
    return std::clamp(std::llround(v), 0LL, maxDigits(count));
}

} // namespace

bool isResolution(int pulsesPerDegree)
{
    return pulsesPerDegree == 1 || pulsesPerDegree == 2 || pulsesPerDegree == 4 || pulsesPerDegree == 10;
}

const char *positionRefusal(double azimuth, double elevation, Dialect d)
{
    if (!std::isfinite(azimuth))
        return "azimuth is not a number";
    if (azimuth < kMinAzimuth || azimuth > kMaxAzimuth)
        return "azimuth outside -180..540, the SPID range";
    if (d == Dialect::Rot1Prog)
        return nullptr; // azimuth only: the elevation is not sent
    if (!std::isfinite(elevation))
        return "elevation is not a number";
    if (elevation < kMinElevation || elevation > kMaxElevation)
        return "elevation outside -20..210, the SPID range";
    return nullptr;
}

Encoded encodeSet(double azimuth, double elevation, Dialect d, int azimuthPulses, int elevationPulses)
{
    if (!isSpid(d))
        return {{}, "not a SPID dialect"};
    if (const char *why = positionRefusal(azimuth, elevation, d))
        return {{}, why};
    QByteArray frame = bareFrame(Command::Set);
    if (d == Dialect::Rot1Prog) {
        putDigits(frame, 1, fitDigits(360.0 + azimuth, 3), 3, '0');
        frame[4] = '0';
        return {frame, nullptr};
    }
    if (!isResolution(azimuthPulses) || !isResolution(elevationPulses))
        return {{}, "pulses per degree must be 1, 2, 4 or 10"};
    putDigits(frame, 1, fitDigits(azimuthPulses * (360.0 + azimuth), 4), 4, '0');
    frame[5] = char(azimuthPulses);
    putDigits(frame, 6, fitDigits(elevationPulses * (360.0 + elevation), 4), 4, '0');
    frame[10] = char(elevationPulses);
    return {frame, nullptr};
}

QByteArray encodeStatus()
{
    return bareFrame(Command::Status);
}

QByteArray encodeStop()
{
    return bareFrame(Command::Stop);
}

Encoded encodeMove(int directions, Dialect d)
{
    if (d != Dialect::Md01)
        return {{}, "only the MD-01/02 have a move command"};
    const bool leftAndRight = (directions & MoveBit::Left) && (directions & MoveBit::Right);
    const bool upAndDown = (directions & MoveBit::Up) && (directions & MoveBit::Down);
    if (directions <= 0 || directions > 0x0F || leftAndRight || upAndDown)
        return {{}, "a move names at most one direction per axis"};
    QByteArray frame = bareFrame(Command::Move);
    frame[1] = char(directions);
    return {frame, nullptr};
}

QByteArray encodeReply(double azimuth, double elevation, Dialect d, int azimuthPulses, int elevationPulses)
{
    if (d == Dialect::Rot1Prog) {
        QByteArray frame(kRot1ReplySize, '\0');
        frame[0] = kStart;
        putDigits(frame, 1, fitDigits(360.0 + azimuth, 3), 3, '\0');
        frame[4] = kEnd;
        return frame;
    }
    QByteArray frame(kReplySize, '\0');
    frame[0] = kStart;
    putDigits(frame, 1, fitDigits(10.0 * (360.0 + azimuth), 4), 4, '\0');
    frame[5] = char(azimuthPulses);
    putDigits(frame, 6, fitDigits(10.0 * (360.0 + elevation), 4), 4, '\0');
    frame[10] = char(elevationPulses);
    frame[11] = kEnd;
    return frame;
}

int replySize(Dialect d)
{
    return d == Dialect::Rot1Prog ? kRot1ReplySize : kReplySize;
}

} // namespace slew::protocol::spid
