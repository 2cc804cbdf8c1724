#pragma once
// The tracker server's panel: turn the rotctld-compatible server on or off,
// where it listens and whom it lets in, who is connected and what they last
// sent, and whether the operator is holding remote control after a Stop.

#include <QTimer>
#include <QWidget>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTreeWidget;

namespace slew::bridge {
class RotctldServer;
}

namespace slew::ui {

class RotctldPanel : public QWidget {
    Q_OBJECT
public:
    explicit RotctldPanel(bridge::RotctldServer *server, QWidget *parent = nullptr);

    // Sets the fields and starts listening (from --rotctld-listen).
    bool startListening(const QString &address, quint16 port);

signals:
    void message(const QString &text); // for the event log

private:
    void apply();
    void keepSettings();    // what the operator set, for the next start
    void restoreSettings(); // at construction
    void refuse(const QString &why);
    void refreshClients();
    void refreshHold(bool held);
    void showListening();

    bridge::RotctldServer *m_server;
    QCheckBox *m_enabled;
    QLineEdit *m_address;
    QSpinBox *m_port;
    QLineEdit *m_allowed;
    QDoubleSpinBox *m_deadband;
    QLabel *m_state;
    QLabel *m_hold;
    QPushButton *m_handBack;
    QTreeWidget *m_clients;
    QTimer m_refresh; // coalesces updates: a chatty tracker must not redraw the list per line
};

} // namespace slew::ui
