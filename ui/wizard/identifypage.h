#pragma once
// Step 2: which dialect the controller speaks and which optional commands it
// answers; then the wizard's session connects with that dialect.
// On the window's own connection nothing is opened again (a serial port
// would be busy, and a `sim:` link would start another simulator): the page
// shows the dialect the window speaks and what its probe found.

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
    void showWindowConnection();

    SetupWizard *m_wizard;
    tuning::DialectIdentifier m_identifier;
    QProgressBar *m_progress;
    QListWidget *m_answers;
    QLabel *m_result;
};

} // namespace slew::ui
