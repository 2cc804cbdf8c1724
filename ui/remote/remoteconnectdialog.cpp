// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/remoteconnectdialog.h"

#include "operatortheme.h"
#include "remote/remoteopener.h"

#include "model/settingsfile.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>

namespace slew::ui {

RemoteConnectDialog::RemoteConnectDialog(QWidget *parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("remoteConnectDialog"));
    setWindowTitle(tr("Open remote station"));
    m_address = new QLineEdit(QSettings().value(QLatin1String(kAddressKey)).toString());
    m_address->setObjectName(QStringLiteral("remoteAddress"));
    m_address->setPlaceholderText(tr("mqtts://USER@HOST:8883/STATION?cafile=/path/ca.pem"));
    m_address->setMinimumWidth(460);
    m_password = new QLineEdit;
    m_password->setObjectName(QStringLiteral("remotePassword"));
    m_password->setEchoMode(QLineEdit::Password);
    m_problem = new QLabel;
    m_problem->setObjectName(QStringLiteral("remoteProblem"));
    m_problem->setTextFormat(Qt::PlainText);
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(warningText());
    auto *note = new QLabel(tr("Without /STATION: every station on the broker (the station network)."));
    note->setWordWrap(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        if (openRemote())
            accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *form = new QFormLayout(this);
    form->addRow(tr("Broker"), m_address);
    form->addRow(QString(), note);
    form->addRow(tr("Password"), m_password);
    form->addRow(m_problem);
    form->addRow(buttons);
}

QString RemoteConnectDialog::problem() const
{
    return m_problem->text();
}

bool RemoteConnectDialog::openRemote()
{
    QString error;
    const auto address = remote::parseBrokerAddress(m_address->text(), &error);
    if (!address) {
        m_problem->setText(error);
        return false;
    }
    if (!openRemoteWindow(*address, m_password->text(), &error)) {
        m_problem->setText(error);
        return false;
    }
    model::saveSetting(QLatin1String(kAddressKey), m_address->text().trimmed());
    return true;
}

} // namespace slew::ui
