#pragma once
// The rotors of a multi-rotor controller, side by side under the plot: a
// tile each (rotortile.h), the window's own rotor marked. Hidden for a
// controller with one rotor.

#include <QWidget>

class QHBoxLayout;

namespace slew::session {
class ControllerRotors;
}

namespace slew::ui {

class RotorTile;

class RotorsPanel : public QWidget {
    Q_OBJECT
public:
    explicit RotorsPanel(session::ControllerRotors *rotors, QWidget *parent = nullptr);

    QList<RotorTile *> tiles() const { return m_tiles; }
    RotorTile *tile(int number) const;

private:
    void rebuild();

    session::ControllerRotors *m_rotors;
    QHBoxLayout *m_row;
    QList<RotorTile *> m_tiles;
};

} // namespace slew::ui
