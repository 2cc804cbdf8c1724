#include "rotor/positionreadout.h"

#include <cmath>

#include <QGridLayout>
#include <QLabel>

namespace slew::ui {

// A figure as shown to a tenth: -0.04 rounds to "-0.0" in printf, which
// reads as a sign error; it is shown as 0.0.
double shownTenths(double value)
{
    const double rounded = std::round(value * 10.0) / 10.0;
    return rounded == 0.0 ? 0.0 : rounded;
}


using session::RotatorSession;

namespace {

QLabel *bigFigure(const QString &name)
{
    auto *l = new QLabel(QStringLiteral("---.-°"));
    l->setObjectName(name);
    QFont f(QStringLiteral("monospace"));
    f.setStyleHint(QFont::Monospace);
    f.setPointSize(22);
    f.setBold(true);
    l->setFont(f);
    l->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return l;
}

} // namespace

PositionReadout::PositionReadout(RotatorSession *session, QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("positionReadout"));
    m_az = bigFigure(QStringLiteral("readoutAzimuth"));
    m_el = bigFigure(QStringLiteral("readoutElevation"));
    m_target = new QLabel;
    m_target->setObjectName(QStringLiteral("readoutTarget"));
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("readoutStatus"));
    m_status->setWordWrap(true);

    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(new QLabel(tr("Azimuth")), 0, 0);
    grid->addWidget(m_az, 0, 1);
    grid->addWidget(new QLabel(tr("Elevation")), 1, 0);
    grid->addWidget(m_el, 1, 1);
    grid->addWidget(m_target, 2, 0, 1, 2);
    grid->addWidget(m_status, 3, 0, 1, 2);

    connect(session, &RotatorSession::positionChanged, this, &PositionReadout::showPosition);
    connect(session, &RotatorSession::targetChanged, this, [this](double az, double el) {
        m_target->setText(tr("Target  %1°  %2°").arg(shownTenths(az), 0, 'f', 1).arg(shownTenths(el), 0, 'f', 1));
    });
    connect(session, &RotatorSession::targetCleared, m_target, &QLabel::clear);
    connect(session, &RotatorSession::statusChanged, this, &PositionReadout::showStatus);
    connect(session, &RotatorSession::stateChanged, this, [this](RotatorSession::State s) {
        if (s == RotatorSession::State::Connecting) {
            m_az->setText(QStringLiteral("---.-°"));
            m_el->setText(QStringLiteral("---.-°"));
            m_target->clear();
            m_status->clear();
        }
    });
}

void PositionReadout::showPosition(double az, double el, bool stale)
{
    m_az->setText(QStringLiteral("%1°").arg(shownTenths(az), 6, 'f', 1));
    m_el->setText(QStringLiteral("%1°").arg(shownTenths(el), 6, 'f', 1));
    const QString style = stale ? QStringLiteral("color:#808080;") : QStringLiteral("color:#4cd964;");
    m_az->setStyleSheet(style);
    m_el->setStyleSheet(style);
    m_az->setToolTip(stale ? tr("No fresh position from the controller") : QString());
}

void PositionReadout::showStatus(session::StatusWord status)
{
    if (!status.valid) {
        m_status->clear();
        return;
    }
    if (!status.isPerAxis()) {
        m_status->setText(tr("Status: %1").arg(session::describeAxisStatus(status.azimuth())));
        return;
    }
    m_status->setText(tr("Az: %1   El: %2")
                          .arg(session::describeAxisStatus(status.azimuth()),
                               session::describeAxisStatus(status.elevation())));
}

} // namespace slew::ui
