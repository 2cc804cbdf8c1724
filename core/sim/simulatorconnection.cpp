// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulatorconnection.h"

#include "simulator.h"

#include "protocol/spidcodec.h"

#include <QAbstractSocket>
#include <QIODevice>

#include <algorithm>
#include <cmath>

namespace slew::sim {

namespace {

// A host that sends faster than the paced line carries overruns the UART,
// and one that never reads stops getting answers: both buffers are capped.
constexpr qsizetype kMaxInbound = 64 * 1024;
constexpr qsizetype kMaxOutbound = 256 * 1024;
constexpr qsizetype kReadChunk = 16 * 1024;
// How long a command ended by a space alone waits for the rest of its line.
constexpr double kIdleLineEnd = 0.1;

} // namespace

SimulatorConnection::SimulatorConnection(Simulator &simulator, QIODevice *device,
                                         const ConnectionSettings &settings, QObject *parent)
    : QObject(parent),
      m_simulator(simulator),
      m_device(device),
      m_settings(settings),
      m_firmware(simulator.rotator(), simulator.counters(), settings.dialect),
      m_log(settings.log),
      m_rng(simulator.options().rotator.seed + 7u)
{
    m_openedAt = m_simulator.clock().now();
    m_firmware.setFirmware(simulator.options().firmware);
    if (protocol::isSpid(settings.dialect)) {
        m_firmware.configureSpid({simulator.options().spidPulses, simulator.options().md01Log});
        m_log.endLinesAfter(protocol::spid::kEnd);
    }
    if (settings.dialect == protocol::Dialect::Micro2g) {
        m_simulator.micro2g(); // made now, on this simulator's clock
        m_firmware.serveMicro2g([this](const QString &line) { return m_simulator.handleMicro2g(line); });
    }
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &SimulatorConnection::service);
    connect(&m_simulator, &Simulator::ticked, this, &SimulatorConnection::onTick);
    if (m_settings.unsolicited) {
        m_pushListenerOf = &m_simulator;
        m_simulator.addPushListener();
    }
    connect(&m_simulator, &Simulator::connectionsDropped, this, [this] {
        if (!m_dropped) {
            m_dropped = true;
            emit dropRequested();
        }
    });
    if (m_device) {
        connect(m_device, &QIODevice::readyRead, this, &SimulatorConnection::readDevice);
        if (m_device->bytesAvailable() > 0)
            QMetaObject::invokeMethod(this, &SimulatorConnection::readDevice, Qt::QueuedConnection);
    }
    schedule();
}

SimulatorConnection::~SimulatorConnection()
{
    if (m_pushListenerOf)
        m_pushListenerOf->removePushListener();
}

double SimulatorConnection::byteSeconds() const
{
    return m_settings.baud > 0 ? 10.0 / m_settings.baud : 0.0; // 8N1: ten bit times a byte
}

void SimulatorConnection::readDevice()
{
    if (!m_device)
        return;
    // Read in bounded pieces so a flood cannot starve the event loop; a
    // socket does not signal again for bytes already buffered, so what is
    // left is picked up by a queued call.
    char buffer[kReadChunk];
    for (int round = 0; round < 16 && m_device->bytesAvailable() > 0; ++round) {
        const qint64 n = m_device->read(buffer, sizeof buffer);
        if (n <= 0)
            break;
        receive(QByteArrayView(buffer, n));
    }
    if (m_device && m_device->bytesAvailable() > 0)
        QMetaObject::invokeMethod(this, &SimulatorConnection::readDevice, Qt::QueuedConnection);
}

void SimulatorConnection::receive(QByteArrayView bytes)
{
    if (bytes.isEmpty() || m_dropped)
        return;
    const double perByte = byteSeconds();
    if (perByte <= 0.0) {
        process(bytes, m_simulator.clock().now());
        return;
    }
    // On a paced line the bytes arrive one character time after another.
    if (m_inboundBytes + bytes.size() > kMaxInbound)
        bytes = bytes.first(std::max<qsizetype>(0, kMaxInbound - m_inboundBytes));
    if (bytes.isEmpty())
        return;
    const double now = m_simulator.clock().now();
    m_inboundFreeAt = std::max(now, m_inboundFreeAt) + perByte * double(bytes.size());
    m_inbound.push_back({m_inboundFreeAt, bytes.toByteArray()});
    m_inboundBytes += bytes.size();
    schedule();
}

