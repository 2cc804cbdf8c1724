#pragma once
// One rotor of a multi-rotor controller, in a few square centimetres: its
// compass, heading and state, a bearing to go to, and its own Stop. Every
// command goes through the rotor's session, so the same gate and the same
// refusals apply as in the window's main controls.

#include <QFrame>

#include <cmath>

class QLabel;
class QToolButton;
class QSpinBox;

namespace slew::session {
class RotatorSession;
}

namespace slew::ui {

class CompassDial;

class RotorTile : public QFrame {
    Q_OBJECT
public:
    // `isMain`: this is the window's own rotor (the plot, jog and charts).
    RotorTile(session::RotatorSession *session, int number, bool isMain, QWidget *parent = nullptr);

    session::RotatorSession *session() const { return m_session; }
    int number() const { return m_number; }
    CompassDial *dial() const { return m_dial; }
    QSpinBox *bearing() const { return m_bearing; }
    QToolButton *goButton() const { return m_go; }
    QToolButton *stopButton() const { return m_stop; }
    QString headingText() const;
    QString stateText() const;

private:
    void showPosition(double az, double el, bool stale);
    void showState();
    void go();

    session::RotatorSession *m_session;
    int m_number;
    CompassDial *m_dial;
    QLabel *m_heading;
    QLabel *m_state;
    QSpinBox *m_bearing;
    QToolButton *m_go;
    QToolButton *m_stop;
    QString m_refusal; // the last command this tile's session refused, until the next goes out
    double m_lastHeading = std::nan("");
    bool m_turning = false;
};

} // namespace slew::ui
