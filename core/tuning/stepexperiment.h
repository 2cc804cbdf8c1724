#pragma once
// One step of one axis on the real controller: bring the axis to rest at the
// start, command the target, and record the positions that come back until
// the axis has stayed at the target for a while or the window runs out. Only
// this axis is commanded; the other keeps what it was doing. Driven entirely by the session's signals
// and a light timer; nothing waits.

#include "sampleclock.h"
#include "stepresponse.h"

#include "session/sessiontypes.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace slew::session {
class RotatorSession;
}

namespace slew::tuning {

struct StepSettings {
    double band = 0.08;          // degrees: "at" a position means within this
    double holdSeconds = 1.0;    // at rest this long counts as settled
    double minimumSeconds = 1.0; // watch a step at least this long
    double maximumSeconds = 15.0;
    double prepareSeconds = 30.0; // the most the move to the start may take
    int silenceMs = 5000;        // no position for this long (wall time) is a failure
};

class StepExperiment : public QObject {
    Q_OBJECT
public:
    enum class Phase { Idle, Preparing, Stepping, Done };
    Q_ENUM(Phase)

    StepExperiment(session::RotatorSession *session, QObject *parent = nullptr);

    void setSettings(const StepSettings &settings) { m_settings = settings; }
    const StepSettings &settings() const { return m_settings; }

    // Starts; false with error() set (and nothing sent) when it cannot.
    bool start(session::Axis axis, double from, double to);
    // Ends the experiment and stops the axis (SA or SE).
    void cancel();

    Phase phase() const { return m_phase; }
    QString error() const { return m_error; }
    const StepResponse &response() const { return m_response; }

signals:
    void progress(double fraction, const QString &what);
    void sampleRecorded(const slew::tuning::PositionSample &sample);
    void finished(const slew::tuning::StepResponse &response);
    void failed(const QString &reason);

private:
    void onPosition(double az, double el, bool stale);
    void evaluate();
    void beginStep();
    session::CommandResult command(double position);
    void end();
    void fail(const QString &reason);
    double reading() const;

    session::RotatorSession *m_session;
    SampleClock m_clock;
    StepSettings m_settings;
    QTimer m_tick;
    QElapsedTimer m_lastSampleWall;
    Phase m_phase = Phase::Idle;
    session::Axis m_axis = session::Axis::Azimuth;
    double m_from = 0.0, m_to = 0.0;
    double m_phaseStart = 0.0;  // clock time the phase began
    double m_lastAway = 0.0;    // clock time the axis was last outside the band of its goal
    double m_last = 0.0;        // latest reading of the axis
    StepResponse m_response;
    QString m_error;
};

} // namespace slew::tuning

Q_DECLARE_METATYPE(slew::tuning::PositionSample)
Q_DECLARE_METATYPE(slew::tuning::StepResponse)
