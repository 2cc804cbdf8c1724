// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The radio behind the rotator controller: a station controller that drives
// the radios itself takes Doppler-corrected frequencies on the rotator's own
// link, as the Easycomm tables' station commands (`DN` receive, `UP`
// transmit, `DM`/`UM` modes; session/controllerradiocommands.h).
// URI: `controller`.
//
// It goes through the rotator session's queue, so a frequency never delays
// a poll's answer or a stop, and through a CommandPacer like every radio
// link, so only the newest frequency waits. The controller's answers to
// UP/DN say what it was told, not what the radio's dial shows, so the dial
// is not followed on this path (canReadBack() is false); readings still
// check what the controller holds, where the dialect answers them
// (Easycomm II and later; Easycomm I takes settings blind).
//
// A setting is checked before it is queued: against the limits every radio
// link keeps (radiolimits.h), refused in the same words as the others, and
// then against what the controller's line carries (ten digits of hertz, a
// mode of eight letters or digits), so a value no controller can take is
// refused in words when it is given, never dropped on the way.

#include "commandpacer.h"
#include "radiolink.h"

#include <QElapsedTimer>
#include <QTimer>

#include <optional>

namespace slew::session {
class RotatorSession;
}

namespace slew::radio {

class ControllerRadioLink : public RadioLink {
    Q_OBJECT
public:
    // The session must outlive this.
    explicit ControllerRadioLink(session::RotatorSession *session, QObject *parent = nullptr);

    void open() override;
    void close() override;
    State state() const override { return m_state; }
    QString uri() const override { return QStringLiteral("controller"); }
    void setReceiveHz(double hz) override;
    void setTransmitHz(double hz) override;
    void setSplit(bool) override {} // the controller has a line for each path already
    void setMode(const QString &mode, int passbandHz) override;         // DM
    void setTransmitMode(const QString &mode, int passbandHz) override; // UM
    void readFrequencies() override;
    bool canReadBack() const override;
    int latencyMs() const override { return m_latencyMs; }
    void setMinimumIntervalMs(int ms) override { m_pacer.setMinimumIntervalMs(ms); }
    void dropWaiting() override { m_pacer.dropWaiting(); }

    // For tests and the traffic view: what the pacer holds.
    const CommandPacer &pacer() const { return m_pacer; }

private:
    void setState(State state, const QString &detail);
    void setFrequency(CommandKind kind, const QString &line, double hz);
    void setPathMode(CommandKind kind, const QString &line, const QString &mode, int passbandHz);
    void submit(const PacedCommand &command);
    void send(const PacedCommand &command);
    void onReported(int path, double hz);
    void finishRead(bool ok, const QString &why);

    session::RotatorSession *m_session;
    CommandPacer m_pacer;
    State m_state = State::Closed;
    // A read on its way: what has come back of it, and since when.
    RadioFrequencies m_reading;
    bool m_readInFlight = false;
    QElapsedTimer m_readSince;
    QTimer m_readTimeout;
    int m_latencyMs = 0;
};

} // namespace slew::radio
