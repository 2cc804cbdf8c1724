#include "rotor/rotctldpanel.h"

#include "bridge/rotctldserver.h"
#include "input/finitenumber.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace slew::ui {
namespace {

// Where the operator's server settings are kept (QSettings).
constexpr char kEnabledKey[] = "trackers/enabled";
constexpr char kAddressKey[] = "trackers/address";
constexpr char kPortKey[] = "trackers/port";
constexpr char kAllowedKey[] = "trackers/allowed";
constexpr char kDeadbandKey[] = "trackers/deadband";

} // namespace

RotctldPanel::RotctldPanel(bridge::RotctldServer *server, QWidget *parent) : QWidget(parent), m_server(server)
{
    m_enabled = new QCheckBox(tr("Let trackers steer through Slew (rotctld protocol)"));
    m_enabled->setObjectName("rotctldEnabled");
    m_address = new QLineEdit(QStringLiteral("127.0.0.1"));
    m_address->setObjectName("rotctldAddress");
    m_address->setToolTip(tr("Only this machine can connect unless another address is named."));
    m_port = new QSpinBox;
    m_port->setObjectName("rotctldPort");
    m_port->setRange(0, 65535);
    m_port->setValue(4533);
    m_allowed = new QLineEdit;
    m_allowed->setObjectName("rotctldAllowed");
    m_allowed->setPlaceholderText(tr("any client (or: 192.0.2.7, 192.0.2.8)"));
    m_deadband = new QDoubleSpinBox;
    m_deadband->setObjectName("rotctldDeadband");
    m_deadband->setRange(0.0, 10.0);
    m_deadband->setSingleStep(0.1);
    m_deadband->setSuffix(QStringLiteral("°"));
    m_deadband->setValue(server->deadband());
    m_deadband->setToolTip(tr("A target this close to the one already commanded is not re-sent."));
    m_state = new QLabel(tr("Off"));
    m_state->setObjectName("rotctldState");
    m_hold = new QLabel;
    m_hold->setObjectName("rotctldHold");
    m_handBack = new QPushButton(tr("Hand control back to trackers"));
    m_handBack->setObjectName("rotctldHandBack");
    m_clients = new QTreeWidget;
    m_clients->setObjectName("rotctldClients");
    m_clients->setHeaderLabels({tr("Client"), tr("Last command"), tr("At"), tr("Commands")});
    m_clients->setRootIsDecorated(false);
    m_clients->header()->setSectionResizeMode(QHeaderView::ResizeToContents);

    auto *form = new QFormLayout;
    form->addRow(tr("Address"), m_address);
    form->addRow(tr("Port"), m_port);
    form->addRow(tr("Allowed clients"), m_allowed);
    form->addRow(tr("Deadband"), m_deadband);
    // The hold's text wraps rather than widening the window (it is long, and
    // orange, when it matters), and the button to end it sits under it.
    m_hold->setWordWrap(true);
    auto *holdRow = new QHBoxLayout;
    holdRow->addWidget(m_handBack);
    holdRow->addStretch(1);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_enabled);
    layout->addLayout(form);
    layout->addWidget(m_state);
    layout->addWidget(m_hold);
    layout->addLayout(holdRow);
    layout->addWidget(m_clients, 1);

    connect(m_enabled, &QCheckBox::toggled, this, &RotctldPanel::apply);
    // What the operator sets here is kept for the next start; a server
    // started from the command line (--rotctld-listen) is for that run only.
    connect(m_enabled, &QCheckBox::clicked, this, &RotctldPanel::keepSettings);
    connect(m_deadband, &QDoubleSpinBox::editingFinished, this, &RotctldPanel::keepSettings);
    connect(m_deadband, &QDoubleSpinBox::valueChanged, this, [this](double v) { m_server->setDeadband(v); });
    connect(m_handBack, &QPushButton::clicked, m_server, &bridge::RotctldServer::releaseRemote);
    m_refresh.setSingleShot(true);
    m_refresh.setInterval(250);
    connect(&m_refresh, &QTimer::timeout, this, &RotctldPanel::refreshClients);
    connect(m_server, &bridge::RotctldServer::clientsChanged, &m_refresh, [this] {
        if (!m_refresh.isActive())
            m_refresh.start();
    });
    connect(m_server, &bridge::RotctldServer::commandReceived, &m_refresh, [this] {
        if (!m_refresh.isActive())
            m_refresh.start();
    });
    connect(m_server, &bridge::RotctldServer::remoteHeldChanged, this, &RotctldPanel::refreshHold);
    connect(m_server, &bridge::RotctldServer::logMessage, this, &RotctldPanel::message);
    refreshHold(m_server->isRemoteHeld());
    restoreSettings();
}

