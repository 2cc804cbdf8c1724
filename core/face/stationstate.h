// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a face shows of a station's rotator, tracking and radio now, as
// values: the link, where the antenna points and where it is sent, its
// travel and park, what Slew tracks and the pass, the alarms and the holds,
// the radio's link and hold and where it is tuned. A station in this
// process fills it from its parts (station/stationstatereader.h); one on a
// broker publishes it as JSON (remote/stationstate.h).

#include "model/rotatorlimits.h"

#include <QPointF>
#include <QString>
#include <QStringList>

#include <optional>

namespace slew::face {

struct StationState {
    qint64 unixMs = 0;
    // The station's own clock at unixMs, when it is not the wall clock (a
    // rehearsal), and how fast it runs (0 while paused): the pass times
    // below are in its time, and a viewer counts down by it.
    std::optional<qint64> clockMs;
    double clockRate = 1.0;
    // disconnected, connecting, connected, reconnecting: the rotator's link.
    QString link = QStringLiteral("disconnected");
    QString linkDetail; // why it failed, when it did
    std::optional<QPointF> position; // az, el in the pointing frame
    bool stale = true;
    std::optional<QPointF> target;
    bool moving = false;
    // What the controller says each axis is doing, in words ("moving,
    // pointing"): none from a controller that reports no status, and no
    // elevation from one whose status is not per axis (the azimuth's then
    // stands for both).
    std::optional<QString> azimuthStatus, elevationStatus;
    // An axis' status reports an error; the controller's error register
    // says its homing (RESET) failed, and what it says, in words.
    bool axisError = false;
    bool homingFailed = false;
    QString controllerErrors;
    model::RotatorLimits limits; // the travel in force: the profile's, narrowed by the controller's
    // The profile's own travel, which a controller's narrower report does
    // not change: a preset is stored against it, for the day the report widens.
    model::RotatorLimits profileLimits;
    std::optional<QPointF> park;
    bool azimuthOnly = false;
    // What the controller can do, once it has said (before that, what most
    // can): its dialect's name, for what a face says about it; whether a
    // jog's speed is the operator's (else the controller turns at its own);
    // whether it can find its end stops (home); whether it parks by a
    // command of its own (else Slew parks it by a go-to).
    QString dialect;
    bool probed = false;
    bool jogSpeed = true;
    bool canHome = true;
    bool parkCommand = true;
    // off, planning, waiting, tracking, done.
    QString tracking = QStringLiteral("off");
    QString trackingTarget;
    std::optional<int> trackingNorad; // a satellite's catalogue number, up to nine digits
    std::optional<qint64> passAosMs, passLosMs;
    std::optional<double> passMaxElevation;
    QStringList alarms;
    bool severe = false;
    bool operatorHold = false;
    // The motion guard stopped an axis (session/motionguard.h) and holds it
    // until the operator clears it (StationFace::clearMotionFaults); what it
    // saw is among the alarms.
    bool motionHeld = false;
    QString controllerVersion;
    QString slewVersion;
    // The radio (station/dopplerradio.h): its link, named as the rotator's,
    // or "none" when the station has no radio set; empty when not said (a
    // station older than these fields). Whether the operator holds its
    // dial (the Doppler steering tunes nothing then), whether the steering
    // tunes it now, and the frequencies Slew last set on it or read from it
    // (Hz), when known.
    QString radioLink;
    bool radioHeld = false;
    bool radioSteering = false;
    std::optional<double> radioReceiveHz, radioTransmitHz;
};

// A state carries at most this many alarms.
inline constexpr int kMostAlarms = 32;

} // namespace slew::face
