// SPDX-License-Identifier: GPL-3.0-or-later
#include "slewcommandline.h"

#include "optionnames.h"

#include "console/consolecommand.h"
#include "console/radiocommand.h"
#include "bridge/rotctldserver.h"
#include "protocol/dialect.h"
#include "sim/simulatoroptions.h"
#include "sim/simulatortcpserver.h"
#include "input/boundedfile.h"
#include "sky/boundeddownload.h"
#include "sky/elementsetsources.h"
#include "radio/transponderimport.h"
#include "radio/transpondersources.h"
#include "records/passrecordstore.h"
#include "tracking/stationclock.h"

#include <QCommandLineParser>

namespace slew::cli {
namespace {

// Options that several modes share, written once.
ProgramOption connectOption(const QString &description)
{
    return {{opt::connect}, QStringLiteral("URI"), description, true};
}

ProgramOption dialectOption()
{
    return {{opt::dialect},
            QStringLiteral("name"),
            QStringLiteral("The controller's command set: %1.").arg(protocol::dialectNameList()),
            true};
}

ProgramOption profileOption()
{
    return {{opt::profile},
            QStringLiteral("file"),
            QStringLiteral("A rotator profile (JSON, as the window exports it): limits, overlap, park, dialect."),
            true};
}

ProgramOption rotctldListenOption()
{
    return {{opt::rotctldListen},
            QStringLiteral("address:port"),
            QStringLiteral("Let trackers (Gpredict, the SatNOGS client, rotctl) steer through Slew: serve Hamlib's "
                           "rotctld protocol on ADDRESS:PORT. The address is 127.0.0.1 unless one is named."),
            true};
}

ProgramOption limitsOption()
{
    return {{opt::limits},
            QStringLiteral("travel"),
            QStringLiteral("The rotator's travel for this run, AZMIN:AZMAX,ELMIN:ELMAX: 0:450,0:180 for an overlap and "
                           "flip rotator, -180:180,0:90 for a south stop. It replaces the profile's, and every move is "
                           "checked against it."),
            true};
}

ProgramOption clockStartOption(const QString &description)
{
    return {{opt::clockStart}, QStringLiteral("time"), description};
}

// `keepingPace` says how the rotator keeps up with a faster clock.
ProgramOption clockRateOption(const QString &keepingPace)
{
    return {{opt::clockRate},
            QStringLiteral("n"),
            QStringLiteral("With --clock-start: run the station clock n times faster, 1 to %1 (default 1). %2")
                .arg(tracking::StationClock::kMaxRate)
                .arg(keepingPace)};
}

ProgramOption stationOption(const QString &description, bool inConfigFile = false)
{
    return {{opt::qth}, QStringLiteral("station"), description, inConfigFile};
}

ProgramOption horizonOption(bool inConfigFile = false)
{
    return {{opt::horizon},
            QStringLiteral("file"),
            QStringLiteral("The station's horizon mask: a line `azimuth elevation` (degrees) a point, # for comments; "
                           "the mask is read straight between the points and round through north, and a wall is "
                           "two points at one azimuth. AOS and LOS are where a target clears it."),
            inConfigFile};
}

ProgramOption rotctldMaxClientsOption()
{
    return {{opt::rotctldMaxClients},
            QStringLiteral("n"),
            QStringLiteral("How many trackers may be connected at once (default %1); one more reads RPRT -9 and is "
                           "closed.")
                .arg(bridge::RotctldServer::kDefaultMaxClients),
            true};
}

// Where passes are recorded, for the window, the service and the report.
ProgramOption passDbOption(const QString &description, bool inConfigFile = false)
{
    return {{opt::passDb}, QStringLiteral("file"), description, inConfigFile};
}

ProgramOption passKeepDaysOption(bool inConfigFile = false)
{
    return {{opt::passKeepDays},
            QStringLiteral("days"),
            QStringLiteral("How long the recorded passes' samples (the antenna's path, for the picture) are kept, 1 "
                           "to %1 days (default %2); the passes' figures stay.")
                .arg(records::PassRecordStore::kMaxKeepDays)
                .arg(records::PassRecordStore::kDefaultKeepDays),
            inConfigFile};
}

// One rule for the window, the service and the plan printed
// (sky/elementage.h); the window keeps its own under Sky → Element sets.
ProgramOption maxElementAgeOption(bool inConfigFile = false)
{
    return {{opt::maxElementAge},
            QStringLiteral("days"),
            QStringLiteral("A satellite is tracked only while its elements are at most this many days from their "
                           "epoch (either side: a rehearsal of an old pass with new elements is as far off), 0.5 to "
                           "365 (default 14); a pass further out is dropped, with the reason."),
            inConfigFile};
}

ProgramOption tleOption(const QString &purpose)
{
    return {{opt::tle},
            QStringLiteral("file"),
            purpose + QStringLiteral(" Element sets in any form, told from the content: TLE or three-line sets "
                                     "(Alpha-5 numbers too), or GP data as CSV, OMM XML, JSON or OMM KVN with "
                                     "catalogue numbers of up to nine digits. Sets that cannot be read are reported "
                                     "and skipped. Without it, the cached copies of the window's element-set sources "
                                     "are used (Sky, Element sets; slew --update-elements).")};
}

ProgramMode makeWindowMode()
{
    ProgramMode mode;
    mode.title = QStringLiteral("The operator window");
    mode.synopsis = QStringLiteral("slew [--connect URI] [--dialect NAME] [--profile FILE] "
                                   "[--limits AZMIN:AZMAX,ELMIN:ELMAX] [--rotctld-listen ADDRESS:PORT] [--goto AZ,EL] "
                                   "[--clock-start ISO8601 [--clock-rate N]] [--screenshot FILE.png [--settle-ms MS]]");
    mode.description = QStringLiteral(
        "Opens the operator window: the polar plot, the jog pad, go-to, Stop, Park and Home, the controller's "
        "configuration, live telemetry charts, the traffic log, the rotctld server and the setup and tuning "
        "wizard. Without --connect it opens the last connection, or the built-in simulator the first time. "
        "The same program runs as a station service (slew --headless --help), tunes a rotator without a "
        "window (slew --tune URI --help), predicts passes (slew --passes SAT --help, slew --where SAT --help), "
        "refreshes the element sets the window uses (slew --update-elements [URL...], slew --update-elements --help), "
        "plans several targets by priority (slew --schedule --track A --track B --help), draws a recorded pass "
        "(slew --pass-report ID --help), and opens a station on an MQTT broker (slew --remote URL --help).");
    mode.options = {
        connectOption(QStringLiteral("Connect to URI at start: serial:/dev/ttyUSB0?baud=19200, tcp://HOST:PORT, "
                                     "rotctld://HOST:PORT or sim:?az_max=450.")),
        dialectOption(),
        profileOption(),
        limitsOption(),
        rotctldListenOption(),
        rotctldMaxClientsOption(),
        {{opt::gotoAzEl}, QStringLiteral("az,el"), QStringLiteral("Once connected, move to this position.")},
        clockStartOption(QStringLiteral(
            "Start in rehearsal: the station clock starts at this UTC instant (ISO 8601) and runs; the passes, the "
            "plot and tracking follow it, and an orange line says so. Sky, Time controller changes it or goes back "
            "to real time.")),
        clockRateOption(QStringLiteral("The built-in simulator (sim:) runs as many times faster, from where it is, "
                                       "so the antenna keeps up with the plan.")),
        stationOption(QStringLiteral("Set the station (as Sky, Station does, and kept): LAT,LON or LAT,LON,HEIGHT_M, "
                                     "or a Maidenhead locator of 4, 6 or 8 characters (JO65hq).")),
        passDbOption(QStringLiteral("Record every tracked pass in this SQLite file, and show it in the History tab "
                                    "(default: passes.sqlite in the data directory, ~/.local/share/Slew/slew/). "
                                    "When the station service records into it, the window shows it and records "
                                    "nothing.")),
        passKeepDaysOption(),
        {{opt::screenshot},
         QStringLiteral("FILE.png"),
         QStringLiteral("Render the window to a PNG after the settle time, then exit. Needs no display.")},
        {{opt::settleMs},
         QStringLiteral("ms"),
         QStringLiteral("How long to run before the screenshot (default 3000).")},
    };
    return mode;
}

ProgramMode makeHeadlessMode()
{
    ProgramMode mode;
    mode.title = QStringLiteral("Station service");
    mode.synopsis = QStringLiteral("slew --headless [--config FILE] [--connect URI] [--dialect NAME] "
                                   "[--profile FILE] [--limits AZMIN:AZMAX,ELMIN:ELMAX] [--rotctld-listen ADDRESS:PORT] "
                                   "[--rotctld-allow ADDRESSES] [--rotors LIST] [--qth STATION [--tle FILE] "
                                   "--track CATNR|NAME|sun|moon|azel:AZ,EL|radec:RA,DEC [--track ...] [--horizon FILE] [--min-el DEG] [--guard S] [--max-element-age DAYS] [--clock-start ISO8601] [--clock-rate N] "
                                   "[--radio URI (--downlink FREQ [--uplink FREQ] | --transponders FILE [--transponder NAME])]] "
                                   "[--mqtt mqtts://USER@HOST:8883 --station-name NAME [--mqtt-password-file FILE]]");
    mode.description = QStringLiteral(
        "Runs Slew with no window and no display, as a station service: it keeps the link to the rotator open "
        "and reconnects after a loss, serves the rotctld protocol to trackers, and logs one line per event on "
        "standard output. On SIGTERM or SIGINT it stops the rotator, waits for the stop to leave the link, and "
        "exits.");
    mode.options = {
        {{opt::headless}, {}, QStringLiteral("Run as a station service, without a window.")},
        {{opt::config},
         QStringLiteral("file"),
         QStringLiteral("Read settings from FILE, one `name = value` a line, where name is one of connect, dialect, "
                        "profile, limits, rotctld-listen, rotctld-allow, rotctld-max-clients, rotors, qth, horizon, tle, track (a line a target), min-el, guard, max-element-age, and the radio's "
                        "radio, downlink, uplink, downlink-mode, uplink-mode, doppler, uplink-follows, downlink-offset, "
                        "uplink-offset, transponders, transponder, transponder-invert, radio-restore, radio-vfos, "
                        "pass-db, pass-keep-days, and the broker's mqtt, station-name, mqtt-password-file. Options on "
                        "the command line win over the file.")},
        connectOption(QStringLiteral("The rotator's link URI (default sim:, the built-in simulator).")),
        dialectOption(),
        profileOption(),
        rotctldListenOption(),
        {{opt::rotctldAllow},
         QStringLiteral("addresses"),
         QStringLiteral("Comma-separated client addresses the rotctld server accepts (default: any)."),
         true},
        rotctldMaxClientsOption(),
        limitsOption(),
        {{opt::track},
         QStringLiteral("target"),
         QStringLiteral("Track every pass of a satellite (a catalogue number, an AMSAT name or any part of a name, of --tle's sets or "
                        "else the cached ones of the window's sources), the sun "
                        "or the moon until SIGTERM: plan each pass before AOS (never the long way round, the flip or "
                        "the overlap where the travel has them), pre-position, follow, and log the plan, AOS, and at "
                        "LOS the pointing error (RMS and worst). Also azel:AZ,EL (hold a fixed direction) and "
                        "radec:RA,DEC (a radio source: RA in hours, or degrees with a d; Dec in degrees; J2000; "
                        "23:23:24 style accepted). Needs --qth. Remote trackers on the rotctld port are "
                        "held off while a pass is tracked. Given more than once (in a config file, a line each), "
                        "the targets are scheduled by priority, the first highest: where passes overlap the higher "
                        "priority keeps its pass, a pass the rotator cannot reach in time from the one before is "
                        "dropped, and every decision is logged (slew --schedule prints the same plan)."),
         true,
         true},
        horizonOption(true),
        {{opt::guard},
         QStringLiteral("seconds"),
         QStringLiteral("With --track given more than once: the least time between two passes of the schedule, "
                        "besides the rotator's move, 0 to 3600 (default 30)."),
         true},
        maxElementAgeOption(true),
        [] {
            ProgramOption tle = tleOption(QStringLiteral("The satellites of --track, and those a remote track (--mqtt) "
                                                         "may name."));
            tle.inConfigFile = true;
            return tle;
        }(),
        {{opt::minEl},
         QStringLiteral("degrees"),
         QStringLiteral("With --track: passes must climb above this, -5 to 90 (default 0)."),
         true},
        clockStartOption(QStringLiteral("With --track: start the station clock at this UTC instant (ISO 8601) and "
                                        "let it run, to rehearse a pass on the simulator or on the rotator.")),
        clockRateOption(QStringLiteral("To keep pace, run the simulator at the same time scale (sim:?time_scale=n, "
                                       "slew-sim --time-scale n).")),
        {{opt::radio},
         QStringLiteral("uri"),
         QStringLiteral("With --track of a satellite: keep this radio on its Doppler-corrected frequencies while a "
                        "pass is tracked, and log the Doppler error at LOS. rigctld://HOST:PORT (Hamlib's rigctld, "
                        "port 4532 by default), hamlib:MODEL?device=PATH&baud=N (libhamlib in process; MODEL as "
                        "rigctl -l lists it), sim: (a simulated radio), or controller (the rotator controller's own "
                        "UP and DN: Easycomm II and III). The frequencies come from --downlink and --uplink or from "
                        "--transponders."),
         true},
        {{opt::downlink},
         QStringLiteral("freq"),
         QStringLiteral("With --radio: what the satellite transmits, as 145.8M, 435.125 MHz, 1296200k or hertz."),
         true},
        {{opt::uplink},
         QStringLiteral("freq"),
         QStringLiteral("With --radio: what the satellite listens on; the radio is put in split and transmits there, "
                        "Doppler-corrected."),
         true},
        {{opt::downlinkMode},
         QStringLiteral("mode"),
         QStringLiteral("With --radio: the receive mode at AOS (a Hamlib name: USB, LSB, CW, FM, AM, PKTUSB...)."),
         true},
        {{opt::uplinkMode}, QStringLiteral("mode"), QStringLiteral("With --radio: the transmit mode at AOS."), true},
        {{opt::doppler},
         QStringLiteral("paths"),
         QStringLiteral("With --radio: correct both paths (the default), the downlink only or the uplink only "
                        "(both, downlink, uplink)."),
         true},
        {{opt::uplinkFollows},
         QStringLiteral("how"),
         QStringLiteral("With --radio: when the operator turns the receive dial, move the uplink the same way, the "
                        "opposite way (an inverting transponder) or not at all (same, opposite, no). A transponder "
                        "from --transponders sets this itself."),
         true},
        {{opt::transponderInvert},
         {},
         QStringLiteral("With --radio: the frequencies given are an inverting linear transponder's: the uplink follows "
                        "the operator's dial the opposite way (as --uplink-follows opposite)."),
         true},
        {{opt::radioVfos},
         QStringLiteral("layout"),
         QStringLiteral("With --radio: split (the default: receive on VFOA, transmit on VFOB with split on, as "
                        "Gpredict does) or main-sub (receive on Sub, transmit on Main, no split: the IC-9700 and "
                        "its kind in satellite mode, turned on at the radio; through rigctld it needs rigctld -o)."),
         true},
        {{opt::radioRestore},
         {},
         QStringLiteral("With --radio: after each pass put the radio back on the frequency it was found on before AOS, "
                        "with split off again if Slew turned it on. Without it the radio is left where the pass ended."),
         true},
        {{opt::downlinkOffset},
         QStringLiteral("freq"),
         QStringLiteral("With --radio: a calibration offset added to the downlink (signed, as -1.2k; within 1 MHz)."),
         true},
        {{opt::uplinkOffset}, QStringLiteral("freq"), QStringLiteral("With --radio: the same for the uplink."), true},
        {{opt::transponders},
         QStringLiteral("file"),
         QStringLiteral("With --radio: the satellite's transponders from a SatNOGS DB transmitter list (.json) or a "
                        "Gpredict .trsp file; may be given more than once. Its first alive linear transponder is "
                        "tuned (else its first alive one) unless --transponder names another."),
         true},
        {{opt::transponder},
         QStringLiteral("name"),
         QStringLiteral("With --transponders: the transponder to tune, by the start of its description."),
         true},
        {{opt::rotors},
         QStringLiteral("list"),
         QStringLiteral("Serve these rotors of a multi-rotor controller (the Micro-2g's 1 to 4, as 1,2,4 or 1-4) over "
                        "the one link, each with a session and a rotctld port of its own: the first rotor on "
                        "--rotctld-listen's port, the next on the port after it, and so on (each a free port of its "
                        "own with port 0). The --connect URI then names no rotor. Log lines say which rotor they "
                        "are about."),
         true},
        stationOption(QStringLiteral("Where the antenna stands: LAT,LON or LAT,LON,HEIGHT_M (degrees north and east, "
                                     "metres above the WGS-84 ellipsoid), or a Maidenhead locator of 4, 6 or 8 "
                                     "characters (JO65hq). Checked at start and logged."),
                      true),
        passDbOption(QStringLiteral("Record every tracked pass in this SQLite file: its times, the pointing and "
                                    "Doppler figures, how it ended, and the antenna's path, committed every 2 s "
                                    "(default: passes.sqlite in the service user's data directory, "
                                    "~/.local/share/Slew/slew/). A file named here that cannot be used stops the "
                                    "service at start; the default one is skipped with a log line."),
                     true),
        passKeepDaysOption(true),
        {{opt::mqtt},
         QStringLiteral("url"),
         QStringLiteral("Publish the station on an MQTT broker and obey commands from it (docs/remote.md): "
                        "mqtts://USER@HOST:8883?cafile=CA.pem, TLS checked against the CA file (or the system's "
                        "authorities). Plain mqtt:// only to a broker on this machine. Under slew/NAME/: state "
                        "and online (retained), telemetry, command and reply. The broker's access list decides who "
                        "may watch and who may command. Needs --station-name."),
         true},
        {{opt::stationName},
         QStringLiteral("name"),
         QStringLiteral("With --mqtt: the station's name on the broker, its topic level (letters, digits, -, _ and .)."),
         true},
        {{opt::mqttPasswordFile},
         QStringLiteral("file"),
         QStringLiteral("With --mqtt: the broker password is the first line of FILE, which other users may not "
                        "read. Without it, the environment variable SLEW_MQTT_PASSWORD; never on the command line."),
         true},
    };
    return mode;
}

ProgramMode makePassReportMode()
{
    ProgramMode mode;
    mode.title = QStringLiteral("The picture of a recorded pass");
    mode.synopsis = QStringLiteral("slew --pass-report ID --out FILE.png [--pass-db FILE]");
    mode.description = QStringLiteral(
        "Draws a pass that the station recorded: the target's track across the sky and the antenna's path on a "
        "polar plot (north up, azimuth clockwise, the horizon at the rim), the pointing error against minutes "
        "from AOS with AOS, TCA and LOS marked, and the pass's figures. Needs no display. ID is the pass's "
        "number, as the window's History tab lists it. Nothing is written for a pass that is not recorded or "
        "whose samples are gone.");
    mode.options = {
        {{opt::passReport}, QStringLiteral("id"), QStringLiteral("The recorded pass to draw.")},
        {{opt::out}, QStringLiteral("file"), QStringLiteral("The PNG to write.")},
        passDbOption(QStringLiteral("The pass records to read (default: passes.sqlite in the data directory). "
                                    "Read only: a file the station service records into can be read meanwhile.")),
    };
    return mode;
}

ProgramMode makeTuneMode()
{
    ProgramMode mode;
    mode.title = QStringLiteral("Tuning without a window");
    mode.synopsis = QStringLiteral("slew --tune URI [--axis az|el|both] [--apply] [--step DEGREES] [--dialect NAME] "
                                   "[--profile FILE]");
    mode.description = QStringLiteral(
        "Measures a step on each axis, fits a model, proposes PID gains, tries them, and prints rise time, "
        "overshoot, settling time and steady-state error before and after. Without --apply the old gains are "
        "written back. Ctrl-C stops the rotator and restores the old gains.");
    mode.options = {
        {{opt::tune}, QStringLiteral("URI"), QStringLiteral("The rotator's link URI.")},
        {{opt::axis}, QStringLiteral("axis"), QStringLiteral("az, el or both (default both).")},
        {{opt::apply}, {}, QStringLiteral("Keep the new gains on the controller.")},
        {{opt::dialect},
         QStringLiteral("name"),
         QStringLiteral("easycomm3 (default) or satnogs: the dialects with the CR and CW registers.")},
        profileOption(),
        {{opt::step}, QStringLiteral("degrees"), QStringLiteral("Step size, 0.5 to 30 (default 2).")},
    };
    return mode;
}

ProgramOption qthOption()
{
    return stationOption(
        QStringLiteral("Where the station is: LAT,LON or LAT,LON,HEIGHT_M (degrees north and east, metres above "
                       "the WGS-84 ellipsoid), or a Maidenhead locator of 4, 6 or 8 characters (JO65hq). Without it, the "
                       "station set in the window (Sky, Station) is used."));
}


ProgramMode makePassesMode()
{
    ProgramMode mode;
    mode.title = QStringLiteral("Pass prediction");
    mode.synopsis = QStringLiteral("slew --passes SAT|all|sun|moon --qth STATION [--tle FILE] [--hours 24] "
                                   "[--min-el 10] [--aos-el 0] [--start ISO8601] [--json]");
    mode.description = QStringLiteral(
        "Prints the passes of a satellite over the station: AOS, the highest point (TCA) and LOS with their "
        "times (UTC) and azimuths, the maximum elevation and whether the satellite is in sunlight. SAT is a "
        "catalogue number (Alpha-5 too) or a name it goes by (AO-91, ZARYA, OSCAR 7, part of a name), in any "
        "case; \"all\" predicts every satellite, "
        "sorted by AOS. For the sun and the moon it prints rise, culmination and set, and needs no --tle.");
    mode.options = {
        {{opt::passes}, QStringLiteral("sat"), QStringLiteral("The satellite, \"all\", \"sun\" or \"moon\".")},
        qthOption(),
        tleOption(QStringLiteral("The satellites.")),
        {{opt::hours}, QStringLiteral("hours"), QStringLiteral("How far ahead to look, 0.1 to 720 (default 24).")},
        {{opt::minEl},
         QStringLiteral("degrees"),
         QStringLiteral("Only passes whose highest point climbs to this elevation, -5 to 90 (default 10; "
                        "every rising for the sun and the moon). AOS and LOS stay where --aos-el puts them.")},
        {{opt::aosEl},
         QStringLiteral("degrees"),
         QStringLiteral("AOS and LOS where the elevation crosses this, -5 to 90 (default 0, the horizon, as the "
                        "window's pass table has them; the almanac's -0.833 for the sun and the moon).")},
        // --time too: --where's name for the same idea, so neither has to be
        // remembered for the right command.
        {{opt::start, opt::time},
         QStringLiteral("time"),
         QStringLiteral("Start of the search, ISO 8601 in UTC (default now); --time is the same.")},
        {{opt::json}, {}, QStringLiteral("Print JSON instead of a table.")},
        horizonOption(),
    };
    return mode;
}

ProgramMode makeScheduleMode()
{
    ProgramMode mode;
    mode.title = QStringLiteral("A schedule of several targets");
    mode.synopsis = QStringLiteral("slew --schedule --track TARGET [--track TARGET ...] --qth STATION [--tle FILE] "
                                   "[--horizon FILE] [--start ISO8601] [--hours 24] [--min-el DEG] [--guard S] [--max-element-age DAYS] "
                                   "[--profile FILE | --limits AZMIN:AZMAX,ELMIN:ELMAX] [--json]");
    mode.description = QStringLiteral(
        "Prints the plan the station service follows for these targets, the first the highest priority: every "
        "pass in the window, taken or dropped, and why it was dropped (an overlap with a higher priority, the "
        "rotator unable to get there in time from the pass before, below the horizon mask, elements too old, no "
        "path the rotator can drive). The rotator is the profile's (its travel, speeds and accelerations), or the "
        "default G-5500 class one; --limits sets its travel. The station and its horizon fall back to what the "
        "window keeps (Sky, Station), as --passes does.");
    mode.options = {
        {{opt::schedule}, {}, QStringLiteral("Print a schedule.")},
        {{opt::track},
         QStringLiteral("target"),
         QStringLiteral("A target: a satellite (a catalogue number, an AMSAT name or any part of a name), sun, moon, "
                        "azel:AZ,EL or radec:RA,DEC. Once for each target, the first the highest priority."),
         false,
         true},
        qthOption(),
        tleOption(QStringLiteral("The satellites among the targets.")),
        horizonOption(),
        {{opt::start, opt::time},
         QStringLiteral("time"),
         QStringLiteral("Start of the plan, ISO 8601 in UTC (default now).")},
        {{opt::hours}, QStringLiteral("hours"), QStringLiteral("How far ahead to plan, 0.1 to 168 (default 24).")},
        {{opt::minEl},
         QStringLiteral("degrees"),
         QStringLiteral("Passes must climb above this elevation, -5 to 90 (default 0).")},
        {{opt::guard},
         QStringLiteral("seconds"),
         QStringLiteral("The least time between two passes, besides the rotator's move, 0 to 3600 (default 30).")},
        maxElementAgeOption(),
        profileOption(),
        limitsOption(),
        {{opt::json}, {}, QStringLiteral("Print JSON instead of a line a pass.")},
    };
    return mode;
}

ProgramMode makeWhereMode()
{
    ProgramMode mode;
    mode.title = QStringLiteral("Where is it now");
    mode.synopsis = QStringLiteral("slew --where SAT|sun|moon --qth STATION [--tle FILE] [--time ISO8601] "
                                   "[--refraction] [--json]");
    mode.description = QStringLiteral(
        "Prints where a satellite, the sun or the moon is seen from the station: azimuth and elevation in "
        "degrees, range in km and range-rate in km/s (positive when receding), and for a satellite the point "
        "beneath it and whether it is in sunlight.");
    mode.options = {
        {{opt::where}, QStringLiteral("sat"), QStringLiteral("The satellite, \"sun\" or \"moon\".")},
        qthOption(),
        tleOption(QStringLiteral("The satellites; not read for the sun and the moon.")),
        {{opt::time, opt::start},
         QStringLiteral("time"),
         QStringLiteral("ISO 8601 in UTC (default now); --start is the same, as --passes takes it.")},
        {{opt::refraction}, {}, QStringLiteral("Add standard atmospheric refraction to the elevation.")},
        {{opt::json}, {}, QStringLiteral("Print JSON instead of text.")},
    };
    return mode;
}

ProgramMode makeUpdateElementsMode()
{
    ProgramMode mode;
    mode.title = QStringLiteral("Refreshing element sets");
    mode.synopsis = QStringLiteral("slew --update-elements [URL...]");
    mode.description =
        QStringLiteral(
            "Refreshes element-set sources (http, https or file URLs) into the cache the window, --passes, --where, "
            "--schedule and --track read, with no window, so a station can refresh from a timer. A source may "
            "answer in any of the five forms (TLE, CSV, OMM XML, JSON, OMM KVN), told from its content: CelesTrak's "
            "GP queries (gp.php?GROUP=amateur&FORMAT=csv or FORMAT=json, gp.php?CATNR=25544&FORMAT=csv, and the "
            "supplemental sup-gp.php?FILE=starlink&FORMAT=csv) carry catalogue numbers of up to nine digits, which "
            "FORMAT=tle cannot. The URLs given are refreshed and join the sources listed in the window (Sky, Element "
            "sets); without one, those are refreshed. It prints one line per source: the URL, how many sets it holds, and "
            "whether the new copy replaced the cached one or the cached copy was kept, and why. A download is "
            "given up when it is larger than %1, sends no data for %2 or takes longer than %3 in all. A new copy "
            "replaces the cached one only when it reads cleanly (at most one entry in ten refused, not an HTML "
            "page) and keeps at least half of the cached copy's satellites; otherwise the cached copy stays.")
            .arg(slew::input::byteSizeText(sky::kMaxElementSetBytes), sky::durationText(sky::kElementSetSilenceMs),
                 sky::durationText(sky::kElementSetTransferMs));
    mode.options = {
        {{opt::updateElements},
         {},
         QStringLiteral("Refresh the element sets from the URLs that follow, or from the window's sources.")},
    };
    return mode;
}

ProgramMode makeExportElementsMode()
{
    ProgramMode mode;
    mode.title = QStringLiteral("Writing element sets for other programs");
    mode.synopsis = QStringLiteral("slew --export-elements [--format tle|csv|json|xml|kvn] [--tle FILE] [--out FILE] "
                                   "[SAT...]");
    mode.description = QStringLiteral(
        "Writes the element sets Slew holds (--tle's file, else the cached copies of the window's sources), or "
        "the satellites named, in one form, so a program that reads only TLEs can still be fed from Slew. A TLE "
        "carries catalogue numbers up to 99999 as digits and up to 339999 in Alpha-5 (A0000 is 100000); a set "
        "above that, which no TLE can carry, is left out and named on the standard error. The other forms carry "
        "every set whole: CSV and JSON as CelesTrak writes them, XML and KVN as CCSDS OMMs.");
    mode.options = {
        {{opt::exportElements}, {}, QStringLiteral("Write element sets.")},
        {{opt::format},
         QStringLiteral("form"),
         QStringLiteral("tle (the default; three lines a set), csv, json, xml (OMM XML) or kvn (OMM KVN).")},
        tleOption(QStringLiteral("The element sets to write from.")),
        {{opt::out},
         QStringLiteral("file"),
         QStringLiteral("Write to this file (whole or not at all) rather than the standard output.")},
    };
    return mode;
}

ProgramMode makeUpdateTranspondersMode()
{
    ProgramMode mode;
    mode.title = QStringLiteral("Refreshing transponders");
    mode.synopsis = QStringLiteral("slew --update-transponders [URL...]");
    mode.description =
        QStringLiteral(
            "Refreshes transponder sources into the cache the window and the station service read (beside the "
            "element sets'): SatNOGS DB's transmitter list (%1, or a saved copy as a file URL) and Gpredict .trsp "
            "files (file:///path/25544.trsp, named after the satellite's catalogue number). The URLs given are "
            "kept as the sources; without a URL it refreshes the kept ones, or SatNOGS DB's list when none are "
            "kept. One line per source, as for the element sets. A download is given up when it is larger than "
            "%2, sends no data for %3 or takes longer than %4 in all; a new copy replaces the cached one only when "
            "at most one entry in ten is skipped and it keeps at least half of the cached copy's satellites. "
            "`slew --headless --radio URI` tunes from this cache when it is given neither --downlink nor "
            "--transponders.")
            .arg(QLatin1String(radio::kSatnogsTransmittersUrl), slew::input::byteSizeText(radio::kLargestTransmitterList),
                 sky::durationText(radio::kTransponderSilenceMs), sky::durationText(radio::kTransponderTransferMs));
    mode.options = {
        {{opt::updateTransponders},
         {},
         QStringLiteral("Refresh the transponders from the URLs that follow, or from the kept sources.")},
    };
    return mode;
}

ProgramMode makeRemoteMode()
{
    ProgramMode mode;
    mode.title = QStringLiteral("A station on a broker");
    mode.synopsis = QStringLiteral("slew --remote mqtts://USER@HOST:8883[/NAME][?cafile=CA.pem] [--mqtt-password-file FILE] "
                                   "[--screenshot FILE.png [--settle-ms MS]]");
    mode.description = QStringLiteral(
        "Opens a station that a station service publishes on an MQTT broker (slew --headless --mqtt): with /NAME, "
        "that station's window (its plot, position, alarms and telemetry, go-to, jog, Stop, Park, Home and "
        "tracking), which says plainly that it is remote and how old the last state is; without a name, the "
        "station network: every station the broker knows, each on a small plot. The broker's access list decides "
        "whether this account may command or only watch. The password comes from --mqtt-password-file or "
        "SLEW_MQTT_PASSWORD, never the command line. See docs/remote.md.");
    mode.options = {
        {{opt::remote},
         QStringLiteral("url"),
         QStringLiteral("The broker and, after a slash, the station: mqtts://USER@HOST:8883/NAME?cafile=CA.pem. Plain "
                        "mqtt:// only to a broker on this machine.")},
        {{opt::mqttPasswordFile},
         QStringLiteral("file"),
         QStringLiteral("The broker password is the first line of FILE, which other users may not read; without "
                        "it, SLEW_MQTT_PASSWORD.")},
        {{opt::screenshot},
         QStringLiteral("FILE.png"),
         QStringLiteral("Render the window to a PNG after the settle time, then exit. Needs no display.")},
        {{opt::settleMs},
         QStringLiteral("ms"),
         QStringLiteral("How long to run before the screenshot (default 3000).")},
    };
    return mode;
}

ProgramMode makeSimMode()
{
    ProgramMode mode;
    mode.title = QStringLiteral("Options");
    mode.synopsis = QStringLiteral("slew-sim [--listen ADDRESS:PORT] [--pty PATH] [--dialect NAME] "
                                   "[SIMULATOR OPTIONS]");
    mode.description = QStringLiteral(
        "Simulated az/el rotator, served on TCP and/or a pseudo-terminal. It speaks the same bytes as a real "
        "controller, so any program that drives a rotator (Slew, Hamlib's rotctl and rotctld, Gpredict through "
        "rotctld) can be tried without hardware. It prints one ready line with the address and the terminal path, "
        "and exits on SIGTERM or SIGINT with a count of the lines it received.");
    mode.options = {
        {{opt::listen},
         QStringLiteral("address:port"),
         QStringLiteral("Serve TCP on ADDRESS:PORT; port 0 picks a free one (default 127.0.0.1:4533 when --pty is "
                        "not given).")},
        {{opt::pty},
         QStringLiteral("path"),
         QStringLiteral("Serve a pseudo-terminal, symlinked at PATH (open it as a serial port).")},
        {{opt::listenDialect},
         QStringLiteral("name"),
         QStringLiteral("Dialect of the TCP endpoint if not --dialect's.")},
        {{opt::logReceived}, QStringLiteral("file"), QStringLiteral("Write every line received to FILE.")},
        {{opt::maxClients},
         QStringLiteral("n"),
         QStringLiteral("TCP clients at once (default %1); one more is refused and closed.")
             .arg(sim::SimulatorTcpServer::kDefaultMaxClients)},
    };
    // The simulator's own options, which sim: URIs take too (`--az-max 450`
    // here is `sim:?az_max=450` there). The clock option is for tests in the
    // same process: a server always runs on the wall clock.
    for (const sim::SimulatorOptionInfo &info : sim::simulatorOptionList()) {
        const QString name = QString::fromLatin1(info.name);
        if (name == u"clock")
            continue;
        QStringList names{QString(name).replace(u'_', u'-')};
        if (name.contains(u'_'))
            names << name;
        QString description = QString::fromLatin1(info.description);
        description[0] = description[0].toUpper();
        mode.options.append({names, QString::fromLatin1(info.valueName), description + u'.'});
    }
    return mode;
}

QString seeAlso()
{
    return QStringLiteral("rotctl(1), rotctld(1), the Slew README and docs/protocol.md, docs/simulator.md and "
                          "docs/tuning.md in the source.");
}

} // namespace

const ProgramDescription &slewProgram()
{
    static const ProgramDescription program = [] {
        ProgramDescription p;
        p.name = QStringLiteral("slew");
        p.summary = QStringLiteral("controller for az/el antenna rotators");
        p.description = QStringLiteral(
            "Slew drives az/el antenna rotators that speak Easycomm I, II or III, the SatNOGS variant, Yaesu "
            "GS-232A/B, the Micro-2g controller's command set, or SPID's binary Rot2Prog and Rot1Prog (MD-01, "
            "MD-02), over a serial port, over TCP, through Hamlib's rotctld, or its own simulator when no "
            "rotator is attached. Every move, from the operator, a tracker, a preset or a raw command, is checked "
            "against the rotator's limits before a byte is sent.");
        // The manual's order; each mode is its own accessor's, never found by
        // its place here.
        p.modes = {slewWindowMode(),
                   slewHeadlessMode(),
                   slewTuneMode(),
                   slewPassesMode(),
                   slewWhereMode(),
                   slewUpdateElementsMode(),
                   slewUpdateTranspondersMode(),
                   slewScheduleMode(),
                   slewPassReportMode(),
                   slewRemoteMode(),
                   slewExportElementsMode()};
        p.sections = {
            {QStringLiteral("Links"),
             QStringLiteral(
                 "A link is named by a URI, the same on the command line, in "
                 "the window and in profiles:\n"
                 "\n"
                 "  "
                 "serial:/dev/"
                 "ttyUSB0?baud=19200&data=8&parity=none&stop=1&flow=none\n"
                 "  tcp://HOST:PORT\n"
                 "  rotctld://HOST:PORT\n"
                 "  sim:?az_max=450&el_max=180\n"
                 "\n"
                 "The simulator's options are listed in slew-sim(1).")},
            {QStringLiteral("Keyboard"),
             QStringLiteral("In the operator window:\n"
                            "\n"
                            "  Esc          Stop, always\n"
                            "  Space        Stop; in a text field only while "
                            "the rotator moves\n"
                            "  arrow keys   jog while held (one start and one "
                            "stop, however the keyboard repeats)\n"
                            "  1 to 9       go to the preset of that number\n"
                            "  Enter        in the go-to fields: go (the focus "
                            "then leaves the field)\n"
                            "  Ctrl+D       in the target picker: keep the "
                            "target as a favourite")},
            {QStringLiteral("Files"),
             QStringLiteral(
                 "  /etc/slew/NAME.conf\n"
                 "\n"
                 "Settings of the station service slew-station@NAME.service, "
                 "read with --config. "
                 "/etc/slew/example.conf shows every setting.\n"
                 "\n"
                 "  ~/.config/Slew/slew.conf\n"
                 "\n"
                 "The window's remembered connection, presets, station and "
                 "preferences, and the list of "
                 "element-set sources that slew --update-elements refreshes. "
                 "One that cannot be read is "
                 "moved aside to slew.conf.broken-DATE, never deleted.\n"
                 "\n"
                 "  ~/.config/Slew/satellite-names.txt\n"
                 "\n"
                 "The operator's own names for satellites, a catalogue number "
                 "and a name a line ('#' "
                 "begins a comment), read after the built-in AMSAT names: a "
                 "name given here is found by "
                 "every search. A bad line is said and skipped.\n"
                 "\n"
                 "  ~/.cache/Slew/slew/element-sets/\n"
                 "\n"
                 "The last good copy of each element-set source, shared by the "
                 "window and "
                 "slew --update-elements.\n"
                 "\n"
                 "  ~/.local/share/Slew/slew/passes.sqlite\n"
                 "\n"
                 "The record of every tracked pass (SQLite), unless --pass-db "
                 "names another; the station "
                 "service's is under its state directory, "
                 "/var/lib/slew-station/NAME/.\n"
                 "\n"
                 "  rotator.json\n"
                 "\n"
                 "A rotator profile, wherever the window's Configuration tab "
                 "exports it (Export profile) "
                 "and --profile reads it from: the link, dialect, limits, "
                 "overlap and park.")},
            {QStringLiteral("Exit status"),
             QStringLiteral("0 when Slew ends normally, 1 when a tuning run "
                            "fails or is cancelled, --passes or "
                            "--where finds no satellite to answer for, "
                            "--update-elements could not refresh a "
                            "source (each is named), or --pass-report finds no "
                            "such pass or no samples of it, 2 for "
                            "a bad option, a bad config file, a server that "
                            "cannot listen, --update-elements with no "
                            "sources, or pass records that cannot be read.")},
            {QStringLiteral("Examples"),
             QStringLiteral("  slew --connect serial:/dev/ttyUSB0?baud=9600 "
                            "--dialect easycomm2\n"
                            "  slew --headless --connect tcp://192.0.2.10:4533 "
                            "--rotctld-listen 127.0.0.1:4533\n"
                            "  systemctl enable --now slew-station@example\n"
                            "  slew --tune sim:?kp=12&ki=1&kd=1 --axis az\n"
                            "  slew --passes \"ISS (ZARYA)\" --qth JO65hq "
                            "--tle amateur.txt --hours 48\n"
                            "  slew --where moon --qth 55.69,12.63,20\n"
                            "  slew --connect sim: --qth JO65hq --clock-start "
                            "2026-11-25T12:00:00Z --clock-rate 5\n"
                            "  slew --update-elements "
                            "'https://celestrak.org/NORAD/elements/"
                            "gp.php?GROUP=amateur&FORMAT=csv'\n"
                            "  slew --export-elements --format tle --out "
                            "~/.config/Gpredict/amateur.tle\n"
                            "  slew --pass-report 12 --out pass-12.png\n"
                            "  slew --remote "
                            "'mqtts://alice@broker.example:8883/mast?cafile=/"
                            "etc/slew/broker-ca.pem'")},
            {QStringLiteral("See also"),
             QStringLiteral("slew-sim(1), ") + seeAlso()},
        };
        return p;
    }();
    return program;
}

const ProgramMode &slewWindowMode()
{
    static const ProgramMode mode = makeWindowMode();
    return mode;
}

const ProgramMode &slewHeadlessMode()
{
    static const ProgramMode mode = makeHeadlessMode();
    return mode;
}

const ProgramMode &slewTuneMode()
{
    static const ProgramMode mode = makeTuneMode();
    return mode;
}

const ProgramMode &slewPassesMode()
{
    static const ProgramMode mode = makePassesMode();
    return mode;
}

const ProgramMode &slewWhereMode()
{
    static const ProgramMode mode = makeWhereMode();
    return mode;
}

const ProgramMode &slewUpdateElementsMode()
{
    static const ProgramMode mode = makeUpdateElementsMode();
    return mode;
}

const ProgramMode &slewUpdateTranspondersMode()
{
    static const ProgramMode mode = makeUpdateTranspondersMode();
    return mode;
}

const ProgramMode &slewScheduleMode()
{
    static const ProgramMode mode = makeScheduleMode();
    return mode;
}

const ProgramMode &slewPassReportMode()
{
    static const ProgramMode mode = makePassReportMode();
    return mode;
}

const ProgramMode &slewRemoteMode()
{
    static const ProgramMode mode = makeRemoteMode();
    return mode;
}

const ProgramMode &slewExportElementsMode()
{
    static const ProgramMode mode = makeExportElementsMode();
    return mode;
}

const ProgramDescription &slewSimProgram()
{
    static const ProgramDescription program = [] {
        ProgramDescription p;
        p.name = QStringLiteral("slew-sim");
        p.summary = QStringLiteral("simulated az/el antenna rotator on TCP or a pseudo-terminal");
        p.modes = {slewSimMode()};
        p.description = p.modes.first().description;
        p.sections = {
            {QStringLiteral("Examples"),
             QStringLiteral("  slew-sim --listen 127.0.0.1:4533 --dialect easycomm3\n"
                            "  slew-sim --pty /tmp/rotator --dialect gs232b --baud 9600\n"
                            "  rotctl -m 202 -r /tmp/rotator -s 9600 P 180 30")},
            {QStringLiteral("See also"), QStringLiteral("slew(1), ") + seeAlso()},
        };
        return p;
    }();
    return program;
}

const ProgramMode &slewSimMode()
{
    static const ProgramMode mode = makeSimMode();
    return mode;
}

const ProgramDescription &slewctlProgram()
{
    static const ProgramDescription program = [] {
        ProgramDescription p;
        p.name = QStringLiteral("slewctl");
        p.summary = QStringLiteral("command-line client for az/el antenna rotators");
        ProgramMode mode;
        mode.title = QStringLiteral("Options");
        mode.synopsis = QStringLiteral("slewctl [--json] [--dialect NAME] [--profile FILE] [--timeout SECONDS] URI "
                                       "[COMMAND [ARGUMENTS]] | slewctl [--json] --radio URI [RADIO COMMAND]");
        mode.description = QStringLiteral(
            "Sends one command to a rotator and prints the result, or, without a command, reads commands at a "
            "prompt (or from standard input) until quit. It uses the same core as the Slew window: every move "
            "and every raw line is checked against the rotator's limits before a byte is sent.");
        mode.options = {
            {{opt::json}, {}, QStringLiteral("Print one JSON object a line, for scripts.")},
            dialectOption(),
            profileOption(),
            {{opt::timeout},
             QStringLiteral("seconds"),
             QStringLiteral("How long --wait waits for the rotator to arrive (default 600).")},
            {{opt::radio},
             QStringLiteral("uri"),
             QStringLiteral("Speak to a radio instead of a rotator (rigctld://HOST:PORT, hamlib:MODEL?device=PATH&baud=N, "
                            "sim:): the words that follow are one radio command (see Radio commands), after which "
                            "the frequencies the radio holds are printed.")},
        };
        p.modes = {mode};
        p.description = mode.description;
        QString commands;
        for (const QString &line : console::consoleCommandSummary().split(u'\n', Qt::SkipEmptyParts))
            commands += QStringLiteral("  ") + line + u'\n';
        commands.chop(1);
        QString radioCommands;
        for (const QString &line : console::radioCommandSummary().split(u'\n', Qt::SkipEmptyParts))
            radioCommands += QStringLiteral("  ") + line + u'\n';
        radioCommands.chop(1);
        p.sections = {
            {QStringLiteral("Commands"), commands},
            {QStringLiteral("Radio commands"), radioCommands},
            {QStringLiteral("Exit status"),
             QStringLiteral("0 done; 1 the controller did not answer, a read-back differed or --wait timed out; 2 a "
                            "bad argument; 3 no link to the rotator, or it was lost; 4 the move or line was refused, "
                            "by Slew (nothing was sent) or by the controller (it answered ?).")},
            {QStringLiteral("Examples"),
             QStringLiteral("  slewctl sim: goto 180 30 --wait\n"
                            "  slewctl serial:/dev/ttyUSB0?baud=9600 --dialect easycomm2 get\n"
                            "  slewctl --json tcp://127.0.0.1:4533 watch --interval 0.5\n"
                            "  slewctl sim: raw 'AZ EL'\n"
                            "  slewctl sim: config set 1 0.8\n"
                            "  slewctl --radio rigctld://127.0.0.1:4532 freq 145.8M")},
            {QStringLiteral("See also"), QStringLiteral("slew(1), slew-sim(1), ") + seeAlso()},
        };
        return p;
    }();
    return program;
}

const ProgramMode &slewctlMode()
{
    return slewctlProgram().modes.at(0);
}

void describeTo(QCommandLineParser &parser, const ProgramMode &mode)
{
    parser.setApplicationDescription(mode.description);
    parser.addHelpOption();
    parser.addVersionOption();
    for (const ProgramOption &option : mode.options)
        parser.addOption(option.toQt());
}

void describeTo(QCommandLineParser &parser, const ProgramDescription &program, const ProgramMode &mode)
{
    describeTo(parser, mode);
    for (const ManualSection &section : program.sections) {
        if (section.heading == QLatin1String("Exit status"))
            parser.setApplicationDescription(mode.description + QStringLiteral("\n\nExit status: ") + section.text);
    }
}

} // namespace slew::cli
