// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// File → Open remote station…: the broker's address (with /NAME for one
// station, without for the station network) and the account's password,
// checked as `slew --remote` checks them; a fault is said under the field
// and nothing opens. The password is not kept; the address is.

#include "remote/brokeraddress.h"

#include <QDialog>

class QLabel;
class QLineEdit;

namespace slew::ui {

class RemoteConnectDialog : public QDialog {
    Q_OBJECT
public:
    static constexpr char kAddressKey[] = "remote/lastAddress";

    explicit RemoteConnectDialog(QWidget *parent = nullptr);

    // Opens the window the fields name; false, with the reason shown, if
    // they cannot be used.
    bool openRemote();

    QLineEdit *addressField() const { return m_address; }
    QLineEdit *passwordField() const { return m_password; }
    QString problem() const;

private:
    QLineEdit *m_address;
    QLineEdit *m_password;
    QLabel *m_problem;
};

} // namespace slew::ui
