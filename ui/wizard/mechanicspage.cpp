#include "mechanicspage.h"

#include "pagebody.h"
#include "setupwizard.h"

#include "session/rotatorsession.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace slew::ui {

namespace {
constexpr double kJogDegrees = 5.0;
}

MechanicsPage::MechanicsPage(SetupWizard *wizard) : QWizardPage(wizard), m_wizard(wizard)
{
    setTitle(tr("Mechanics"));
    setSubTitle(tr("Tell Slew how far the rotator may turn, then check that it moves the way you expect."));
    const auto &lim = wizard->profile().limits;
    m_azRange = new QSpinBox(this);
    m_azRange->setObjectName(QStringLiteral("azRange"));
    m_azRange->setRange(360, 450);
    m_azRange->setSuffix(QStringLiteral("°"));
    m_azRange->setValue(int(lim.azMax - lim.azMin));
    m_northStop = new QRadioButton(tr("North (0° … range)"), this);
    m_southStop = new QRadioButton(tr("South (−180° … range − 180°)"), this);
    m_southStop->setObjectName(QStringLiteral("southStop"));
    (wizard->profile().southStop ? m_southStop : m_northStop)->setChecked(true);
    m_elMax = new QComboBox(this);
    m_elMax->setObjectName(QStringLiteral("elMax"));
    m_elMax->addItem(QStringLiteral("0° … 90°"), 90.0);
    m_elMax->addItem(QStringLiteral("0° … 180° (flip)"), 180.0);
    m_elMax->setCurrentIndex(lim.elMax > 90.0 ? 1 : 0);
    m_jog = new QPushButton(tr("Jog azimuth %1° clockwise").arg(kJogDegrees), this);
    m_jog->setObjectName(QStringLiteral("jog"));
    m_confirmed = new QCheckBox(tr("The antenna turned clockwise (to the right, seen from above)"), this);
    m_confirmed->setObjectName(QStringLiteral("jogConfirmed"));
    m_confirmed->setEnabled(false);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("mechanicsStatus"));
    m_status->setWordWrap(true);

    auto *stops = new QHBoxLayout;
    stops->addWidget(m_northStop);
    stops->addWidget(m_southStop);
    auto *form = new QFormLayout;
    form->addRow(tr("Azimuth travel (over 360° is overlap)"), m_azRange);
    form->addRow(tr("Azimuth end stop at"), stops);
    form->addRow(tr("Elevation"), m_elMax);
    auto *layout = new QVBoxLayout(makePageBody(this));
    layout->addLayout(form);
    layout->addWidget(m_jog);
    layout->addWidget(m_confirmed);
    layout->addWidget(m_status);

    connect(m_jog, &QPushButton::clicked, this, &MechanicsPage::jog);
    connect(m_confirmed, &QCheckBox::toggled, this, &MechanicsPage::completeChanged);
}

bool MechanicsPage::applyLimits()
{
    model::RotatorProfile &p = m_wizard->profile();
    model::RotatorLimits lim;
    lim.azMin = m_southStop->isChecked() ? -180.0 : 0.0;
    lim.azMax = lim.azMin + m_azRange->value();
    lim.elMin = 0.0;
    lim.elMax = m_elMax->currentData().toDouble();
    if (const QString e = lim.validate(); !e.isEmpty()) {
        m_status->setText(e);
        return false;
    }
    p.limits = lim;
    p.southStop = m_southStop->isChecked();
    m_wizard->session()->setProfile(p);
    return true;
}

void MechanicsPage::jog()
{
    if (!applyLimits())
        return;
    session::RotatorSession *s = m_wizard->session();
    if (!s->hasPosition()) {
        m_status->setText(tr("No position from the rotator yet."));
        return;
    }
    const double az = s->azimuth();
    // Clockwise unless that would run into the stop; then the note says so.
    const bool clockwise = az + kJogDegrees <= s->moveGate().limits().azMax;
    const double target = clockwise ? az + kJogDegrees : az - kJogDegrees;
    if (!s->gotoPosition(target, s->elevation())) {
        m_status->setText(tr("The jog was refused."));
        return;
    }
    m_confirmed->setText(clockwise ? tr("The antenna turned clockwise (to the right, seen from above)")
                                   : tr("The antenna turned counter-clockwise (to the left, seen from above)"));
    m_confirmed->setEnabled(true);
    m_status->setText(tr("Watch the antenna: it should turn %1° from %2° to %3°. If it went the other way, "
                         "stop here and swap the motor's direction before going on.")
                          .arg(kJogDegrees)
                          .arg(az, 0, 'f', 1)
                          .arg(target, 0, 'f', 1));
}

bool MechanicsPage::isComplete() const
{
    return m_confirmed->isChecked();
}

bool MechanicsPage::validatePage()
{
    return applyLimits();
}

} // namespace slew::ui
