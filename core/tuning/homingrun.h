#pragma once
// RESET with a watch on it: progress from the distance left to the lower
// end stops, a time limit, and a verdict from GE — a homing error (often a
// missing end stop) or a motor error ends it with a message that says so.
// Cancel sends SA SE.

#include "sampleclock.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace slew::session {
class RotatorSession;
}

namespace slew::tuning {

class HomingRun : public QObject {
    Q_OBJECT
public:
    explicit HomingRun(session::RotatorSession *session, QObject *parent = nullptr);

    // Starts; false with error() (nothing sent) when it cannot.
    bool start(double timeoutSeconds = 120.0);
    void cancel();
    bool isRunning() const { return m_running; }
    QString error() const { return m_error; }
    // The last run failed because the controller refused RESET.
    bool refusedByController() const { return m_refusedByController; }

signals:
    void progress(int percent, const QString &what);
    void succeeded();
    void failed(const QString &reason);
    void cancelled();

private:
    void evaluate();
    void end(bool ok, const QString &reason);
    double distanceLeft() const;

    session::RotatorSession *m_session;
    SampleClock m_clock;
    QTimer m_tick;
    QElapsedTimer m_wall;
    bool m_running = false;
    bool m_refusedByController = false;
    bool m_freshErrors = false;  // GE changed since RESET went out
    double m_timeout = 120.0;
    double m_started = 0.0;
    double m_initialDistance = 1.0;
    double m_atHomeSince = -1.0;
    QString m_error;
};

} // namespace slew::tuning