void SimulatorConnection::process(QByteArrayView bytes, double arrivedAt)
{
    // A half-duplex line still driven by the controller's reply: the host's
    // bytes collide with it and are never heard (RS485, the SatNOGS board).
    if (arrivedAt < m_deafUntil) {
        m_simulator.counters().lostInTurnaround += quint64(bytes.size());
        return;
    }
    m_log.add(bytes);
    m_simulator.syncToNow();
    // An echoing adapter hands the host its own bytes back as they pass,
    // ahead of anything the controller answers.
    if (m_settings.echo)
        send(bytes.toByteArray(), arrivedAt);
    QByteArray out;
    if (m_settings.checksum && !protocol::isSpid(m_settings.dialect)) { // SPID frames carry no checksum
        // A line that does not check is not read at all, and not answered:
        // the controller cannot tell what was meant, so it does nothing.
        m_frames.feed(bytes, [&](protocol::FrameCheck check, QByteArrayView line) {
            if (check == protocol::FrameCheck::Good)
                out += m_firmware.receive(line);
            else
                ++m_simulator.counters().badChecksum;
        });
    } else {
        out = m_firmware.receive(bytes);
    }
    m_simulator.noteInput();
    m_idleFlushAt = m_firmware.awaitingLineEnd() ? m_simulator.clock().now() + kIdleLineEnd : -1.0;
    if (!out.isEmpty())
        answer(std::move(out), arrivedAt);
    schedule();
}

void SimulatorConnection::answer(QByteArray bytes, double at)
{
    send(m_settings.checksum ? protocol::withChecksums(bytes) : std::move(bytes), at);
    // The SatNOGS board lets go of its RS485 pair about 9 ms after the last
    // byte of its reply (docs/protocol.md, "Controllers in the field").
    if (m_firmware.firmware() == Firmware::SatNogs)
        m_deafUntil = std::max(at + m_simulator.linkFaults().latency, m_outboundFreeAt) + kSatnogsTurnaroundS;
}

void SimulatorConnection::corrupt(QByteArray &bytes)
{
    // One bit of one byte a line, never a line end: the damage stays inside
    // the line it hits, as a bit error on a serial line usually does.
    std::uniform_real_distribution<double> chance(0.0, 1.0);
    qsizetype start = 0;
    for (qsizetype i = 0; i <= bytes.size(); ++i) {
        const bool end = i == bytes.size() || bytes[i] == '\r' || bytes[i] == '\n';
        if (!end)
            continue;
        if (i > start && chance(m_rng) < m_simulator.linkFaults().corruptRate) {
            std::uniform_int_distribution<qsizetype> at(start, i - 1);
            char &c = bytes[at(m_rng)];
            c = char(c ^ 0x01);
            if (c == '\r' || c == '\n') // 0x0C and 0x0B flip to line ends: flip another bit
                c = char(c ^ 0x41);
        }
        start = i + 1;
    }
}

void SimulatorConnection::send(QByteArray bytes, double at)
{
    const LinkFaults faults = m_simulator.linkFaults();
    if (faults.corruptRate > 0.0)
        corrupt(bytes);
    if (faults.dropRate > 0.0 || faults.garbageRate > 0.0) {
        std::uniform_real_distribution<double> chance(0.0, 1.0);
        std::uniform_int_distribution<int> anyByte(0, 255);
        QByteArray damaged;
        damaged.reserve(bytes.size());
        for (char c : bytes) {
            if (chance(m_rng) >= faults.dropRate)
                damaged += c;
            if (faults.garbageRate > 0.0 && chance(m_rng) < faults.garbageRate)
                damaged += char(anyByte(m_rng));
        }
        bytes = std::move(damaged);
    }
    if (m_finalOutput) {
        *m_finalOutput += bytes;
        return;
    }
    if (bytes.isEmpty() || !m_device)
        return;

    const double perByte = byteSeconds();
    if (faults.latency <= 0.0 && perByte <= 0.0 && m_outbound.empty()) {
        if (m_device->bytesToWrite() < kMaxOutbound)
            writeToDevice(bytes);
        return;
    }
    if (m_outboundBytes + bytes.size() > kMaxOutbound)
        return;
    // A reply leaves after the latency, once the line is free, and arrives
    // when its last character has crossed.
    m_outboundFreeAt = std::max(at + faults.latency, m_outboundFreeAt) + perByte * double(bytes.size());
    m_outboundBytes += bytes.size();
    m_outbound.push_back({m_outboundFreeAt, std::move(bytes)});
    schedule();
}

