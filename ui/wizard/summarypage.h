#pragma once
// Step 7: everything that will be written, by name ("Az I gain", "El
// park"), written (CW) and read back (CR) register by register, and the
// profile saved for the operator window. Finish stays off until every
// register reads back what was written, and a line says so.

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
    bool isComplete() const override;

private:
    QMap<int, QString> plannedWrites() const;
    void write();
    void onWritten(bool allOk);
    void save();
    void setVerified(bool verified, const QString &why);

    SetupWizard *m_wizard;
    tuning::RegisterReadback m_readback;
    QLabel *m_plan;
    QPushButton *m_write;
    QListWidget *m_results;
    QLineEdit *m_path;
    QPushButton *m_save;
    QLabel *m_status;
    QLabel *m_finishNote; // why Finish is off, or that it is on
    bool m_verified = false; // written, and every register read back as written
};

} // namespace slew::ui
