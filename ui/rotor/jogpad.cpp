#include "rotor/jogpad.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QPushButton>

namespace slew::ui {

namespace {

bool isAzimuth(JogPad::Direction d)
{
    return d == JogPad::Left || d == JogPad::Right;
}

QString directionName(JogPad::Direction d)
{
    switch (d) {
    case JogPad::Left:
        return JogPad::tr("azimuth counter-clockwise");
    case JogPad::Right:
        return JogPad::tr("azimuth clockwise");
    case JogPad::Up:
        return JogPad::tr("elevation up");
    case JogPad::Down:
        break;
    }
    return JogPad::tr("elevation down");
}

} // namespace

JogPad::JogPad(face::StationFace *station, QWidget *parent) : QWidget(parent), m_station(station)
{
    setObjectName(QStringLiteral("jogPad"));
    m_speed = new QDoubleSpinBox;
    m_speed->setObjectName(QStringLiteral("jogSpeed"));
    m_speed->setRange(0.1, 30.0);
    m_speed->setDecimals(1);
    m_speed->setSingleStep(0.5);
    m_speed->setValue(5.0);
    m_speed->setSuffix(QStringLiteral(" °/s"));

    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setSpacing(4);
    grid->addWidget(makeButton(Up, QStringLiteral("▲"), QStringLiteral("jogUp")), 0, 1);
    grid->addWidget(makeButton(Left, QStringLiteral("◀"), QStringLiteral("jogLeft")), 1, 0);
    grid->addWidget(m_speed, 1, 1);
    grid->addWidget(makeButton(Right, QStringLiteral("▶"), QStringLiteral("jogRight")), 1, 2);
    grid->addWidget(makeButton(Down, QStringLiteral("▼"), QStringLiteral("jogDown")), 2, 1);
    // How to jog is said in the group's title (the window's): a line of its
    // own here cost the height a 720-pixel screen does not have.
    connect(station, &face::StationFace::stateChanged, this, &JogPad::follow);
    follow(station->state().value_or(face::StationState{}));
}

void JogPad::follow(const face::StationState &state)
{
    if (state.azimuthOnly != m_azimuthOnly)
        followAxes(state.azimuthOnly);
    followSpeed(state);
}

void JogPad::followSpeed(const face::StationState &state)
{
    // Until the probe has answered the box stays usable: most dialects take
    // a speed, and greying it out on every connect would only flicker.
    const bool ownSpeed = !state.jogSpeed;
    m_speed->setEnabled(!ownSpeed);
    m_speed->setToolTip(ownSpeed ? tr("%1 has no speed command: the controller jogs at its own speed.").arg(state.dialect)
                                 : tr("Jog speed"));
}

void JogPad::followAxes(bool azimuthOnly)
{
    // An azimuth-only rotator has nothing to jog up or down.
    m_azimuthOnly = azimuthOnly;
    for (Direction d : {Up, Down}) {
        if (azimuthOnly)
            release(d);
        m_buttons[d]->setEnabled(!azimuthOnly);
        m_buttons[d]->setToolTip(azimuthOnly ? tr("This rotator turns azimuth only.")
                                             : (d == Up ? tr("Elevation up") : tr("Elevation down")));
    }
}

QPushButton *JogPad::makeButton(Direction d, const QString &text, const QString &name)
{
    auto *b = new QPushButton(text);
    b->setObjectName(name);
    b->setAutoDefault(false);
    b->setFocusPolicy(Qt::NoFocus); // keys go to KeyboardControl, not to a focused button
    b->setMinimumSize(52, 32);
    static const char *tips[] = {"Azimuth counter-clockwise", "Azimuth clockwise", "Elevation up", "Elevation down"};
    b->setToolTip(tr(tips[d]));
    connect(b, &QPushButton::pressed, this, [this, d] { press(d); });
    connect(b, &QPushButton::released, this, [this, d] { release(d); });
    m_buttons[d] = b;
    return b;
}

double JogPad::speed() const
{
    return m_speed->value();
}

double JogPad::axisSpeed(Direction negative, Direction positive) const
{
    const int axis = isAzimuth(negative) ? 0 : 1;
    const bool forward = m_held[positive] && (!m_held[negative] || m_lastPressed[axis] == positive);
    const bool back = m_held[negative] && !forward;
    return forward ? speed() : back ? -speed() : 0.0;
}

void JogPad::press(Direction d)
{
    if (m_held[d] || !m_buttons[d]->isEnabled()) // the arrow keys come here too
        return;
    m_held[d] = true;
    m_lastPressed[isAzimuth(d) ? 0 : 1] = d;
    m_buttons[d]->setDown(true);
    const face::Outcome sent = m_station->startJog(axisSpeed(Left, Right), axisSpeed(Down, Up));
    if (sent.isAccepted())
        emit jogStarted(tr("jog %1 at %2°/s").arg(directionName(d)).arg(speed(), 0, 'f', 1));
}

void JogPad::release(Direction d)
{
    if (!m_held[d])
        return;
    m_held[d] = false;
    m_buttons[d]->setDown(false);
    // The opposite direction on the same axis, or the other axis, may still
    // be held: they go on.
    const double az = axisSpeed(Left, Right), el = axisSpeed(Down, Up);
    if (az != 0 || el != 0) {
        m_station->startJog(az, el);
        return;
    }
    m_station->endJog(tr("jog %1 released").arg(directionName(d)));
}

void JogPad::releaseAll()
{
    for (Direction d : {Left, Right, Up, Down})
        release(d);
}

} // namespace slew::ui
