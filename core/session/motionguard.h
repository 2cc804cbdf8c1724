// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Watches one axis while Slew drives it (a go-to, a jog, a tracker's move)
// for what most controllers never report: an axis that does not move
// (jammed, iced, a burnt relay, a slipping clutch) and one that runs the
// wrong way (a reversed feedback pot or motor). A G-5500 on a GS-232 or an
// Arduino Easycomm board has no status register and no stall detection: a
// jammed axis keeps its relay energised until someone notices. Slew stops
// it instead (rotatorsession.h holds the axis until the operator clears it).
//
//   - No motion: driven, and not moved by leastProgressDeg the way it is
//     driven (towards the target, or the jog's way) within noMotionSeconds,
//     while further from the target than a controller's deadband may leave
//     it (deadbandDeg): so a jam within that of the target is not seen.
//     A new target on the same side (a tracker's next point, a jog's next
//     leg) does not restart that time: only progress does.
//   - Runaway: driven, and back from the furthest it came the way it is
//     driven by more than runawayDeg, going on the wrong way (not turning
//     back) for runawaySeconds. An axis told to turn round coasts on the
//     old way first, and turns back; a loop past its target turns with the
//     way it is driven; a reversed motor or pot keeps going.
//
// Pure logic on the readings it is given, in the link's time (a
// simulator's stepped clock in tests).

#include <QString>

#include <optional>

namespace slew::session {

struct MotionGuardSettings {
    bool enabled = true;
    double leastProgressDeg = 0.5;
    // A G-5500's azimuth turns about 6°/s, its elevation about 4°/s: 5 s
    // is a good many degrees of travel, and longer than any start-up.
    double noMotionSeconds = 5.0;
    double runawayDeg = 2.0;
    double runawaySeconds = 2.0;
    // A controller may come to rest this far short of its target by its own
    // design (a deadband: a Micro-2g's can be several degrees), or not start
    // for a step smaller than it: no motion this close is not judged.
    double deadbandDeg = 8.0;

    friend bool operator==(const MotionGuardSettings &, const MotionGuardSettings &) = default;
};

struct MotionFault {
    enum class Kind { NoMotion, Runaway };
    Kind kind = Kind::NoMotion;
    double seconds = 0;       // how long it was seen
    double at = 0;            // the axis' reading then
    std::optional<double> towards; // the target, for a go-to
    int direction = 0;        // +1 or -1, the way it was driven; 0: the controller's own way
};

class AxisMotionGuard {
public:
    void setSettings(const MotionGuardSettings &settings) { m_settings = settings; }
    const MotionGuardSettings &settings() const { return m_settings; }

    // Driven from `position` towards `target` (a go-to) or, without one, in
    // `direction` (+1 or -1: a jog), from `nowS`. A target within `arrivedDeg` of the position is not a drive.
    void drive(double nowS, double position, std::optional<double> target, int direction, double arrivedDeg);
    // Driven by the controller's own command to where it rests at
    // `restsAt` (its park), reached whichever way round it chooses: arrival
    // is judged by bearing (0° and 360° alike), and no way is the wrong one.
    void driveByController(double nowS, double position, double restsAt, double arrivedDeg);
    // Not driven any more: stopped, arrived, the link gone.
    void release() { m_driven = false; }
    bool isDriven() const { return m_driven; }

    // A fresh reading. A fault seen releases the guard (its axis is to be
    // stopped); arrival within arrivedDeg releases it too.
    std::optional<MotionFault> reading(double nowS, double position);

private:
    // +1 or -1: towards the target from `position`, or the jog's way.
    int wayAt(double position) const;
    void restart(double nowS, double position, int way);
    std::optional<MotionFault> noMotion(double nowS, double position);

    MotionGuardSettings m_settings;
    bool m_driven = false;
    std::optional<double> m_target;
    std::optional<double> m_restsAt; // a controller's own move ends here, by bearing
    int m_jogWay = 0;
    double m_arrivedDeg = 1.0;
    int m_way = 0;               // the way it is driven now
    double m_progressFrom = 0;   // the reading at the last progress
    double m_progressSince = 0;  // and when
    double m_furthest = 0;       // the furthest reading the way it is driven (times m_way)
    std::optional<double> m_backSince; // since when it is back from there by over runawayDeg, not turning back
    double m_worst = 0;                // the furthest back it has gone since then (times m_way)
};

// "Azimuth did not move for 5.0 s while driven towards 120.0°, at 80.2°:
// stopped"; "Elevation ran the wrong way for 2.0 s while driven up, now at
// 12.3°: stopped".
QString describeMotionFault(bool azimuth, const MotionFault &fault);

} // namespace slew::session
