#include "simulator.h"

namespace slew::sim {

Simulator::Simulator(const SimulatorOptions &options, QObject *parent)
    : QObject(parent),
      m_options(options),
      m_clock(options.manualClock ? SimClock::Mode::Manual : SimClock::Mode::WallClock, options.timeScale),
      m_rotator(options.rotator),
      m_linkFaults(options.link)
{
    m_rotator.setFaults(Axis::Azimuth, options.azimuthFaults);
    m_rotator.setFaults(Axis::Elevation, options.elevationFaults);
    connect(&m_clock, &SimClock::advanced, this, [this](double now) {
        m_rotator.advanceTo(now);
        emit ticked();
    });
}

void Simulator::syncToNow()
{
    m_rotator.advanceTo(m_clock.now());
}

void Simulator::setAxisFaults(Axis axis, const AxisFaults &faults)
{
    syncToNow();
    m_rotator.setFaults(axis, faults);
}

void Simulator::setLinkFaults(const LinkFaults &faults)
{
    m_linkFaults = faults;
    emit linkFaultsChanged();
}

} // namespace slew::sim
