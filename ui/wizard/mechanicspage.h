#pragma once
// Step 3: how far the rotator turns (360°, or up to 450° with overlap; stop
// at north or south, as the Micro-2g program sets rotators up), the elevation range,
// and a short jog the operator confirms moved the right way.

#include <QWizardPage>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QSpinBox;

namespace slew::ui {

class SetupWizard;

class MechanicsPage : public QWizardPage {
    Q_OBJECT
public:
    explicit MechanicsPage(SetupWizard *wizard);
    bool isComplete() const override;
    bool validatePage() override;

private:
    bool applyLimits();
    void jog();

    SetupWizard *m_wizard;
    QSpinBox *m_azRange;
    QRadioButton *m_northStop;
    QRadioButton *m_southStop;
    QComboBox *m_elMax;
    QPushButton *m_jog;
    QCheckBox *m_confirmed;
    QLabel *m_status;
};

} // namespace slew::ui
