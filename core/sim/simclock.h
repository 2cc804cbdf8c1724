#pragma once
// Simulated time. In Manual mode time moves only when someone calls
// advance(), so a test decides exactly how much happens between two checks
// and never sleeps. In WallClock mode it follows a monotonic clock, which is
// what the servers use, and has no timer of its own: whoever needs the
// simulation brought up to date (a command or a query arriving) reads now()
// and catches up. A time scale above 1 makes simulated time run that many
// times faster than the wall clock (a demo, or a test that waits on a long
// slew, need not wait).

#include <QElapsedTimer>
#include <QObject>

namespace slew::sim {

class SimClock : public QObject {
    Q_OBJECT
public:
    enum class Mode { Manual, WallClock };

    static constexpr double maxTimeScale = 20.0;

    // timeScale: simulated seconds per wall-clock second (WallClock mode only).
    explicit SimClock(Mode mode, double timeScale = 1.0, QObject *parent = nullptr);

    Mode mode() const { return m_mode; }
    bool isManual() const { return m_mode == Mode::Manual; }
    double timeScale() const { return m_timeScale; }

    // Seconds since the clock started.
    double now() const;

    // Manual mode: moves time on and emits advanced(). Ignored on a wall clock.
    void advance(double seconds);

    // Wall clock: from now on, run this many times faster (1 to
    // maxTimeScale), going on from the present reading, so nothing simulated
    // jumps: the rotator carries on from where it is. The window's Time
    // controller keeps a running simulator at the station clock's rate this
    // way. Ignored on a manual clock, which moves only when advanced.
    void setTimeScale(double timeScale);

signals:
    // A manual clock moved on: the rotator catches up, connections release
    // what is due. A wall clock never says so: it moves by itself.
    void advanced(double now);

private:
    Mode m_mode;
    double m_timeScale = 1.0;
    double m_manualNow = 0.0;
    double m_wallBase = 0.0;      // simulated seconds at the last change of scale
    qint64 m_wallBaseAtNs = 0;    // m_elapsed's reading then
    QElapsedTimer m_elapsed;
};

} // namespace slew::sim
