#include "simulatorlink.h"

#include "simulatorconnection.h"

namespace slew::sim {

SimulatorLink::SimulatorLink(const QString &uri, const SimulatorOptions &options, QObject *parent)
    : Link(uri, parent), m_simulator(options)
{
    // Connected after the simulator's own handler, so replies the step
    // releases are already on their way when the session's timers look.
    if (m_simulator.clock().isManual())
        connect(&m_simulator.clock(), &SimClock::advanced, this, &Link::clockStepped);
}

SimulatorLink::~SimulatorLink()
{
    delete m_connection;
}

std::optional<double> SimulatorLink::clockSeconds() const
{
    return m_simulator.clock().now();
}

bool SimulatorLink::setTimeScale(double scale)
{
    if (m_simulator.clock().isManual())
        return false;
    m_simulator.clock().setTimeScale(scale);
    return true;
}

double SimulatorLink::timeScale() const
{
    return m_simulator.clock().isManual() ? 1.0 : m_simulator.clock().timeScale();
}

void SimulatorLink::open()
{
    if (m_connection)
        return;
    // Opening reports back from the event loop, like every other link.
    QMetaObject::invokeMethod(
        this,
        [this] {
            if (m_connection)
                return;
            m_pipe.hostEnd()->open(QIODevice::ReadWrite | QIODevice::Unbuffered);
            m_pipe.deviceEnd()->open(QIODevice::ReadWrite | QIODevice::Unbuffered);
            ConnectionSettings settings;
            settings.dialect = m_simulator.options().dialect;
            settings.unsolicited = m_simulator.options().unsolicited;
            settings.echo = m_simulator.options().echo;
            settings.checksum = m_simulator.options().checksum;
            settings.baud = m_simulator.options().baud;
            m_connection = new SimulatorConnection(m_simulator, m_pipe.deviceEnd(), settings, this);
            connect(m_connection, &SimulatorConnection::dropRequested, this, &SimulatorLink::drop,
                    Qt::QueuedConnection);
            emit opened();
        },
        Qt::QueuedConnection);
}

void SimulatorLink::close()
{
    delete m_connection;
    m_connection = nullptr;
    m_pipe.deviceEnd()->close();
    m_pipe.hostEnd()->close();
}

void SimulatorLink::drop()
{
    if (!m_connection)
        return;
    close();
    emit lost(QStringLiteral("%1: the simulated connection dropped").arg(uri()));
}

} // namespace slew::sim
