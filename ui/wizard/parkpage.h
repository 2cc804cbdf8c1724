#pragma once
// Step 6: where the rotator parks, from the present position or typed in;
// the summary writes it to CW7/CW8.

#include <QWizardPage>

class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace slew::ui {

class SetupWizard;

class ParkPage : public QWizardPage {
    Q_OBJECT
public:
    explicit ParkPage(SetupWizard *wizard);
    void initializePage() override;
    bool validatePage() override;

private:
    SetupWizard *m_wizard;
    QDoubleSpinBox *m_az;
    QDoubleSpinBox *m_el;
    QPushButton *m_useCurrent;
    QLabel *m_status;
};

} // namespace slew::ui
