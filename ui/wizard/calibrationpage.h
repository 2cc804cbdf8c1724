// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Step 3 for a controller that calibrates by its end stops (the Micro-2g
// program, docs/protocol.md "Micro-2g"): the operator turns the rotor to its
// left stop and enters the bearing there, does the same at the right stop,
// sets the degrees of travel, and the page reads back with `Z` what the
// controller now holds, flagging whatever differs from what was sent.
//
// The rotor is turned with the switch on its own control box: until it is
// calibrated, a go-to aims with the very calibration being replaced.

#include "protocol/micro2glistings.h"
#include "session/micro2gcalibration.h"
#include "session/rotatorsession.h"

#include <QList>
#include <QWizardPage>

#include <optional>

class QCheckBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace slew::ui {

class SetupWizard;

class CalibrationPage : public QWizardPage {
    Q_OBJECT
public:
    explicit CalibrationPage(SetupWizard *wizard);
    void initializePage() override;
    bool isComplete() const override;

    // Whether this page applies to the wizard's dialect.
    static bool appliesTo(const SetupWizard *wizard);
    // The rotor being calibrated: the link's, or 1 when it names none.
    int rotor() const { return m_rotor; }
    // Consecutive A/D readings within a count of each other that mean the
    // rotor is at rest (two seconds of polls).
    int readingsForRest() const;

private:
    // What the page sent, to compare with what the controller reads back.
    struct Sent {
        std::optional<int> leftAdc, leftBearing, rightAdc, rightBearing, degreeRange;
    };

    bool isActive() const;
    void onPosition();
    void onReading(int rotor, int counts);
    void onCalibration(int rotor, const protocol::Micro2gCalibration &held);
    void onRefused(int rotor, const QString &reason);
    void send(session::Micro2gCalibration::Point point, int value);
    bool atRest() const;
    void updateControls();
    QString describeHeld() const;
    bool differsFromSent() const; // something sent is not what the controller holds
    void setStatus(const QString &text, bool problem);

    SetupWizard *m_wizard;
    int m_rotor = 1;
    QList<int> m_recent; // the latest A/D readings, newest last
    Sent m_sent;
    Sent m_before; // m_sent before the request that is out, should it be refused
    std::optional<protocol::Micro2gCalibration> m_held;
    bool m_waiting = false; // a calibration request is out, not yet answered
    QString m_alarm;        // what the controller last refused, while waiting
    QLabel *m_rotorNote;
    QLabel *m_reading;
    QLabel *m_heading;
    QSpinBox *m_leftBearing;
    QPushButton *m_setLeft;
    QSpinBox *m_rightBearing;
    QPushButton *m_setRight;
    QSpinBox *m_range;
    QPushButton *m_setRange;
    QPushButton *m_readBack;
    QLabel *m_heldText;
    QLabel *m_status;
    QCheckBox *m_skip;
};

} // namespace slew::ui
