#pragma once
// Whether the rotator is moving, as far as the window can tell: the answer
// that decides whether Space in a text field is Stop or a space
// (KeyboardControl). Any sign of motion counts, because a Stop too many
// costs a typed space and a Stop too few leaves the antenna running:
// the controller's status word says an axis moves; a jog button or key is
// held; a go-to is still short of its target; the last two fresh positions
// differ; or the position is stale, so nobody knows.

#include "session/rotatorsession.h"

#include <QObject>
#include <QPointF>

#include <optional>

namespace slew::ui {

class JogPad;

class RotatorMotion : public QObject {
    Q_OBJECT
public:
    RotatorMotion(session::RotatorSession *session, const JogPad *jog, QObject *parent = nullptr);

    bool isMoving() const;

    // Closer than this to a go-to's target on both axes is arrived.
    static constexpr double kArrivedDeg = 0.2;
    // Fresh positions further apart than this are motion, not reading noise.
    static constexpr double kStillDeg = 0.02;

private:
    void onPosition(double az, double el, bool stale);

    session::RotatorSession *m_session;
    const JogPad *m_jog;
    std::optional<QPointF> m_last; // the latest fresh position
    bool m_changed = false;        // it differed from the one before
};

} // namespace slew::ui
