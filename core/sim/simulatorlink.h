#pragma once
// The `sim:` link: a Simulator of its own behind an in-process pipe, so the
// session talks to it exactly as it would to a serial port.

#include "loopbackpipe.h"
#include "simulator.h"
#include "simulatoroptions.h"

#include "transport/link.h"

#include <memory>

namespace slew::sim {

class SimulatorConnection;

class SimulatorLink : public transport::Link {
    Q_OBJECT
public:
    SimulatorLink(const QString &uri, const SimulatorOptions &options, QObject *parent = nullptr);
    ~SimulatorLink() override;

    QIODevice *device() override { return m_pipe.hostEnd(); }
    void open() override;
    void close() override;
    bool isOpen() const override { return m_connection != nullptr; }
    std::optional<double> clockSeconds() const override;
    bool clockIsStepped() const override { return m_simulator.clock().isManual(); }
    bool setTimeScale(double scale) override;
    double timeScale() const override;

    Simulator &simulator() { return m_simulator; }
    // The firmware of the open connection (counters, dialect); null when closed.
    SimulatorConnection *connection() const { return m_connection; }

private:
    void drop();

    Simulator m_simulator;
    LoopbackPipe m_pipe;
    SimulatorConnection *m_connection = nullptr;
};

} // namespace slew::sim
