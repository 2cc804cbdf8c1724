#include "wizard/connectpage.h"

#include "wizard/pagebody.h"
#include "wizard/setupwizard.h"

#include "protocol/dialect.h"
#include "session/connectionplan.h"
#include "session/rotatorsession.h"
#include "session/stopbeforeexit.h"
#include "transport/serialports.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QHBoxLayout>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace slew::ui {

using session::RotatorSession;

ConnectPage::ConnectPage(SetupWizard *wizard) : QWizardPage(wizard), m_wizard(wizard)
{
    setTitle(tr("Connect"));
    setSubTitle(tr("Pick the serial port the controller is on, or type a link (tcp://host:port, sim:). "
                   "Probe tries the common baud rates and reports which one answers."));
    m_windowConnection = new QLabel(this);
    m_windowConnection->setObjectName(QStringLiteral("windowConnection"));
    m_windowConnection->setWordWrap(true);
    m_windowConnection->setTextFormat(Qt::PlainText);
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

    // The question a probe asks first while the window is connected: on the
    // page, not in a dialog of its own, so nothing covers the wizard's STOP.
    m_question = new QWidget(this);
    m_question->setObjectName(QStringLiteral("disconnectQuestion"));
    m_questionText = new QLabel(m_question);
    m_questionText->setWordWrap(true);
    m_questionText->setTextFormat(Qt::PlainText);
    QFont bold = m_questionText->font();
    bold.setBold(true);
    m_questionText->setFont(bold);
    auto *disconnectButton = new QPushButton(tr("Disconnect and probe"), m_question);
    disconnectButton->setObjectName(QStringLiteral("disconnectAndProbe"));
    m_keep = new QPushButton(tr("Keep the connection"), m_question);
    m_keep->setObjectName(QStringLiteral("keepConnection"));
    auto *answers = new QHBoxLayout;
    answers->addWidget(disconnectButton);
    answers->addWidget(m_keep);
    answers->addStretch(1);
    auto *questionLayout = new QVBoxLayout(m_question);
    questionLayout->setContentsMargins(0, 0, 0, 0);
    questionLayout->addWidget(m_questionText);
    questionLayout->addLayout(answers);
    m_question->hide();

    auto *form = new QFormLayout;
    form->addRow(tr("Serial port"), m_ports);
    form->addRow(tr("Link"), m_uri);
    auto *layout = new QVBoxLayout(makePageBody(this));
    layout->addWidget(m_windowConnection);
    layout->addLayout(form);
    layout->addWidget(m_probeButton);
    layout->addWidget(m_question);
    layout->addWidget(m_progress);
    layout->addWidget(m_results);
    layout->addWidget(m_status);

    connect(m_ports, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (i > 0)
            m_uri->setText(m_ports->itemData(i).toString());
    });
    connect(m_uri, &QLineEdit::textChanged, this, [this] {
        m_probe.cancel();
        m_probeButton->setEnabled(true);
        m_answeringUri.clear();
        m_results->clear();
        m_question->hide(); // it named the link as it was
        emit completeChanged();
    });
    connect(disconnectButton, &QPushButton::clicked, this, &ConnectPage::disconnectAndProbe);
    connect(m_keep, &QPushButton::clicked, this, [this] {
        m_question->hide();
        m_status->setText(tr("The window keeps its connection; nothing was probed."));
    });
    connect(m_probeButton, &QPushButton::clicked, this, &ConnectPage::onProbeClicked);
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
        m_answeringUri = m_probe.answeringUri();
        m_status->setText(any ? tr("The controller answers on %1.").arg(m_probe.answeringUri())
                              : tr("Nothing answered. Check the cable, the port and the controller's power."));
        emit completeChanged();
    });
    // The STOP ends a probe as it ends everything else; Probe is there again.
    connect(wizard, &SetupWizard::stopRequested, this, [this] {
        if (!m_probe.isRunning())
            return;
        m_probe.cancel();
        m_probeButton->setEnabled(true);
        m_status->setText(tr("Probe stopped."));
        emit completeChanged();
    });
    connect(wizard->session(), &RotatorSession::stateChanged, this, &ConnectPage::showWindowConnection);
    showWindowConnection();
}

void ConnectPage::showWindowConnection()
{
    if (m_wizard->windowHasConnection())
        m_windowConnection->setText(
            tr("The window is connected to %1. Next sets up that rotator through this connection. To set up "
               "another one, pick its port or link and Probe: Slew asks before it disconnects the window.")
                .arg(m_wizard->session()->uri()));
    else
        m_windowConnection->setText(tr("The window is not connected: pick the controller's port or link and Probe."));
    emit completeChanged();
}

bool ConnectPage::keepsWindowConnection() const
{
    return m_wizard->windowHasConnection() && m_uri->text().trimmed() == m_wizard->session()->uri();
}

void ConnectPage::onProbeClicked()
{
    if (m_wizard->windowHasConnection())
        askToDisconnect();
    else
        probe();
}

void ConnectPage::askToDisconnect()
{
    m_questionText->setText(tr("Disconnect the window from %1 to probe %2? Slew stops the rotator first, and the "
                               "wizard then connects the window to whatever answers.")
                                .arg(m_wizard->session()->uri(), m_uri->text().trimmed()));
    m_question->show();
    m_keep->setFocus(Qt::OtherFocusReason);
}

void ConnectPage::disconnectAndProbe()
{
    m_question->hide();
    RotatorSession *s = m_wizard->session();
    m_probeButton->setEnabled(false);
    m_status->setText(tr("Stopping the rotator and disconnecting the window…"));
    emit completeChanged();
    // The stop leaves the link before the link goes.
    session::stopThenCall(*s, tr("the wizard disconnects the window to probe"), this, [this, s] {
        s->disconnectFromRotator();
        probe();
    });
}

void ConnectPage::probe()
{
    m_results->clear();
    // Ask in the dialect the link names (a simulator's URI) or the window is
    // set to: a Micro-2g answers no Easycomm query at any baud rate.
    const protocol::Dialect dialect = session::probeDialect(m_uri->text(), m_wizard->profile().dialect);
    m_answeringUri.clear();
    if (!m_probe.start(m_uri->text(), dialect)) {
        m_probeButton->setEnabled(true);
        m_status->setText(m_probe.error());
        emit completeChanged();
        return;
    }
    m_probeButton->setEnabled(false);
    emit completeChanged();
}

bool ConnectPage::isComplete() const
{
    if (m_probe.isRunning() || !m_probeButton->isEnabled())
        return false;
    return keepsWindowConnection() || !m_answeringUri.isEmpty();
}

bool ConnectPage::validatePage()
{
    // A probe disconnects the window first, so a window that is connected
    // now is on the link the operator kept, or on the one the wizard
    // connected it to after a probe: either way the wizard goes on with it.
    const bool keep = m_wizard->windowHasConnection();
    m_wizard->setUsesWindowConnection(keep);
    m_wizard->profile().uri = keep ? m_wizard->session()->uri() : m_answeringUri;
    if (keep)
        m_wizard->profile().dialect = m_wizard->session()->profile().dialect;
    return true;
}

} // namespace slew::ui