void RotctldPanel::keepSettings()
{
    QSettings settings;
    settings.setValue(QLatin1String(kEnabledKey), m_enabled->isChecked());
    settings.setValue(QLatin1String(kAddressKey), m_address->text().trimmed());
    settings.setValue(QLatin1String(kPortKey), m_port->value());
    settings.setValue(QLatin1String(kAllowedKey), m_allowed->text().trimmed());
    settings.setValue(QLatin1String(kDeadbandKey), m_deadband->value());
}

void RotctldPanel::restoreSettings()
{
    const QSettings settings;
    if (const QString address = settings.value(QLatin1String(kAddressKey)).toString(); !address.isEmpty())
        m_address->setText(address);
    bool ok = false;
    if (const int port = settings.value(QLatin1String(kPortKey)).toInt(&ok); ok && port >= 0 && port <= 65535)
        m_port->setValue(port);
    m_allowed->setText(settings.value(QLatin1String(kAllowedKey)).toString());
    if (const std::optional<double> deadband = input::finiteNumber(settings.value(QLatin1String(kDeadbandKey)).toString());
        deadband && *deadband >= m_deadband->minimum() && *deadband <= m_deadband->maximum())
        m_deadband->setValue(*deadband);
    // A server the operator left on is on again (or says why it cannot be).
    if (settings.value(QLatin1String(kEnabledKey)).toBool())
        m_enabled->setChecked(true); // applies
}

bool RotctldPanel::startListening(const QString &address, quint16 port)
{
    m_address->setText(address);
    m_port->setValue(port);
    if (m_enabled->isChecked())
        apply();
    else
        m_enabled->setChecked(true); // applies
    return m_server->isListening();
}

void RotctldPanel::apply()
{
    for (QWidget *w : {static_cast<QWidget *>(m_address), static_cast<QWidget *>(m_port),
                       static_cast<QWidget *>(m_allowed)})
        w->setEnabled(!m_enabled->isChecked());
    if (!m_enabled->isChecked()) {
        m_server->close();
        m_state->setText(tr("Off"));
        return;
    }
    const QHostAddress address(m_address->text().trimmed());
    QList<QHostAddress> allowed;
    for (const QString &a : m_allowed->text().split(u',', Qt::SkipEmptyParts)) {
        const QHostAddress peer(a.trimmed());
        if (peer.isNull())
            return refuse(tr("'%1' is not an address; the server stays off").arg(a.trimmed()));
        allowed.append(peer);
    }
    if (address.isNull())
        return refuse(tr("'%1' is not an address; the server stays off").arg(m_address->text()));
    m_server->setAllowedClients(allowed);
    QString error;
    if (!m_server->listen(address, quint16(m_port->value()), &error))
        return refuse(error);
    showListening();
}

void RotctldPanel::refuse(const QString &why)
{
    // Back to off without going through apply() again, which would replace
    // the reason with a plain "Off".
    const QSignalBlocker quiet(m_enabled);
    m_enabled->setChecked(false);
    for (QWidget *w : {static_cast<QWidget *>(m_address), static_cast<QWidget *>(m_port),
                       static_cast<QWidget *>(m_allowed)})
        w->setEnabled(true);
    m_state->setText(why);
    emit message(why);
}

void RotctldPanel::showListening()
{
    m_state->setText(tr("Listening on %1:%2 — in Gpredict, add a rotator at this host and port")
                         .arg(m_server->address().toString())
                         .arg(m_server->port()));
}

void RotctldPanel::refreshClients()
{
    m_clients->clear();
    for (const auto &c : m_server->clients()) {
        auto *item = new QTreeWidgetItem(m_clients);
        item->setText(0, c.peer);
        item->setText(1, c.lastCommand);
        item->setText(2, c.lastSeen.toLocalTime().toString(QStringLiteral("HH:mm:ss")));
        item->setText(3, QString::number(c.commands));
    }
}

void RotctldPanel::refreshHold(bool held)
{
    m_hold->setText(held ? tr("Operator holds control: remote moves are refused (Stop was pressed)")
                         : tr("Trackers may steer"));
    m_hold->setStyleSheet(held ? QStringLiteral("color: #b35c00; font-weight: bold;") : QString());
    m_handBack->setEnabled(held);
}

} // namespace slew::ui
