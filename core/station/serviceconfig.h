// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the station service is asked to run, from its command line or its
// config file (app/slew_headless.cpp reads both into this), and the parsers
// for the options whose syntax is the station's own.

#include "radiooptions.h"
#include "remoteoperation.h"

#include "model/rotatorlimits.h"
#include "model/rotatorprofile.h"
#include "sky/elementage.h"
#include "sky/site.h"
#include "tracking/tracktarget.h"

#include <QHostAddress>
#include <QList>

#include <optional>

namespace slew::station {

struct ServiceConfig {
    model::RotatorProfile profile;     // its uri is the link to open
    QHostAddress rotctldAddress = QHostAddress(QHostAddress::LocalHost);
    quint16 rotctldPort = 0;
    bool rotctldEnabled = false;
    QList<QHostAddress> allowedClients; // empty: any
    int rotctldMaxClients = 32;         // RotctldServer::kDefaultMaxClients
    std::optional<sky::Site> station; // --qth / `qth =`: where the antenna stands
    // --rotors: the rotors of a multi-rotor controller to serve, each with a
    // session and a rotctld port of its own: rotctldPort, the next port, and
    // so on (each a free port of its own when rotctldPort is 0). Empty: the
    // one rotor the URI names, or the controller's default.
    QList<int> rotors;
    // --track: follow every pass of a satellite, the sun or the moon with
    // the (first) rotor until SIGTERM; given more than once, the passes of
    // all of them by a schedule, the first the highest priority
    // (schedulerunner.h). Needs the station.
    struct Track {
        QList<tracking::TrackTarget> targets; // at least one
        const tracking::TrackTarget &target() const { return targets.first(); }
        double minElevationDeg = 0;
        double guardSeconds = 30; // --guard: between two passes of a schedule
        double maxElementAgeDays = sky::kElementAgeLimitDays; // --max-element-age
        std::optional<double> clockStartJulian; // --clock-start: a rehearsal
        double clockRate = 1.0;                 // --clock-rate
    };
    std::optional<Track> track;
    // --radio and what goes with it: the radio tuned for Doppler while the
    // tracked satellite is up. Needs a satellite's --track.
    std::optional<RadioOptions> radio;
    // --pass-db: where every tracked pass is recorded. Empty: the default
    // file (records/passrecordstore.h), skipped with a log line when it
    // cannot be used; a file named here that cannot be used stops the start.
    QString passRecords;
    int passKeepDays = 90; // --pass-keep-days
    // --mqtt and what goes with it: the station published and commanded
    // over an MQTT broker (remoteoperation.h).
    std::optional<RemoteOptions> remote;
};

// "AZMIN:AZMAX,ELMIN:ELMAX" (`--limits 0:450,0:180`) as limits, checked;
// nothing (and why in *error) otherwise.
std::optional<model::RotatorLimits> parseLimits(const QString &text, QString *error);

// "1,2,4" or "1-4" as rotor numbers 1..4, each once, in the order given;
// nothing (and why in *error) for anything else.
std::optional<QList<int>> parseRotorList(const QString &text, QString *error);

} // namespace slew::station
