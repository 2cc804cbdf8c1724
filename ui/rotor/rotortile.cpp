#include "rotor/rotortile.h"

#include "operatortheme.h"
#include "widgets/compassdial.h"

#include "session/rotatorsession.h"

#include <QGridLayout>
#include <QLabel>
#include <QToolButton>
#include <QSpinBox>

#include <cmath>

namespace slew::ui {

using session::RotatorSession;

RotorTile::RotorTile(RotatorSession *session, int number, bool isMain, QWidget *parent)
    : QFrame(parent), m_session(session), m_number(number)
{
    setObjectName(QStringLiteral("rotorTile%1").arg(number));
    setFrameShape(QFrame::StyledPanel);
    auto *title = new QLabel(isMain ? tr("<b>Rotor %1</b> · this window").arg(number) : tr("<b>Rotor %1</b>").arg(number));
    title->setToolTip(isMain ? tr("The plot, the jog pad, go-to and the charts drive this rotor.")
                             : tr("Another rotor on the same controller line."));
    m_dial = new CompassDial;
    m_dial->setObjectName(QStringLiteral("dial"));
    m_heading = new QLabel(QStringLiteral("—"));
    m_heading->setObjectName(QStringLiteral("heading"));
    QFont big = m_heading->font();
    big.setPointSizeF(big.pointSizeF() * 1.25);
    big.setBold(true);
    m_heading->setFont(big);
    m_state = new QLabel;
    m_state->setObjectName(QStringLiteral("state"));
    m_state->setWordWrap(true);
    m_bearing = new QSpinBox;
    m_bearing->setObjectName(QStringLiteral("bearing"));
    m_bearing->setRange(0, 359);
    m_bearing->setSuffix(QStringLiteral("°"));
    m_bearing->setWrapping(true);
    m_bearing->setToolTip(tr("Bearing to turn rotor %1 to").arg(number));
    // Tool buttons: four tiles share the plot's width, and a push button's
    // style minimum would make the window wider than a laptop screen.
    m_go = new QToolButton;
    m_go->setText(tr("Go"));
    m_go->setObjectName(QStringLiteral("go"));
    m_stop = new QToolButton;
    m_stop->setText(tr("Stop"));
    m_stop->setObjectName(QStringLiteral("stop"));
    m_stop->setToolTip(tr("Stop rotor %1 (the window's Stop, Esc or Pause stops every rotor)").arg(number));
    m_stop->setStyleSheet(QStringLiteral("QToolButton { color: %1; font-weight: bold; }").arg(QLatin1String(tone::kRefused)));
    // Narrow enough that four tiles fit under the plot without widening the
    // window: a small compass, a bearing field without arrows (the wheel and
    // the keys still step it), words that wrap.
    title->setWordWrap(true);
    m_dial->setMinimumSize(48, 48);
    m_bearing->setButtonSymbols(QAbstractSpinBox::NoButtons);
    m_bearing->setAlignment(Qt::AlignRight);

    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(5, 4, 5, 5);
    grid->setHorizontalSpacing(4);
    grid->setVerticalSpacing(2);
    grid->addWidget(title, 0, 0, 1, 2);
    grid->addWidget(m_dial, 1, 0, 2, 1);
    grid->addWidget(m_heading, 1, 1);
    grid->addWidget(m_state, 2, 1);
    grid->addWidget(m_bearing, 3, 0);
    grid->addWidget(m_go, 3, 1);
    grid->addWidget(m_stop, 4, 0, 1, 2);
    grid->setColumnStretch(0, 1);
    grid->setColumnStretch(1, 1);
    for (QWidget *w : {static_cast<QWidget *>(m_go), static_cast<QWidget *>(m_stop)})
        w->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);

    connect(m_go, &QToolButton::clicked, this, &RotorTile::go);
    connect(m_bearing, &QSpinBox::editingFinished, this, [this] {
        if (m_bearing->hasFocus())
            go();
    });
    connect(m_stop, &QToolButton::clicked, this, [this] { m_session->stop(tr("rotor %1's stop button").arg(m_number)); });
    connect(session, &RotatorSession::positionChanged, this, &RotorTile::showPosition);
    connect(session, &RotatorSession::targetChanged, this, [this](double az, double) {
        m_dial->setTarget(az);
        showState();
    });
    connect(session, &RotatorSession::stateChanged, this, &RotorTile::showState);
    connect(session, &RotatorSession::commandRefused, this, [this](const QString &reason) {
        m_refusal = reason;
        showState();
    });
    connect(session, &RotatorSession::moveSent, this, [this] {
        m_refusal.clear();
        showState();
    });
    if (session->hasPosition())
        showPosition(session->azimuth(), session->elevation(), session->positionStale());
    showState();
}

QString RotorTile::headingText() const
{
    return m_heading->text();
}

QString RotorTile::stateText() const
{
    return m_state->text();
}

void RotorTile::showPosition(double az, double, bool stale)
{
    // Turning is what the readings say, not what was asked: a rotor at rest
    // inside its controller's tolerance of the target is at rest.
    m_turning = !stale && !std::isnan(m_lastHeading) && std::abs(az - m_lastHeading) > 0.5;
    m_lastHeading = stale ? std::nan("") : az;
    m_dial->setHeading(az, stale);
    m_heading->setText(stale ? tr("%1° ?").arg(std::lround(az)) : tr("%1°").arg(std::lround(az)));
    m_heading->setToolTip(stale ? tr("No fresh reading from the controller") : QString());
    showState();
}

void RotorTile::showState()
{
    QString text;
    QString colour = QStringLiteral("#9aa5b4");
    if (!m_refusal.isEmpty()) {
        text = m_refusal;
        colour = QString::fromLatin1(tone::kRefused);
    } else if (!m_session->isConnected()) {
        text = m_session->state() == RotatorSession::State::Disconnected ? tr("not connected") : tr("connecting…");
        m_dial->clear();
    } else if (m_turning) {
        const auto target = m_session->activeTarget();
        text = target ? tr("turning to %1°").arg(std::lround(target->azimuth)) : tr("turning");
    } else {
        text = tr("at rest");
    }
    m_state->setText(text);
    m_state->setStyleSheet(QStringLiteral("color: %1;").arg(colour));
    const bool connected = m_session->isConnected();
    m_go->setEnabled(connected);
    m_bearing->setEnabled(connected);
}

void RotorTile::go()
{
    m_session->gotoPosition(m_bearing->value(), 0);
}

} // namespace slew::ui
