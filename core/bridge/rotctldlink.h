#pragma once
// `rotctld://host:port`: a link to a running rotctld, so Slew reaches any
// rotator Hamlib drives.
//
// The link only connects. On open it asks `\dump_state` (as Hamlib's own
// client for rotctld does), reports the limits it reads there through
// limitsReported(), and then hands the session the socket itself: the
// session speaks the rotctld dialect (protocol/parser_rotctld.cpp,
// protocol/encoder.cpp) straight to the peer, with nothing in between.
// hints() names that dialect, so a window connecting to a rotctld:// URI
// speaks it without being told.
//
// The handshake is read in a slot connected in the constructor, before any
// reader the session connects to device(): it takes every byte until `done`,
// so the session finds nothing to read until the link has opened.

#include "transport/link.h"

#include <QTcpSocket>
#include <QTimer>

namespace slew::bridge {

class RotctldLink : public transport::Link {
    Q_OBJECT
public:
    static constexpr int kHandshakeTimeoutMs = 5000; // for the answer to \dump_state
    static constexpr qsizetype kMaxHandshakeBytes = 4096;

    RotctldLink(const QString &uri, QString host, quint16 port, QObject *parent = nullptr);

    QIODevice *device() override { return &m_socket; }
    void open() override;
    void close() override;
    bool isOpen() const override { return m_open; }
    transport::LinkHints hints() const override;

    // Registers the `rotctld` scheme with createLink().
    static void registerScheme();

private:
    void onConnected();
    void onSocketError();
    void onHandshakeBytes();
    void finishHandshake();
    void fail(const QString &reason);

    QString m_host;
    quint16 m_port;
    QTcpSocket m_socket;
    QTimer m_handshakeTimer;
    QByteArray m_handshake; // the \dump_state answer read so far
    bool m_open = false;
    bool m_opening = false;
};

} // namespace slew::bridge
