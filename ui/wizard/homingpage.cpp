#include "wizard/homingpage.h"

#include "wizard/pagebody.h"
#include "wizard/setupwizard.h"

#include "protocol/dialect.h"

#include <QCheckBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace slew::ui {

namespace {
constexpr double kHomingTimeoutSeconds = 180.0; // a full 450° sweep at a slow homing speed
}

HomingPage::HomingPage(SetupWizard *wizard) : QWizardPage(wizard), m_wizard(wizard), m_homing(wizard->session())
{
    setTitle(tr("Homing"));
    setSubTitle(tr("The controller drives both axes to their lower end stops and zeroes there (RESET)."));
    m_home = new QPushButton(tr("Home"), this);
    m_home->setObjectName(QStringLiteral("home"));
    m_progress = new QProgressBar(this);
    m_result = new QLabel(this);
    m_result->setObjectName(QStringLiteral("homingResult"));
    m_result->setWordWrap(true);
    m_skip = new QCheckBox(tr("Skip: this rotator has no end stops"), this);
    m_skip->setObjectName(QStringLiteral("skipHoming"));

    auto *layout = new QVBoxLayout(makePageBody(this));
    layout->addWidget(m_home, 0, Qt::AlignLeft);
    layout->addWidget(m_progress);
    layout->addWidget(m_result);
    layout->addWidget(m_skip);
    layout->addStretch(1); // the verdict stays under the bar, not halfway down the page

    connect(m_home, &QPushButton::clicked, this, [this] {
        m_homed = false;
        emit completeChanged();
        if (!m_homing.start(kHomingTimeoutSeconds)) {
            m_result->setText(m_homing.error());
            return;
        }
        setRunning(true);
    });
    connect(&m_homing, &tuning::HomingRun::progress, this, [this](int percent, const QString &what) {
        m_progress->setValue(percent);
        m_result->setText(what);
    });
    connect(&m_homing, &tuning::HomingRun::succeeded, this, [this] {
        m_homed = true;
        setRunning(false);
        m_result->setText(tr("Homed: both axes found their end stops and are at zero."));
    });
    connect(&m_homing, &tuning::HomingRun::failed, this, [this](const QString &why) {
        setRunning(false);
        m_result->setText(why);
    });
    connect(&m_homing, &tuning::HomingRun::cancelled, this, [this] {
        setRunning(false);
        m_result->setText(m_homing.error());
    });
    connect(m_skip, &QCheckBox::toggled, this, &HomingPage::completeChanged);
    connect(wizard, &SetupWizard::stopRequested, &m_homing, &tuning::HomingRun::cancel);
}

void HomingPage::initializePage()
{
    // A controller without a homing command (SPID, GS-232) has nothing to
    // run here: said so, and skipped, rather than offered and then refused.
    const protocol::Dialect d = m_wizard->profile().dialect;
    const bool canHome = protocol::dialectSupports(d, protocol::Op::Reset);
    m_home->setEnabled(canHome && !m_homing.isRunning());
    m_home->setToolTip(canHome ? QString() : tr("%1 has no homing command").arg(protocol::dialectName(d)));
    if (!canHome) {
        m_skip->setChecked(true);
        m_result->setText(tr("%1 has no homing command: the controller keeps its own zero. Skipped.")
                              .arg(protocol::dialectName(d)));
    }
}

void HomingPage::setRunning(bool running)
{
    m_home->setEnabled(!running);
    m_home->setToolTip(running ? tr("Homing: the STOP below ends it") : QString());
    emit completeChanged();
}

bool HomingPage::isComplete() const
{
    return !m_homing.isRunning() && (m_homed || m_skip->isChecked());
}

} // namespace slew::ui
