#pragma once
// Step 1: where the rotator is (a serial port, or any link URI) and, for a
// serial port, which baud rate it answers at.
//
// A window that is connected already keeps its connection: Next goes on
// with it, no probe needed. Probing another link would take the port (or
// the window's place) from that connection, so the page asks first, and
// only on a yes stops the rotator and disconnects the window.

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
    // Probe pressed: straight to the probe, or first the question.
    void onProbeClicked();
    void askToDisconnect();
    void disconnectAndProbe();
    void probe();
    // Next goes on with the window's connection: it has one, and the link
    // field still names it.
    bool keepsWindowConnection() const;
    void showWindowConnection();

    SetupWizard *m_wizard;
    tuning::BaudProbe m_probe;
    QString m_answeringUri; // what the last probe found, until the link is edited
    QLabel *m_windowConnection;
    QComboBox *m_ports;
    QLineEdit *m_uri;
    QPushButton *m_probeButton;
    QProgressBar *m_progress;
    QListWidget *m_results;
    QLabel *m_status;
    QWidget *m_question;      // "disconnect the window?", shown while it waits for an answer
    QLabel *m_questionText;
    QPushButton *m_keep;
};

} // namespace slew::ui
