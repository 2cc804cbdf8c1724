#pragma once
// Step 1: where the rotator is (a serial port, or any link URI) and, for a
// serial port, which baud rate it answers at.

#include "tuning/baudprobe.h"

#include <QWizardPage>

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;

namespace slew::ui {

class SetupWizard;

class ConnectPage : public QWizardPage {
    Q_OBJECT
public:
    explicit ConnectPage(SetupWizard *wizard);
    bool isComplete() const override;
    bool validatePage() override;

private:
    void probe();

    SetupWizard *m_wizard;
    tuning::BaudProbe m_probe;
    QComboBox *m_ports;
    QLineEdit *m_uri;
    QPushButton *m_probeButton;
    QProgressBar *m_progress;
    QListWidget *m_results;
    QLabel *m_status;
};

} // namespace slew::ui
