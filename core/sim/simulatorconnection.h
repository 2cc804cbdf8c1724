// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One host's connection to the simulator, over any QIODevice (a TCP socket,
// the in-process pipe, the pseudo-terminal). It feeds the firmware, and puts
// the line between them: serial pacing at a baud rate, reply latency, lost
// and garbage bytes, pushes of changed fields, and cutting the connection.
//
// Everything happens from the event loop and on the simulator's clock, so on
// a manual clock a delayed reply leaves exactly when a test advances past it.

#include "receivedlog.h"
#include "simulatorfirmware.h"

#include "protocol/checksum.h"
#include "protocol/dialect.h"

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <deque>
#include <random>

class QIODevice;

namespace slew::sim {

class Simulator;

struct ConnectionSettings {
    protocol::Dialect dialect = protocol::Dialect::Easycomm3;
    bool unsolicited = false;
    bool echo = false;            // every received byte goes back first (an echoing adapter)
    bool checksum = false;        // lines framed `*HH` both ways; bad frames refused unread
    int baud = 0;                 // 0: unpaced
    ReceivedLog *log = nullptr;   // optional record of received lines
};

class SimulatorConnection : public QObject {
    Q_OBJECT
public:
    SimulatorConnection(Simulator &simulator, QIODevice *device, const ConnectionSettings &settings,
                        QObject *parent = nullptr);
    ~SimulatorConnection() override;

    SimulatorFirmware &firmware() { return m_firmware; }
    QIODevice *device() const { return m_device; }

    // Takes bytes the host sent (endpoints whose device does not signal
    // readyRead call this themselves).
    void receive(QByteArrayView bytes);

    // The host sends nothing more (it shut down its side, and the socket is
    // about to close): `lastBytes` and any input still on the paced line are
    // handled now, an unterminated last line is ended, and every reply not
    // yet written is returned at once, latency and pacing notwithstanding,
    // rather than lost. Nothing is sent on the device after this.
    QByteArray takeFinalOutput(QByteArrayView lastBytes = {});

    // Bytes waiting to leave (pacing, latency); tests and benchmarks look.
    qsizetype pendingOutput() const { return m_outboundBytes; }

signals:
    // The line went away (fault or drop_after): the endpoint closes the device.
    void dropRequested();

private:
    struct Timed {
        double due;
        QByteArray bytes;
    };

    void readDevice();
    // `at` is when the bytes arrived or the reply was made, which on a
    // manual clock can be earlier than the tick that handles them.
    void process(QByteArrayView bytes, double arrivedAt);
    void send(QByteArray bytes, double at);
    void answer(QByteArray bytes, double at); // the firmware's words: framed, then sent
    void corrupt(QByteArray &bytes);
    void service();
    void schedule();
    void onTick();
    double byteSeconds() const;
    void writeToDevice(const QByteArray &bytes);

    Simulator &m_simulator;
    QPointer<QIODevice> m_device;
    ConnectionSettings m_settings;
    SimulatorFirmware m_firmware;
    LineCollector m_log;
    protocol::ChecksumReader m_frames; // checksum=1: received lines are checked here first
    std::mt19937 m_rng;

    std::deque<Timed> m_inbound;
    std::deque<Timed> m_outbound;
    qsizetype m_inboundBytes = 0;
    qsizetype m_outboundBytes = 0;
    double m_inboundFreeAt = 0.0;  // the paced line is busy until then
    double m_outboundFreeAt = 0.0;
    double m_idleFlushAt = -1.0;
    double m_deafUntil = -1.0; // a half-duplex line hears nothing before then
    static constexpr double kSatnogsTurnaroundS = 0.009;
    double m_openedAt = 0.0;
    bool m_dropped = false;
    QByteArray *m_finalOutput = nullptr; // set while takeFinalOutput() collects
    QPointer<Simulator> m_pushListenerOf; // unsolicited: counted there until this goes
    QTimer m_timer;
};

} // namespace slew::sim
