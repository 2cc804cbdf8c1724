// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Single exchanges with a running rigctld over TCP, for the rigctld radio
// link (rigctldradio.h, which says what is sent for each command).
//
// Opening: connect (within limits::kConnectTimeoutMs), then ask
// `+\chk_vfo` (answered within limits::kReplyTimeoutMs): whether rigctld
// runs in VFO mode, where every command names its VFO. Main/Sub without
// VFO mode is lost at once, saying to start rigctld with -o.
//
// Each command goes out as one line in the extended form and its answer is
// read a line at a time (rigctldreply.h); the first answer shows which
// form the peer keeps to. An answer that fits no form, a line past
// kMaxLineBytes, words nobody asked for, or a lost connection cannot be
// matched to commands any more: the radio is lost, with the reason.

#include "exchangeperformer.h"
#include "rigctldreply.h"

#include <QTcpSocket>
#include <QTimer>

#include <memory>

namespace slew::radio {

class RigctldPerformer : public ExchangePerformer {
    Q_OBJECT
public:
    static constexpr qsizetype kMaxLineBytes = 256;

    RigctldPerformer(QString host, quint16 port, QObject *parent = nullptr);
    ~RigctldPerformer() override;

    QString reaching() const override;
    void open(VfoLayout layout) override;
    void perform(const RadioCommand &command) override;
    void close() override;
    void abort() override;
    QString text(const RadioCommand &command) const override;
    // Asked only of a peer that answers in the extended form: the default
    // form's two bare lines could not be told from a stray one.
    bool canReadSplit() const override { return m_peerForm == RigctldReply::Form::Extended; }
    QString peerName() const override { return QStringLiteral("rigctld"); }

    QString host() const { return m_host; }
    quint16 port() const { return m_port; }
    // rigctld was started in VFO mode (-o): every command names its VFO.
    bool inVfoMode() const { return m_vfoMode; }

private:
    enum class Phase { Idle, Connecting, AskingVfoMode, Ready };

    // A command line: `+F 145800000`, or in VFO mode `+F VFOA 145800000`
    // (`+F Sub 145800000` for the receive path with Main/Sub).
    QString line(const char *verb, RadioPath path, const QString &arguments = {}) const;
    RigctldReply replyFor(const RadioCommand &command) const;
    void onConnected();
    void onSocketError();
    void onReadyRead();
    void onDeadline();
    void takeLine(QByteArrayView line);
    // The answer to \chk_vfo: one line of its own, in no form of RigctldReply's.
    void takeVfoModeAnswer(QByteArrayView line);
    void lose(const QString &reason);

    QString m_host;
    quint16 m_port;
    QTcpSocket m_socket;
    QTimer m_deadline; // the opening's: the connection, then \chk_vfo's answer
    Phase m_phase = Phase::Idle;
    VfoLayout m_layout = VfoLayout::Split;
    bool m_vfoMode = false;
    std::unique_ptr<RigctldReply> m_reply; // the answer being read, while a command is out
    RigctldReply::Form m_peerForm = RigctldReply::Form::Either; // as its first answer showed
};

} // namespace slew::radio
