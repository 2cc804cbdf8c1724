// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every option's long name, written once. The table that declares the
// options (slewcommandline.cpp) and every program that reads them back
// (parser.value(opt::connect)) take the name from here: a name mistyped in
// a program then fails to compile instead of silently reading nothing.
// tests/layering/check-option-names.cmake fails when a program writes one
// as a string literal again.
//
// The names are without dashes, as QCommandLineParser takes them; a
// message shows one as commandLineLabel(opt::connect) gives it, "--connect".

#include <QString>

namespace slew::cli::opt {

// The rotator and its link: the window, the service, --tune, slewctl.
inline const QString connect = QStringLiteral("connect");
inline const QString dialect = QStringLiteral("dialect");
inline const QString profile = QStringLiteral("profile");
inline const QString limits = QStringLiteral("limits");
inline const QString gotoAzEl = QStringLiteral("goto"); // `goto` is C++'s
inline const QString timeout = QStringLiteral("timeout");

// The rotctld server for trackers.
inline const QString rotctldListen = QStringLiteral("rotctld-listen");
inline const QString rotctldAllow = QStringLiteral("rotctld-allow");
inline const QString rotctldMaxClients = QStringLiteral("rotctld-max-clients");
inline const QString rotors = QStringLiteral("rotors");

// The window's screenshot (slew, slew --remote).
inline const QString screenshot = QStringLiteral("screenshot");
inline const QString settleMs = QStringLiteral("settle-ms");

// The station, the sky and the station clock.
inline const QString qth = QStringLiteral("qth");
inline const QString horizon = QStringLiteral("horizon");
inline const QString tle = QStringLiteral("tle");
inline const QString clockStart = QStringLiteral("clock-start");
inline const QString clockRate = QStringLiteral("clock-rate");
inline const QString start = QStringLiteral("start"); // --passes, --schedule; --where's alias of time
inline const QString time = QStringLiteral("time");   // --where; --passes' alias of start
inline const QString hours = QStringLiteral("hours");
inline const QString minEl = QStringLiteral("min-el");
inline const QString aosEl = QStringLiteral("aos-el");
inline const QString refraction = QStringLiteral("refraction");
inline const QString json = QStringLiteral("json");

// Tracking and the schedule.
inline const QString track = QStringLiteral("track");
inline const QString guard = QStringLiteral("guard");
inline const QString maxElementAge = QStringLiteral("max-element-age");

// Pass records.
inline const QString passDb = QStringLiteral("pass-db");
inline const QString passKeepDays = QStringLiteral("pass-keep-days");
inline const QString out = QStringLiteral("out");

// The radio (--headless --radio; slewctl --radio).
inline const QString radio = QStringLiteral("radio");
inline const QString downlink = QStringLiteral("downlink");
inline const QString uplink = QStringLiteral("uplink");
inline const QString downlinkMode = QStringLiteral("downlink-mode");
inline const QString uplinkMode = QStringLiteral("uplink-mode");
inline const QString doppler = QStringLiteral("doppler");
inline const QString uplinkFollows = QStringLiteral("uplink-follows");
inline const QString transponderInvert = QStringLiteral("transponder-invert");
inline const QString radioVfos = QStringLiteral("radio-vfos");
inline const QString radioRestore = QStringLiteral("radio-restore");
inline const QString downlinkOffset = QStringLiteral("downlink-offset");
inline const QString uplinkOffset = QStringLiteral("uplink-offset");
inline const QString transponders = QStringLiteral("transponders");
inline const QString transponder = QStringLiteral("transponder");

// The broker.
inline const QString mqtt = QStringLiteral("mqtt");
inline const QString stationName = QStringLiteral("station-name");
inline const QString mqttPasswordFile = QStringLiteral("mqtt-password-file");

// The options that choose a mode of slew, and the service's config file.
inline const QString headless = QStringLiteral("headless");
inline const QString config = QStringLiteral("config");
inline const QString tune = QStringLiteral("tune");
inline const QString passes = QStringLiteral("passes");
inline const QString where = QStringLiteral("where");
inline const QString schedule = QStringLiteral("schedule");
inline const QString passReport = QStringLiteral("pass-report");
inline const QString remote = QStringLiteral("remote");
inline const QString updateElements = QStringLiteral("update-elements");
inline const QString updateTransponders = QStringLiteral("update-transponders");
inline const QString exportElements = QStringLiteral("export-elements");

// What the modes take besides.
inline const QString axis = QStringLiteral("axis");   // --tune
inline const QString apply = QStringLiteral("apply"); // --tune
inline const QString step = QStringLiteral("step");   // --tune
inline const QString format = QStringLiteral("format"); // --export-elements

// slew-sim's own; the simulator's options come from core/sim's table.
inline const QString listen = QStringLiteral("listen");
inline const QString pty = QStringLiteral("pty");
inline const QString listenDialect = QStringLiteral("listen-dialect");
inline const QString logReceived = QStringLiteral("log-received");
inline const QString maxClients = QStringLiteral("max-clients");

// QCommandLineParser's own, from addHelpOption() and addVersionOption().
inline const QString help = QStringLiteral("help");
inline const QString version = QStringLiteral("version");

} // namespace slew::cli::opt
