#include "wizard/identifypage.h"

#include "wizard/pagebody.h"
#include "wizard/setupwizard.h"

#include "protocol/dialect.h"
#include "session/rotatorsession.h"

#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QVBoxLayout>

namespace slew::ui {

using session::RotatorSession;

IdentifyPage::IdentifyPage(SetupWizard *wizard) : QWizardPage(wizard), m_wizard(wizard)
{
    setTitle(tr("Identify"));
    setSubTitle(tr("Slew asks the controller in each Easycomm flavour, in GS-232B, as a Micro-2g and in SPID's "
                   "binary frames, and keeps the one that explains what it answers."));
    m_progress = new QProgressBar(this);
    m_answers = new QListWidget(this);
    m_result = new QLabel(this);
    m_result->setObjectName(QStringLiteral("dialectResult"));
    m_result->setWordWrap(true);
    auto *layout = new QVBoxLayout(makePageBody(this));
    layout->addWidget(m_progress);
    layout->addWidget(m_answers);
    layout->addWidget(m_result);

    connect(&m_identifier, &tuning::DialectIdentifier::progress, this, [this](int percent, const QString &what) {
        m_progress->setValue(percent);
        m_result->setText(what);
    });
    connect(&m_identifier, &tuning::DialectIdentifier::finished, this, &IdentifyPage::onIdentified);
    RotatorSession *s = wizard->session();
    connect(s, &RotatorSession::capabilitiesChanged, this, [this] {
        if (m_wizard->usesWindowConnection() && m_wizard->currentPage() == this)
            showWindowConnection();
        emit completeChanged();
    });
    connect(s, &RotatorSession::positionChanged, this, &IdentifyPage::completeChanged);
    connect(s, &RotatorSession::stateChanged, this, &IdentifyPage::completeChanged);
    connect(wizard, &SetupWizard::stopRequested, this, [this] {
        if (!m_identifier.isRunning())
            return;
        m_identifier.cancel();
        m_result->setText(tr("Identification stopped. Back, then Next, runs it again."));
    });
}

void IdentifyPage::initializePage()
{
    m_answers->clear();
    if (m_wizard->usesWindowConnection()) {
        showWindowConnection();
        return;
    }
    if (!m_identifier.start(m_wizard->profile().uri))
        m_result->setText(m_identifier.error());
}

void IdentifyPage::showWindowConnection()
{
    const RotatorSession *s = m_wizard->session();
    m_answers->clear();
    m_progress->setValue(100);
    if (!s->capabilities().probed) {
        m_result->setText(tr("The window's connection to %1 is still asking the controller what it answers…")
                              .arg(s->uri()));
        return;
    }
    tuning::DialectResult known;
    known.dialect = s->profile().dialect;
    known.capabilities = s->capabilities();
    known.version = s->version();
    m_answers->addItem(known.describe());
    m_result->setText(tr("The window's connection to %1 speaks %2%3; the wizard goes on with it. (To identify "
                         "the controller afresh, go back and probe its link.)")
                          .arg(s->uri(), protocol::dialectName(known.dialect),
                               known.version.isEmpty() ? QString() : tr(" (version %1)").arg(known.version)));
}

void IdentifyPage::onIdentified(bool identified)
{
    for (const auto &r : m_identifier.results())
        m_answers->addItem(QStringLiteral("%1 (score %2)").arg(r.describe()).arg(r.score));
    if (!identified) {
        m_result->setText(tr("No dialect got an answer. An Easycomm I controller answers nothing and cannot be "
                             "set up here; otherwise go back and check the link."));
        return;
    }
    const auto best = *m_identifier.best();
    m_wizard->profile().dialect = best.dialect;
    m_wizard->profile().firmware = best.firmware;
    const QString firmware = best.firmware == protocol::Firmware::Generic
                                 ? QString()
                                 : tr(", and runs the %1 firmware").arg(protocol::firmwareTitle(best.firmware));
    m_result->setText(tr("The controller speaks %1%2%3. Connecting…%4")
                          .arg(protocol::dialectName(best.dialect),
                               best.version.isEmpty() ? QString() : tr(" (version %1)").arg(best.version), firmware,
                               best.dialect == protocol::Dialect::Rot2Prog
                                   ? tr(" An MD-01/02 answers as a Rot2Prog does: if this is one, choose md01 "
                                        "afterwards for its move command.")
                                   : QString()));
    RotatorSession *s = m_wizard->session();
    s->setProfile(m_wizard->profile());
    s->connectTo(m_wizard->profile().uri);
}

bool IdentifyPage::isComplete() const
{
    const RotatorSession *s = m_wizard->session();
    return !m_identifier.isRunning() && s->isConnected() && s->capabilities().probed && s->hasPosition();
}

} // namespace slew::ui
