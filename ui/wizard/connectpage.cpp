#include "connectpage.h"

#include "pagebody.h"
#include "setupwizard.h"

#include "protocol/dialect.h"
#include "transport/linkfactory.h"
#include "transport/serialports.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace slew::ui {

ConnectPage::ConnectPage(SetupWizard *wizard) : QWizardPage(wizard), m_wizard(wizard)
{
    setTitle(tr("Connect"));
    setSubTitle(tr("Pick the serial port the controller is on, or type a link (tcp://host:port, sim:). "
                   "Probe tries the common baud rates and reports which one answers."));
    m_ports = new QComboBox(this);
    m_ports->addItem(tr("(type a link below)"));
    for (const auto &port : transport::availableSerialPorts())
        m_ports->addItem(QStringLiteral("%1 — %2").arg(port.location, port.description), port.uri());
    m_uri = new QLineEdit(wizard->profile().uri, this);
    m_uri->setObjectName(QStringLiteral("uri"));
    m_probeButton = new QPushButton(tr("Probe"), this);
    m_probeButton->setObjectName(QStringLiteral("probe"));
    m_progress = new QProgressBar(this);
    m_results = new QListWidget(this);
    m_results->setObjectName(QStringLiteral("baudResults"));
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("connectStatus"));
    m_status->setWordWrap(true);

    auto *form = new QFormLayout;
    form->addRow(tr("Serial port"), m_ports);
    form->addRow(tr("Link"), m_uri);
    auto *layout = new QVBoxLayout(makePageBody(this));
    layout->addLayout(form);
    layout->addWidget(m_probeButton);
    layout->addWidget(m_progress);
    layout->addWidget(m_results);
    layout->addWidget(m_status);

    connect(m_ports, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (i > 0)
            m_uri->setText(m_ports->itemData(i).toString());
    });
    connect(m_uri, &QLineEdit::textChanged, this, [this] {
        m_probe.cancel();
        m_results->clear();
        emit completeChanged();
    });
    connect(m_probeButton, &QPushButton::clicked, this, &ConnectPage::probe);
    connect(&m_probe, &tuning::BaudProbe::progress, this, [this](int percent, const QString &what) {
        m_progress->setValue(percent);
        m_status->setText(what);
    });
    connect(&m_probe, &tuning::BaudProbe::tried, this, [this](const tuning::BaudResult &r) {
        const QString rate = r.baud > 0 ? tr("%1 baud").arg(r.baud) : tr("link");
        m_results->addItem(QStringLiteral("%1 %2: %3").arg(r.answered ? QStringLiteral("✔") : QStringLiteral("✘"), rate, r.detail));
    });
    connect(&m_probe, &tuning::BaudProbe::finished, this, [this](bool any) {
        m_probeButton->setEnabled(true);
        m_status->setText(any ? tr("The controller answers on %1.").arg(m_probe.answeringUri())
                              : tr("Nothing answered. Check the cable, the port and the controller's power."));
        emit completeChanged();
    });
    connect(wizard, &SetupWizard::stopRequested, &m_probe, &tuning::BaudProbe::cancel);
}

void ConnectPage::probe()
{
    m_results->clear();
    // Ask in the dialect the link names (a simulator's URI) or the window is
    // set to: a Micro-2g answers no Easycomm query at any baud rate.
    protocol::Dialect dialect = m_wizard->profile().dialect;
    if (const auto named = protocol::dialectFromName(transport::linkHintsFor(m_uri->text()).dialect))
        dialect = *named;
    if (!m_probe.start(m_uri->text(), dialect)) {
        m_status->setText(m_probe.error());
        return;
    }
    m_probeButton->setEnabled(false);
}

bool ConnectPage::isComplete() const
{
    return !m_probe.isRunning() && !m_probe.answeringUri().isEmpty();
}

bool ConnectPage::validatePage()
{
    m_wizard->profile().uri = m_probe.answeringUri();
    return true;
}

} // namespace slew::ui
