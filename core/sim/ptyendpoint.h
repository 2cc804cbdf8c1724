#pragma once
// Serves a Simulator on a pseudo-terminal, for peers that only speak to
// serial ports (Hamlib's rotctl). The terminal is made with posix_openpt and
// published as a symlink at a path of the caller's choosing, in raw mode.
//
// The endpoint keeps the slave side open itself: without that, the master
// reads EIO whenever no peer has the terminal open, between two rotctl runs.

#include "simulatorconnection.h"

#include <QObject>
#include <QString>

namespace slew::sim {

class Simulator;
class PtyMasterDevice;

class PtyEndpoint : public QObject {
    Q_OBJECT
public:
    PtyEndpoint(Simulator &simulator, const ConnectionSettings &settings, QObject *parent = nullptr);
    ~PtyEndpoint() override;

    // Creates the terminal and the symlink at linkPath (an existing symlink
    // there is replaced; any other file is left alone and is an error).
    bool open(const QString &linkPath);
    void close();
    QString errorString() const { return m_error; }
    QString linkPath() const { return m_linkPath; }
    QString terminalPath() const { return m_terminalPath; }
    SimulatorConnection *connection() const { return m_connection; }

private:
    bool fail(const QString &what);
    void replug();

    Simulator &m_simulator;
    ConnectionSettings m_settings;
    PtyMasterDevice *m_device = nullptr;
    SimulatorConnection *m_connection = nullptr;
    int m_slaveFd = -1;
    QString m_linkPath;
    QString m_terminalPath;
    QString m_error;
};

} // namespace slew::sim
