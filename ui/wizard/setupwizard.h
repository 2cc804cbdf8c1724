#pragma once
// The setup and tuning wizard: from "plugged in" to "tuned, parked and
// saved". Connect → Identify → Mechanics → Homing → Tuning → Park → Summary,
// with Calibration after Identify for a controller that calibrates by its
// end stops (the Micro-2g program).
// It works on the operator window's session (no second connection to the
// rotator) and builds the profile that the summary writes and saves. A
// window that is already connected keeps its connection: the wizard sets
// that rotator up, and asks before it connects the window anywhere else.
//
// The wizard moves the rotator (jogs, homing, tuning steps) while it covers
// the window, so it carries its own STOP below every page, and Esc presses
// it. Cancel, the one Cancel, stops the rotator too and closes.

#include "model/rotatorprofile.h"

#include <QWizard>

namespace slew::session {
class RotatorSession;
}

namespace slew::ui {

class StopButton;

class SetupWizard : public QWizard {
    Q_OBJECT
public:
    enum PageId {
        ConnectPageId,
        IdentifyPageId,
        MechanicsPageId,
        HomingPageId,
        TuningPageId,
        ParkPageId,
        SummaryPageId,
        CalibrationPageId, // between Identify and Mechanics, where it applies
    };

    explicit SetupWizard(session::RotatorSession *session, QWidget *parent = nullptr);

    session::RotatorSession *session() const { return m_session; }
    // The profile being built; pages fill it in as the operator goes.
    model::RotatorProfile &profile() { return m_profile; }
    const model::RotatorProfile &profile() const { return m_profile; }

    // Whether the wizard goes on with the link the window already had (set
    // by the Connect page): then Identify reads what that connection knows
    // instead of opening the link again.
    bool usesWindowConnection() const { return m_usesWindowConnection; }
    void setUsesWindowConnection(bool uses) { m_usesWindowConnection = uses; }

    // Whether the session has a link or is bringing one up: the window's
    // connection, which the wizard must not replace without asking.
    bool windowHasConnection() const;

    // Cancel or closing: every long action stops, and so does the rotator.
    void reject() override;
    int nextId() const override;

public slots:
    // The wizard's STOP: every long action ends and the rotator stops.
    void stopRotator();

signals:
    void profileSaved(const QString &path);
    void stopRequested(); // pages cancel what they run

protected:
    // Esc is Stop here, as in the window: it stops the rotator and leaves
    // the wizard open, so a stopped jog does not cost the pages filled in.
    void keyPressEvent(QKeyEvent *event) override;

private:
    session::RotatorSession *m_session;
    model::RotatorProfile m_profile;
    StopButton *m_stop;
    bool m_usesWindowConnection = false;
};

} // namespace slew::ui