void SimulatorConnection::writeToDevice(const QByteArray &bytes)
{
    m_device->write(bytes);
    // On a socket, on its way now: Qt drops what it still holds when it
    // reads the host's end of input.
    if (auto *socket = qobject_cast<QAbstractSocket *>(m_device.data()))
        socket->flush();
}

QByteArray SimulatorConnection::takeFinalOutput(QByteArrayView lastBytes)
{
    if (m_dropped)
        return {};
    QByteArray now;
    m_finalOutput = &now;
    const double at = m_simulator.clock().now();
    while (!m_inbound.empty()) {
        const QByteArray bytes = std::move(m_inbound.front().bytes);
        m_inbound.pop_front();
        process(bytes, at);
    }
    m_inboundBytes = 0;
    if (!lastBytes.isEmpty())
        process(lastBytes, at);
    if (m_firmware.hasUnfinishedLine()) {
        m_simulator.syncToNow();
        answer(m_firmware.endLine(), at);
    }
    m_finalOutput = nullptr;
    // Replies already waiting leave before the ones just made.
    QByteArray out;
    for (const Timed &t : m_outbound)
        out += t.bytes;
    m_outbound.clear();
    m_outboundBytes = 0;
    out += now;
    m_dropped = true;
    m_timer.stop();
    return out;
}

void SimulatorConnection::service()
{
    if (m_dropped)
        return;
    const double now = m_simulator.clock().now();
    const LinkFaults faults = m_simulator.linkFaults();
    if (faults.dropAfter > 0.0 && now - m_openedAt >= faults.dropAfter) {
        m_dropped = true;
        m_inbound.clear();
        m_outbound.clear();
        emit dropRequested();
        return;
    }
    while (!m_inbound.empty() && m_inbound.front().due <= now) {
        const QByteArray bytes = std::move(m_inbound.front().bytes);
        const double arrivedAt = m_inbound.front().due;
        m_inbound.pop_front();
        m_inboundBytes -= bytes.size();
        process(bytes, arrivedAt);
    }
    if (m_idleFlushAt >= 0.0 && m_idleFlushAt <= now) {
        m_idleFlushAt = -1.0;
        m_simulator.syncToNow();
        if (QByteArray out = m_firmware.endLine(); !out.isEmpty())
            answer(std::move(out), now);
    }
    QByteArray ready;
    while (!m_outbound.empty() && m_outbound.front().due <= now) {
        ready += m_outbound.front().bytes;
        m_outboundBytes -= m_outbound.front().bytes.size();
        m_outbound.pop_front();
    }
    if (!ready.isEmpty() && m_device && m_device->bytesToWrite() < kMaxOutbound)
        writeToDevice(ready);
    schedule();
}

void SimulatorConnection::schedule()
{
    double next = -1.0;
    auto consider = [&](double t) {
        if (t >= 0.0 && (next < 0.0 || t < next))
            next = t;
    };
    if (!m_inbound.empty())
        consider(m_inbound.front().due);
    if (!m_outbound.empty())
        consider(m_outbound.front().due);
    consider(m_idleFlushAt);
    const double dropAfter = m_simulator.linkFaults().dropAfter;
    if (dropAfter > 0.0)
        consider(m_openedAt + dropAfter);
    if (next < 0.0 || m_dropped) {
        m_timer.stop();
        return;
    }
    const double wait = next - m_simulator.clock().now();
    if (wait <= 0.0) {
        m_timer.start(0);
    } else if (!m_simulator.clock().isManual()) {
        // wait is simulated time; the timer runs on the wall clock.
        m_timer.start(int(std::ceil(wait * 1000.0 / m_simulator.clock().timeScale())));
    } else {
        m_timer.stop(); // a manual clock releases it from onTick()
    }
}

void SimulatorConnection::onTick()
{
    if (m_dropped)
        return;
    if (m_settings.unsolicited) {
        if (QByteArray out = m_firmware.unsolicitedChanges(); !out.isEmpty())
            answer(std::move(out), m_simulator.clock().now());
    }
    service();
}

} // namespace slew::sim
