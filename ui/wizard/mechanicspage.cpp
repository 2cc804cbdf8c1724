#include "wizard/mechanicspage.h"

#include "wizard/directioncheck.h"
#include "wizard/pagebody.h"
#include "wizard/setupwizard.h"

#include "session/rotatorsession.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace slew::ui {

using session::Axis;
using Verdict = DirectionCheck::Verdict;

namespace {
constexpr double kJogDegrees = 5.0;

QString confirmation(const DirectionCheck &check)
{
    if (check.axis() == Axis::Azimuth)
        return check.upward() ? MechanicsPage::tr("The antenna turned clockwise (to the right, seen from above)")
                              : MechanicsPage::tr("The antenna turned counter-clockwise (to the left, seen from above)");
    return check.upward() ? MechanicsPage::tr("The antenna tilted up (towards the zenith)")
                          : MechanicsPage::tr("The antenna tilted down (towards the horizon)");
}
} // namespace

MechanicsPage::MechanicsPage(SetupWizard *wizard) : QWizardPage(wizard), m_wizard(wizard)
{
    setTitle(tr("Mechanics"));
    setSubTitle(tr("Tell Slew how far the rotator may turn, then check that each axis moves the way you expect."));
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
    m_azimuth = makeRow(Axis::Azimuth, "jog", "azDirection", "jogConfirmed");
    m_elevation = makeRow(Axis::Elevation, "jogElevation", "elDirection", "jogElevationConfirmed");
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
    layout->addWidget(m_azimuth.box);
    layout->addWidget(m_elevation.box);
    layout->addWidget(m_status);
    layout->addStretch(1);

    // A jog stopped by the wizard's STOP (or Esc) no longer says which way.
    connect(wizard, &SetupWizard::stopRequested, m_azimuth.check, &DirectionCheck::stop);
    connect(wizard, &SetupWizard::stopRequested, m_elevation.check, &DirectionCheck::stop);
}

MechanicsPage::AxisRow MechanicsPage::makeRow(Axis axis, const char *jogName, const char *noteName,
                                              const char *confirmName)
{
    const bool azimuth = axis == Axis::Azimuth;
    AxisRow row;
    row.check = new DirectionCheck(m_wizard->session(), axis, this);
    row.box = new QGroupBox(azimuth ? tr("Azimuth direction") : tr("Elevation direction"), this);
    row.jog = new QPushButton(azimuth ? tr("Jog azimuth %1° clockwise").arg(kJogDegrees)
                                      : tr("Jog elevation %1° up").arg(kJogDegrees),
                              row.box);
    row.jog->setObjectName(QLatin1String(jogName));
    row.note = new QLabel(row.box);
    row.note->setObjectName(QLatin1String(noteName));
    row.note->setWordWrap(true);
    row.confirmed = new QCheckBox(confirmation(*row.check), row.box);
    row.confirmed->setObjectName(QLatin1String(confirmName));
    row.confirmed->setEnabled(false);
    auto *layout = new QVBoxLayout(row.box);
    layout->addWidget(row.jog, 0, Qt::AlignLeft);
    layout->addWidget(row.note);
    layout->addWidget(row.confirmed);
    // The row is returned by value: the lambdas look the page's own up.
    connect(row.jog, &QPushButton::clicked, this, [this, axis] { jog(rowFor(axis)); });
    connect(row.check, &DirectionCheck::verdictChanged, this, [this, axis] { showVerdict(rowFor(axis)); });
    connect(row.confirmed, &QCheckBox::toggled, this, &MechanicsPage::completeChanged);
    return row;
}

MechanicsPage::AxisRow &MechanicsPage::rowFor(Axis axis)
{
    return axis == Axis::Azimuth ? m_azimuth : m_elevation;
}

void MechanicsPage::initializePage()
{
    // The Micro-2g and the Rot1Prog turn azimuth only: nothing to tilt.
    m_elevation.box->setVisible(checksElevation());
}

bool MechanicsPage::checksElevation() const
{
    return !m_wizard->session()->isAzimuthOnly();
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

void MechanicsPage::jog(AxisRow &row)
{
    if (!applyLimits())
        return;
    // A new jog is a new question: the last answer does not carry over.
    row.confirmed->setChecked(false);
    if (!row.check->start(kJogDegrees)) {
        m_status->setText(row.check->error());
        return;
    }
    m_status->clear();
}

void MechanicsPage::showVerdict(AxisRow &row)
{
    const Verdict v = row.check->verdict();
    row.note->setText(row.check->describe());
    row.confirmed->setText(confirmation(*row.check));
    // What the reading contradicts cannot be confirmed by eye.
    const bool confirmable = v == Verdict::Watching || v == Verdict::RightWay || v == Verdict::Stopped;
    if (!confirmable)
        row.confirmed->setChecked(false);
    row.confirmed->setEnabled(confirmable);
    emit completeChanged();
}

bool MechanicsPage::passed(const AxisRow &row) const
{
    return row.confirmed->isChecked() && row.check->verdict() != Verdict::WrongWay;
}

bool MechanicsPage::isComplete() const
{
    return passed(m_azimuth) && (!checksElevation() || passed(m_elevation));
}

bool MechanicsPage::validatePage()
{
    return applyLimits();
}

} // namespace slew::ui
