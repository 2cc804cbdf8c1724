#pragma once
// Step 2: which dialect the controller speaks and which optional commands it
// answers; then the wizard's session connects with that dialect.

#include "tuning/dialectidentifier.h"

#include <QWizardPage>

class QLabel;
class QListWidget;
class QProgressBar;

namespace slew::ui {

class SetupWizard;

class IdentifyPage : public QWizardPage {
    Q_OBJECT
public:
    explicit IdentifyPage(SetupWizard *wizard);
    void initializePage() override;
    bool isComplete() const override;

private:
    void onIdentified(bool identified);

    SetupWizard *m_wizard;
    tuning::DialectIdentifier m_identifier;
    QProgressBar *m_progress;
    QListWidget *m_answers;
    QLabel *m_result;
};

} // namespace slew::ui
