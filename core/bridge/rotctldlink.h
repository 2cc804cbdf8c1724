#pragma once
// `rotctld://host:port`: a link to a running rotctld, so Slew reaches any
// rotator Hamlib drives.
//
// The session speaks Easycomm on every link, so this link translates: the
// session's Easycomm lines become rotctld commands (`AZ EL` -> `p`,
// `AZ10 EL20` -> `P 10 20`, `EL20` alone -> `P <where azimuth is going> 20`, `SA SE` -> `S`, `PARK` -> `K`, `RESET` -> `R 1`,
// `VR`/`MR` -> `M 16 n`, `VE` -> `_`) and the answers come back as Easycomm
// replies. What rotctld cannot give (GS, GE, IP, CR) gets no answer, so the
// session's probe marks it absent. On open it reads `\dump_state` and
// reports the limits; an error code from rotctld becomes a readable notice.

#include "sim/loopbackpipe.h"
#include "protocol/parser.h"
#include "transport/link.h"

#include <QElapsedTimer>
#include <QTcpSocket>
#include <QTimer>

#include <deque>

namespace slew::bridge {

class RotctldLink : public transport::Link {
    Q_OBJECT
public:
    static constexpr int kMaxPending = 32;      // commands waiting for rotctld
    static constexpr int kAnswerTimeoutMs = 3000;

    RotctldLink(const QString &uri, QString host, quint16 port, QObject *parent = nullptr);

    QIODevice *device() override { return m_pipe.hostEnd(); }
    void open() override;
    void close() override;
    bool isOpen() const override { return m_open; }

    // Registers the `rotctld` scheme with createLink().
    static void registerScheme();

private:
    enum class Expect { Position, Status, Info, DumpState };
    struct Pending {
        QByteArray command; // as sent, for messages
        Expect expect;
        qint64 sentAtMs;
    };

    void onConnected();
    void onSocketError();
    void onSocketReadyRead();
    void onHostBytes();
    void translate();
    void send(const QByteArray &command, Expect expect);
    void handleLine(const QByteArray &line);
    void finishDumpState();
    void reply(const QByteArray &easycomm);
    void checkTimeouts();
    void fail(const QString &reason);

    QString m_host;
    quint16 m_port;
    QTcpSocket m_socket;
    sim::LoopbackPipe m_pipe;
    protocol::Parser m_parser{protocol::Dialect::SatNogs};
    QList<protocol::Message> m_line; // the Easycomm line being read from the session
    QByteArray m_socketBuffer;
    std::deque<Pending> m_pending;
    QList<QByteArray> m_answerLines; // lines of the answer being collected
    QTimer m_timeoutTimer;
    QElapsedTimer m_clock;
    bool m_open = false;
    bool m_opening = false;
    // For a one-axis move: where each axis was last sent (NaN after a stop
    // or before any) and last seen.
    double m_sentAz = qQNaN();
    double m_sentEl = qQNaN();
    double m_seenAz = qQNaN();
    double m_seenEl = qQNaN();
};

} // namespace slew::bridge
