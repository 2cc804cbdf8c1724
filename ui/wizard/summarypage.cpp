#include "wizard/summarypage.h"

#include "wizard/pagebody.h"
#include "wizard/registernames.h"
#include "wizard/setupwizard.h"

#include "protocol/dialect.h"

#include <QDir>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QStandardPaths>
#include <QVBoxLayout>

namespace slew::ui {

SummaryPage::SummaryPage(SetupWizard *wizard) : QWizardPage(wizard), m_wizard(wizard), m_readback(wizard->session())
{
    setTitle(tr("Summary"));
    setSubTitle(tr("Write the settings to the controller, check each register, and save the profile."));
    m_plan = new QLabel(this);
    m_plan->setObjectName(QStringLiteral("plan"));
    m_plan->setWordWrap(true);
    m_write = new QPushButton(tr("Write to the controller and read back"), this);
    m_write->setObjectName(QStringLiteral("write"));
    m_results = new QListWidget(this);
    m_results->setObjectName(QStringLiteral("writeResults"));
    m_path = new QLineEdit(this);
    m_path->setObjectName(QStringLiteral("profilePath"));
    m_save = new QPushButton(tr("Save profile"), this);
    m_save->setObjectName(QStringLiteral("save"));
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("summaryStatus"));
    m_status->setWordWrap(true);
    m_finishNote = new QLabel(this);
    m_finishNote->setObjectName(QStringLiteral("finishNote"));
    m_finishNote->setWordWrap(true);
    auto *saveRow = new QHBoxLayout;
    saveRow->addWidget(m_path, 1);
    saveRow->addWidget(m_save);
    auto *layout = new QVBoxLayout(makePageBody(this));
    layout->addWidget(m_plan);
    layout->addWidget(m_write);
    layout->addWidget(m_results, 1);
    layout->addLayout(saveRow);
    layout->addWidget(m_status);
    layout->addWidget(m_finishNote);

    connect(m_write, &QPushButton::clicked, this, &SummaryPage::write);
    connect(m_save, &QPushButton::clicked, this, &SummaryPage::save);
    connect(&m_readback, &tuning::RegisterReadback::finished, this, &SummaryPage::onWritten);
}

namespace {

// One register's write and read-back as the operator reads it:
// "Az park: wrote 180°, reads 180.00° — ok".
QString describeCheck(const tuning::RegisterCheck &check)
{
    const QString name = registerName(check.reg);
    const QString wrote = registerValue(check.reg, check.written);
    if (!check.answered)
        return SummaryPage::tr("%1: wrote %2, no answer when read back").arg(name, wrote);
    return SummaryPage::tr("%1: wrote %2, reads %3 — %4")
        .arg(name, wrote, registerValue(check.reg, check.readBack),
             check.ok ? SummaryPage::tr("ok") : SummaryPage::tr("does not match"));
}

} // namespace

void SummaryPage::onWritten(bool allOk)
{
    m_write->setEnabled(true);
    QStringList wrong;
    for (const auto &check : m_readback.results()) {
        m_results->addItem(describeCheck(check));
        if (!check.ok)
            wrong << registerName(check.reg);
    }
    m_status->setText(allOk ? tr("Every register holds what was written.")
                            : tr("Some registers do not hold what was written: see the list."));
    setVerified(allOk, allOk ? tr("Every register reads back what was written: Finish closes the wizard "
                                  "(save the profile first to keep it).")
                             : tr("Finish stays off: %1 did not read back what was written. Write again, or "
                                  "Cancel.")
                                   .arg(wrong.join(QStringLiteral(", "))));
}

void SummaryPage::setVerified(bool verified, const QString &why)
{
    m_verified = verified;
    m_finishNote->setText(why);
    emit completeChanged();
}

bool SummaryPage::isComplete() const
{
    // A controller without registers has nothing to write or read back.
    return m_verified || plannedWrites().isEmpty();
}

QMap<int, QString> SummaryPage::plannedWrites() const
{
    const model::RotatorProfile &p = m_wizard->profile();
    QMap<int, QString> writes;
    if (!protocol::dialectSupports(p.dialect, protocol::Op::ConfigWrite))
        return writes; // no registers (SPID, GS-232): the profile is all there is
    auto gains = [&](int first, const std::optional<model::PidGains> &g) {
        if (!g)
            return;
        writes.insert(first, tuning::RegisterReadback::format(g->kp));
        writes.insert(first + 1, tuning::RegisterReadback::format(g->ki));
        writes.insert(first + 2, tuning::RegisterReadback::format(g->kd));
    };
    gains(1, p.azGains);
    gains(4, p.elGains);
    writes.insert(7, tuning::RegisterReadback::format(p.parkAz));
    writes.insert(8, tuning::RegisterReadback::format(p.parkEl));
    return writes;
}

void SummaryPage::initializePage()
{
    const model::RotatorProfile &p = m_wizard->profile();
    QStringList lines;
    lines << tr("Link %1, dialect %2").arg(p.uri, protocol::dialectName(p.dialect));
    lines << tr("Azimuth %1° … %2° (stop at %3), elevation %4° … %5°")
                 .arg(p.limits.azMin)
                 .arg(p.limits.azMax)
                 .arg(p.southStop ? tr("south") : tr("north"))
                 .arg(p.limits.elMin)
                 .arg(p.limits.elMax);
    const QMap<int, QString> writes = plannedWrites();
    if (!writes.isEmpty())
        lines << tr("To be written to the controller and read back:");
    for (auto it = writes.begin(); it != writes.end(); ++it)
        lines << tr("• %1: %2").arg(registerName(it.key()), registerValue(it.key(), it.value()));
    if (writes.isEmpty())
        lines << tr("%1 has no configuration registers: nothing to write; the park position %2°, %3° is kept "
                    "in the profile.")
                     .arg(protocol::dialectName(p.dialect))
                     .arg(p.parkAz)
                     .arg(p.parkEl);
    m_write->setEnabled(!writes.isEmpty());
    m_write->setToolTip(writes.isEmpty() ? tr("This controller has no registers to write.") : QString());
    m_plan->setText(lines.join(u'\n'));
    // Whatever was written before the operator went back and changed it is
    // not what this plan writes.
    m_results->clear();
    setVerified(false, writes.isEmpty() ? tr("Nothing to write to this controller: Finish closes the wizard "
                                             "(save the profile first to keep it).")
                                        : tr("Finish is off until these settings are written to the controller "
                                             "and every register reads back what was written."));
    if (m_path->text().isEmpty()) {
        const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppConfigLocation);
        m_path->setText(QDir(dir).filePath(QStringLiteral("rotator.json")));
    }
}

void SummaryPage::write()
{
    m_results->clear();
    setVerified(false, tr("Finish is off while the registers are written and read back."));
    if (!m_readback.run(plannedWrites())) {
        m_status->setText(m_readback.error());
        setVerified(false, tr("Finish stays off: nothing was written (%1).").arg(m_readback.error()));
        return;
    }
    m_write->setEnabled(false);
    m_status->setText(tr("Writing…"));
}

void SummaryPage::save()
{
    const QString path = m_path->text().trimmed();
    if (path.isEmpty()) {
        m_status->setText(tr("Enter a file name for the profile."));
        return;
    }
    QDir().mkpath(QFileInfo(path).absolutePath());
    QString error;
    if (!m_wizard->profile().save(path, &error)) {
        m_status->setText(error);
        return;
    }
    m_status->setText(tr("Profile saved to %1.").arg(path));
    emit m_wizard->profileSaved(path);
}

} // namespace slew::ui
