#include "simclock.h"

#include <algorithm>

namespace slew::sim {

SimClock::SimClock(Mode mode, double timeScale, QObject *parent)
    : QObject(parent), m_mode(mode), m_timeScale(mode == Mode::WallClock ? timeScale : 1.0)
{
    if (m_mode == Mode::WallClock)
        m_elapsed.start();
}

double SimClock::now() const
{
    if (m_mode == Mode::Manual)
        return m_manualNow;
    return m_wallBase + m_timeScale * double(m_elapsed.nsecsElapsed() - m_wallBaseAtNs) / 1e9;
}

void SimClock::setTimeScale(double timeScale)
{
    if (m_mode != Mode::WallClock)
        return;
    // One reading for both: no time is lost or counted twice.
    const qint64 ns = m_elapsed.nsecsElapsed();
    m_wallBase += m_timeScale * double(ns - m_wallBaseAtNs) / 1e9;
    m_wallBaseAtNs = ns;
    m_timeScale = std::clamp(timeScale, 1.0, maxTimeScale);
}

void SimClock::advance(double seconds)
{
    if (m_mode != Mode::Manual || !(seconds > 0.0))
        return;
    m_manualNow += seconds;
    emit advanced(m_manualNow);
}

} // namespace slew::sim
