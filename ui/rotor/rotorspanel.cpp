#include "rotor/rotorspanel.h"

#include "rotor/rotortile.h"

#include "session/controllerrotors.h"

#include <QHBoxLayout>

namespace slew::ui {

RotorsPanel::RotorsPanel(session::ControllerRotors *rotors, QWidget *parent) : QWidget(parent), m_rotors(rotors)
{
    setObjectName(QStringLiteral("rotorsPanel"));
    m_row = new QHBoxLayout(this);
    m_row->setContentsMargins(0, 4, 0, 0);
    m_row->setSpacing(6);
    connect(rotors, &session::ControllerRotors::rotorsChanged, this, &RotorsPanel::rebuild);
    rebuild();
}

RotorTile *RotorsPanel::tile(int number) const
{
    for (RotorTile *t : m_tiles) {
        if (t->number() == number)
            return t;
    }
    return nullptr;
}

void RotorsPanel::rebuild()
{
    // Tiles hold session pointers: every change of the rotor list makes them anew.
    qDeleteAll(m_tiles);
    m_tiles.clear();
    const QList<session::RotatorSession *> sessions = m_rotors->rotors();
    for (int n = 1; n <= sessions.size(); ++n) {
        auto *t = new RotorTile(sessions[n - 1], n, sessions[n - 1] == m_rotors->main());
        m_row->addWidget(t, 1);
        m_tiles.append(t);
    }
    setVisible(!m_tiles.isEmpty());
}

} // namespace slew::ui
