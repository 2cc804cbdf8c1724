#include "simulator.h"

#include "micro2g/micro2gstatefile.h"

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
        if (m_micro2g) {
            m_micro2g->advance(now - m_micro2gAt);
            m_micro2gAt = now;
        }
        emit ticked();
    });
    m_pushTick.setTimerType(Qt::PreciseTimer);
    connect(&m_pushTick, &QTimer::timeout, this, &Simulator::pushTick);
    // Load a kept state now, so that a bad file is known before a host connects.
    if (options.dialect == protocol::Dialect::Micro2g || !options.stateFile.isEmpty())
        micro2g();
}

void Simulator::syncToNow()
{
    const double now = m_clock.now();
    m_rotator.advanceTo(now);
    if (m_micro2g && now > m_micro2gAt) {
        m_micro2g->advance(now - m_micro2gAt);
        m_micro2gAt = now;
    }
}

void Simulator::addPushListener()
{
    ++m_pushListeners;
    noteInput(); // pushes the first state at once, and on while it changes
}

void Simulator::removePushListener()
{
    if (--m_pushListeners <= 0) {
        m_pushListeners = 0;
        m_pushTick.stop();
    }
}

void Simulator::noteInput()
{
    if (m_pushListeners == 0 || m_clock.isManual())
        return;
    // A command may set the rotator moving: pushes at the full pace again.
    // A tick already at that pace is left to run, or a stream of input
    // would put it off for ever.
    if (!m_pushTick.isActive() || m_pushTick.interval() != kPushTickMs)
        m_pushTick.start(kPushTickMs);
}

void Simulator::pushTick()
{
    syncToNow();
    emit ticked();
    // At rest nothing changes for a push to tell: no tick until input
    // arrives. Standing still, only a cooling motor's temperature moves, a
    // hundredth of a degree in seconds. (A Micro-2g line pushes nothing.)
    if (m_rotator.atRest())
        m_pushTick.stop();
    else if (m_rotator.standingStill() && m_pushTick.interval() != kCoolingTickMs)
        m_pushTick.start(kCoolingTickMs);
}

Micro2gController &Simulator::micro2g()
{
    if (!m_micro2g) {
        m_micro2g = std::make_unique<Micro2gController>();
        m_micro2gAt = m_clock.now();
        if (!m_options.stateFile.isEmpty())
            m_stateFileError = loadMicro2gState(m_options.stateFile, *m_micro2g);
    }
    return *m_micro2g;
}

QStringList Simulator::handleMicro2g(const QString &line)
{
    syncToNow();
    Micro2gController &controller = micro2g();
    const QJsonObject before = controller.settings();
    const QStringList replies = controller.handle(line);
    // Only a changed calibration, preset or tolerance is written: a poll
    // every second must not rewrite the file every second.
    if (!m_options.stateFile.isEmpty() && controller.settings() != before) {
        m_stateFileError = saveMicro2gState(m_options.stateFile, controller);
        if (!m_stateFileError.isEmpty())
            emit stateFileFailed(m_stateFileError);
    }
    return replies;
}

void Simulator::setAxisFaults(Axis axis, const AxisFaults &faults)
{
    syncToNow();
    m_rotator.setFaults(axis, faults);
    noteInput(); // a fault may set the axis moving (or stop it), for the pushes to tell
}

void Simulator::setLinkFaults(const LinkFaults &faults)
{
    m_linkFaults = faults;
    emit linkFaultsChanged();
}

} // namespace slew::sim
