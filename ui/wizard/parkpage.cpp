#include "wizard/parkpage.h"

#include "wizard/pagebody.h"
#include "wizard/setupwizard.h"

#include "protocol/dialect.h"
#include "session/rotatorsession.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace slew::ui {

ParkPage::ParkPage(SetupWizard *wizard) : QWizardPage(wizard), m_wizard(wizard)
{
    setTitle(tr("Park position"));
    setSubTitle(tr("Where the antenna rests when it is not in use (PARK). Written to CW7 and CW8 on the summary page."));
    m_az = new QDoubleSpinBox(this);
    m_az->setObjectName(QStringLiteral("parkAz"));
    m_az->setDecimals(1);
    m_az->setSuffix(QStringLiteral("°"));
    m_el = new QDoubleSpinBox(this);
    m_el->setObjectName(QStringLiteral("parkEl"));
    m_el->setDecimals(1);
    m_el->setSuffix(QStringLiteral("°"));
    m_useCurrent = new QPushButton(tr("Use the present position"), this);
    m_useCurrent->setObjectName(QStringLiteral("useCurrent"));
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    auto *form = new QFormLayout;
    form->addRow(tr("Azimuth"), m_az);
    form->addRow(tr("Elevation"), m_el);
    auto *layout = new QVBoxLayout(makePageBody(this));
    layout->addLayout(form);
    layout->addWidget(m_useCurrent);
    layout->addWidget(m_status);
    connect(m_useCurrent, &QPushButton::clicked, this, [this] {
        const session::RotatorSession *s = m_wizard->session();
        if (!s->hasPosition()) {
            m_status->setText(tr("No position from the rotator yet."));
            return;
        }
        m_az->setValue(s->azimuth());
        m_el->setValue(s->elevation());
    });
}

void ParkPage::initializePage()
{
    // Where the park position goes depends on the controller: its registers,
    // or (without any, as SPID) only the profile, which Park then drives to.
    const protocol::Dialect d = m_wizard->profile().dialect;
    setSubTitle(protocol::dialectSupports(d, protocol::Op::ConfigWrite)
                    ? tr("Where the antenna rests when it is not in use (PARK). Written to CW7 and CW8 on the summary page.")
                    : tr("Where the antenna rests when it is not in use. %1 has no park registers: the position is "
                         "kept in the profile, and Park drives there with a go-to.")
                          .arg(protocol::dialectName(d)));
    // The spin boxes only offer what the limits allow.
    const model::RotatorProfile &p = m_wizard->profile();
    m_az->setRange(p.limits.azMin, p.limits.azMax);
    m_el->setRange(p.limits.elMin, p.limits.elMax);
    m_az->setValue(p.parkAz);
    m_el->setValue(p.parkEl);
    m_status->clear();
    // A controller with park registers parks where they say: start from
    // what it holds, not from the profile's guess (0/90 in a fresh one).
    const session::RotatorSession *s = m_wizard->session();
    if (!s->isConnected() || !s->hasParkRegisters() || !protocol::dialectSupports(d, protocol::Op::ConfigWrite))
        return;
    if (!s->parkKnown()) {
        m_status->setText(tr("Park not read yet: these are the profile's %1°, %2°, not what the controller holds.")
                              .arg(p.parkAz, 0, 'f', 1)
                              .arg(p.parkEl, 0, 'f', 1));
        return;
    }
    m_az->setValue(s->controllerParkAzimuth());
    m_el->setValue(s->controllerParkElevation());
    m_status->setText(tr("The controller's park registers hold %1°, %2°.")
                          .arg(s->controllerParkAzimuth(), 0, 'f', 1)
                          .arg(s->controllerParkElevation(), 0, 'f', 1));
}

bool ParkPage::validatePage()
{
    model::RotatorProfile &p = m_wizard->profile();
    const QString e = model::MoveGate(p.limits).pointing(m_az->value(), m_el->value(), std::nullopt).refusal;
    if (!e.isEmpty()) {
        m_status->setText(e);
        return false;
    }
    p.parkAz = m_az->value();
    p.parkEl = m_el->value();
    return true;
}

} // namespace slew::ui
