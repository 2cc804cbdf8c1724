#pragma once
// Step 4: RESET with a progress bar, a time limit and a clear verdict from
// GE; the wizard's STOP (or Esc) ends it and stops the rotator. A rotator
// without end stops may skip it.

#include "tuning/homingrun.h"

#include <QWizardPage>

class QCheckBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace slew::ui {

class SetupWizard;

class HomingPage : public QWizardPage {
    Q_OBJECT
public:
    explicit HomingPage(SetupWizard *wizard);
    bool isComplete() const override;
    void initializePage() override;

private:
    void setRunning(bool running);

    SetupWizard *m_wizard;
    tuning::HomingRun m_homing;
    bool m_homed = false;
    QPushButton *m_home;
    QProgressBar *m_progress;
    QLabel *m_result;
    QCheckBox *m_skip;
};

} // namespace slew::ui
