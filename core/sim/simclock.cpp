#include "simclock.h"

namespace slew::sim {

SimClock::SimClock(Mode mode, double timeScale, QObject *parent)
    : QObject(parent), m_mode(mode), m_timeScale(mode == Mode::WallClock ? timeScale : 1.0)
{
    if (m_mode == Mode::WallClock) {
        m_elapsed.start();
        m_tick.setTimerType(Qt::PreciseTimer);
        m_tick.setInterval(tickMilliseconds);
        connect(&m_tick, &QTimer::timeout, this, [this] { emit advanced(now()); });
        m_tick.start();
    }
}

double SimClock::now() const
{
    if (m_mode == Mode::Manual)
        return m_manualNow;
    return m_timeScale * double(m_elapsed.nsecsElapsed()) / 1e9;
}

void SimClock::advance(double seconds)
{
    if (m_mode != Mode::Manual || !(seconds > 0.0))
        return;
    m_manualNow += seconds;
    emit advanced(m_manualNow);
}

} // namespace slew::sim
