#pragma once
// Step 3: how far the rotator turns (360°, or up to 450° with overlap; stop
// at north or south, as the Micro-2g program sets rotators up), the elevation range,
// and a short jog of each axis that the reading must agree with (a reading
// that runs the wrong way stops the rotator) and the operator confirms
// moved the right way. An azimuth-only controller has no elevation to check.

#include "session/sessiontypes.h"

#include <QWizardPage>

class QCheckBox;
class QComboBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QSpinBox;

namespace slew::ui {

class DirectionCheck;
class SetupWizard;

class MechanicsPage : public QWizardPage {
    Q_OBJECT
public:
    explicit MechanicsPage(SetupWizard *wizard);
    void initializePage() override;
    bool isComplete() const override;
    bool validatePage() override;

private:
    // One axis' jog, what its reading said, and the operator's tick.
    struct AxisRow {
        DirectionCheck *check = nullptr;
        QGroupBox *box = nullptr;
        QPushButton *jog = nullptr;
        QLabel *note = nullptr;
        QCheckBox *confirmed = nullptr;
    };

    AxisRow makeRow(session::Axis axis, const char *jogName, const char *noteName, const char *confirmName);
    AxisRow &rowFor(session::Axis axis);
    bool applyLimits();
    void jog(AxisRow &row);
    void showVerdict(AxisRow &row);
    bool passed(const AxisRow &row) const;
    bool checksElevation() const;

    SetupWizard *m_wizard;
    QSpinBox *m_azRange;
    QRadioButton *m_northStop;
    QRadioButton *m_southStop;
    QComboBox *m_elMax;
    AxisRow m_azimuth;
    AxisRow m_elevation;
    QLabel *m_status;
};

} // namespace slew::ui
