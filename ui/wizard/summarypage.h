#pragma once
// Step 7: everything that will be written, written (CW) and read back (CR)
// register by register, and the profile saved for the operator window.

#include "tuning/registerreadback.h"

#include <QWizardPage>

class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace slew::ui {

class SetupWizard;

class SummaryPage : public QWizardPage {
    Q_OBJECT
public:
    explicit SummaryPage(SetupWizard *wizard);
    void initializePage() override;

private:
    QMap<int, QString> plannedWrites() const;
    void write();
    void save();

    SetupWizard *m_wizard;
    tuning::RegisterReadback m_readback;
    QLabel *m_plan;
    QPushButton *m_write;
    QListWidget *m_results;
    QLineEdit *m_path;
    QPushButton *m_save;
    QLabel *m_status;
};

} // namespace slew::ui
