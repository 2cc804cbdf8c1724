// SPDX-License-Identifier: GPL-3.0-or-later
#include "simulatoroptions.h"

#include "input/finitenumber.h"

#include "rotatormodels.h"
#include "simclock.h"

#include "protocol/spidcodec.h"

#include <QStringList>

#include <cmath>
#include <limits>

namespace slew::sim {

namespace {

using protocol::Dialect;

// The model comes first: slew-sim applies its flags in this order, and the
// URI reader takes it first too, so the other items adjust the preset.
const std::vector<SimulatorOptionInfo> kOptions = {
    {"model", "name", "class of rotator: g5500 (default, 6.2/2.7 deg/s), satnogs (30 deg/s) or heavy (2/1 deg/s)"},
    {"drive", "kind", "worm (default: self-locking, stops when released) or free (spur or direct drive: coasts)"},
    {"control", "kind",
     "servo (default: a speed loop follows the position loop) or relay (full speed or off: on beyond 0.5 deg "
     "from the target, off within 0.1 deg, as a G-5500's own control box behind a GS-232-style board)"},
    {"kp", "gain", "initial proportional gain of both axes (CW1/CW4)"},
    {"ki", "gain", "initial integral gain of both axes (CW2/CW5)"},
    {"kd", "gain", "initial derivative gain of both axes (CW3/CW6)"},
    {"az_max", "degrees", "azimuth range end, 360..450 (above 360 is overlap)"},
    {"el_max", "degrees", "elevation range end, 90 or 180"},
    {"ticks_per_deg", "ticks", "encoder resolution, reported by \\?ENC (1..100000)"},
    {"max_speed", "deg/s", "driver speed cap of both axes (default: the model's)"},
    {"max_accel", "deg/s^2", "driver acceleration cap of both axes (default: the model's)"},
    {"park_az", "degrees", "azimuth park position (CW7)"},
    {"park_el", "degrees", "elevation park position (CW8)"},
    {"start_az", "degrees", "azimuth at start"},
    {"start_el", "degrees", "elevation at start"},
    {"dialect", "name",
     "easycomm1, easycomm2, easycomm3, satnogs, gs232a, gs232b, micro2g (the four-rotor Micro-2g controller), "
     "or the binary SPID rot2prog, rot1prog (azimuth only) and md01 (MD-01/02 in ROT2 mode)"},
    {"firmware", "name",
     "generic (default: as the documents say), k3ng or satnogs. k3ng answers as K3NG's Arduino firmware does, in its "
     "Easycom emulation (dialect easycomm2: `+aaa.a +eee.e`, each answer ended by the byte that ended its query, `?` "
     "for what it lacks) or its Yaesu one (gs232a, gs232b: `AZ=aaaEL=eee`, `?>` for what it lacks), and stops within "
     "3 degrees of an azimuth target. satnogs (dialect satnogs) answers as the SatNOGS firmware v2.2 does: GS4 for a "
     "whole move, CR10 and CR11 read as register 1, a line heard only 9 ms after its last reply"},
    {"spid_pulses", "n", "rot2prog, md01: the resolution the controller reports in PH/PV, pulses per degree: 1, 2 (default), 4 or 10"},
    {"md01_log", "", "md01: write a text log line before every reply, as some MD-01 firmware does"},
    {"state_file", "path", "micro2g: keep the controller's calibration, presets and tolerances in this file across restarts"},
    {"unsolicited", "", "push changed fields unsolicited (easycomm3)"},
    {"echo", "", "send every received byte back before the answer, as some serial adapters do"},
    {"checksum", "", "frame every reply with the XOR checksum *HH and refuse received lines without a good one (line dialects only)"},
    {"baud", "rate", "pace bytes to a serial line of this rate (0: unpaced)"},
    {"clock", "mode", "wall (default) or manual: time moves only when a test advances it"},
    {"time_scale", "factor",
     "wall clock: simulated seconds per real second, 1 (default) to 20; everything simulated (motion, latency, "
     "line pacing) runs that much faster"},
    {"seed", "number", "seed of the noise and link fault generators"},
    {"jam", "axes", "az, el or both: the axis jams; a motor error follows"},
    {"jam_after", "seconds", "how long a driven jammed axis takes to become a motor error"},
    {"freeze", "axes", "az, el or both: the encoder reading freezes (sensor error)"},
    {"noise", "degrees", "encoder noise on both axes (sensor error when it jumps)"},
    {"noise_az", "degrees", "encoder noise on azimuth"},
    {"noise_el", "degrees", "encoder noise on elevation"},
    {"no_endstop", "axes", "az, el or both: the lower limit switch is missing (homing error)"},
    {"reversed", "axes", "az, el or both: the motor is wired the wrong way round; the axis runs away from its target"},
    {"backlash", "degrees", "gear play of both axes"},
    {"backlash_az", "degrees", "gear play of azimuth"},
    {"backlash_el", "degrees", "gear play of elevation"},
    {"latency_ms", "ms", "delay before every reply"},
    {"drop_rate", "share", "share of reply bytes lost, 0..1"},
    {"garbage_rate", "share", "share of reply bytes followed by a random byte, 0..1"},
    {"corrupt_rate", "share", "share of reply lines with one bit flipped, 0..1"},
    {"drop_after", "seconds", "cut each connection this long after it opened"},
};

QString bad(QStringView name, QStringView value, const QString &why)
{
    return QStringLiteral("option %1=%2: %3").arg(name, value, why);
}

bool toNumber(QStringView text, double *out)
{
    const std::optional<double> v = input::finiteNumber(text);
    if (!v)
        return false;
    *out = *v;
    return true;
}

bool toSwitch(QStringView text, bool *out)
{
    if (text.isEmpty() || text == u"1" || text.compare(u"true", Qt::CaseInsensitive) == 0
        || text.compare(u"yes", Qt::CaseInsensitive) == 0 || text.compare(u"on", Qt::CaseInsensitive) == 0) {
        *out = true;
        return true;
    }
    if (text == u"0" || text.compare(u"false", Qt::CaseInsensitive) == 0
        || text.compare(u"no", Qt::CaseInsensitive) == 0 || text.compare(u"off", Qt::CaseInsensitive) == 0) {
        *out = false;
        return true;
    }
    return false;
}

struct AxisChoice {
    bool azimuth = false;
    bool elevation = false;
};

bool toAxes(QStringView text, AxisChoice *out)
{
    AxisChoice c;
    for (QStringView part : text.split(u',', Qt::SkipEmptyParts)) {
        if (part.compare(u"az", Qt::CaseInsensitive) == 0 || part.compare(u"azimuth", Qt::CaseInsensitive) == 0)
            c.azimuth = true;
        else if (part.compare(u"el", Qt::CaseInsensitive) == 0 || part.compare(u"elevation", Qt::CaseInsensitive) == 0)
            c.elevation = true;
        else if (part.compare(u"both", Qt::CaseInsensitive) == 0)
            c.azimuth = c.elevation = true;
        else if (part.compare(u"none", Qt::CaseInsensitive) != 0)
            return false;
    }
    *out = c;
    return true;
}

} // namespace

const std::vector<SimulatorOptionInfo> &simulatorOptionList()
{
    return kOptions;
}

QString applySimulatorOption(SimulatorOptions &o, QStringView rawName, QStringView value)
{
    const QString name = rawName.toString().replace(u'-', u'_').toLower();
    RotatorConfig &r = o.rotator;

    auto number = [&](double lo, double hi, double *out) -> QString {
        double v = 0;
        if (!toNumber(value, &v))
            return bad(name, value, QStringLiteral("not a number"));
        if (v < lo || v > hi)
            return bad(name, value, QStringLiteral("outside %1..%2").arg(lo).arg(hi));
        *out = v;
        return {};
    };
    auto gain = [&](double PidGains::*field) -> QString {
        double v = 0;
        if (QString e = number(0.0, 10000.0, &v); !e.isEmpty())
            return e;
        r.azimuthGains.*field = v;
        r.elevationGains.*field = v;
        return {};
    };
    auto axes = [&](bool AxisFaults::*field) -> QString {
        AxisChoice c;
        bool all = false;
        if (toSwitch(value, &all) && !value.isEmpty())
            c.azimuth = c.elevation = all;
        else if (!toAxes(value, &c))
            return bad(name, value, QStringLiteral("expected az, el, both or none"));
        o.azimuthFaults.*field = c.azimuth;
        o.elevationFaults.*field = c.elevation;
        return {};
    };
    auto magnitude = [&](double AxisFaults::*field, bool az, bool el) -> QString {
        double v = 0;
        if (QString e = number(0.0, 90.0, &v); !e.isEmpty())
            return e;
        if (az)
            o.azimuthFaults.*field = v;
        if (el)
            o.elevationFaults.*field = v;
        return {};
    };
    auto both = [&](double AxisPlant::*field, double lo, double hi) -> QString {
        double v = 0;
        if (QString e = number(lo, hi, &v); !e.isEmpty())
            return e;
        r.azimuth.*field = v;
        r.elevation.*field = v;
        return {};
    };
    const double big = std::numeric_limits<double>::max();

    if (name == u"model") {
        const RotatorModel *model = findRotatorModel(value);
        if (!model)
            return bad(name, value, QStringLiteral("expected %1").arg(rotatorModelNameList()));
        applyRotatorModel(r, *model);
        return {};
    }
    if (name == u"drive") {
        DriveTrain train = DriveTrain::SelfLocking;
        if (value.compare(u"worm", Qt::CaseInsensitive) == 0)
            train = DriveTrain::SelfLocking;
        else if (value.compare(u"free", Qt::CaseInsensitive) == 0)
            train = DriveTrain::FreeRunning;
        else
            return bad(name, value, QStringLiteral("expected worm or free"));
        r.azimuth.driveTrain = r.elevation.driveTrain = train;
        return {};
    }
    if (name == u"control") {
        MotorControl control = MotorControl::Servo;
        if (value.compare(u"servo", Qt::CaseInsensitive) == 0)
            control = MotorControl::Servo;
        else if (value.compare(u"relay", Qt::CaseInsensitive) == 0)
            control = MotorControl::Relay;
        else
            return bad(name, value, QStringLiteral("expected servo or relay"));
        r.azimuth.control = r.elevation.control = control;
        return {};
    }
    if (name == u"kp")
        return gain(&PidGains::kp);
    if (name == u"ki")
        return gain(&PidGains::ki);
    if (name == u"kd")
        return gain(&PidGains::kd);
    if (name == u"az_max")
        return number(360.0, 450.0, &r.azimuth.maxDegrees);
    if (name == u"el_max") {
        double v = 0;
        if (!toNumber(value, &v) || (v != 90.0 && v != 180.0))
            return bad(name, value, QStringLiteral("must be 90 or 180"));
        r.elevation.maxDegrees = v;
        return {};
    }
    if (name == u"ticks_per_deg")
        return both(&AxisPlant::ticksPerDegree, 1.0, 100000.0);
    if (name == u"max_speed")
        return both(&AxisPlant::maxSpeed, 0.1, 360.0);
    if (name == u"max_accel")
        return both(&AxisPlant::maxAcceleration, 0.1, 3600.0);
    if (name == u"park_az")
        return number(0.0, 450.0, &r.parkAzimuth);
    if (name == u"park_el")
        return number(0.0, 180.0, &r.parkElevation);
    if (name == u"start_az")
        return number(0.0, 450.0, &r.startAzimuth);
    if (name == u"start_el")
        return number(0.0, 180.0, &r.startElevation);
    if (name == u"dialect") {
        const auto d = protocol::dialectFromName(value);
        if (!d)
            return bad(name, value, QStringLiteral("expected one of: %1").arg(protocol::dialectNameList()));
        // rotctld is a network peer in front of a controller, not one.
        if (*d == protocol::Dialect::Rotctld)
            return bad(name, value, QStringLiteral("the simulator plays a controller; rotctld is reached with rotctld://"));
        o.dialect = *d;
        return {};
    }
    if (name == u"firmware") {
        const auto firmware = protocol::firmwareFromName(value);
        if (!firmware)
            return bad(name, value, QStringLiteral("expected one of: %1").arg(protocol::firmwareNameList()));
        o.firmware = *firmware;
        return {};
    }
    if (name == u"spid_pulses") {
        double v = 0;
        if (!toNumber(value, &v) || v != std::floor(v) || !protocol::spid::isResolution(int(v)))
            return bad(name, value, QStringLiteral("must be 1, 2, 4 or 10"));
        o.spidPulses = int(v);
        return {};
    }
    if (name == u"md01_log")
        return toSwitch(value, &o.md01Log) ? QString() : bad(name, value, QStringLiteral("expected 1 or 0"));
    if (name == u"state_file") {
        if (value.isEmpty())
            return bad(name, value, QStringLiteral("expected a file path"));
        o.stateFile = value.toString();
        return {};
    }
    if (name == u"unsolicited")
        return toSwitch(value, &o.unsolicited) ? QString() : bad(name, value, QStringLiteral("expected 1 or 0"));
    if (name == u"echo")
        return toSwitch(value, &o.echo) ? QString() : bad(name, value, QStringLiteral("expected 1 or 0"));
    if (name == u"checksum")
        return toSwitch(value, &o.checksum) ? QString() : bad(name, value, QStringLiteral("expected 1 or 0"));
    if (name == u"baud") {
        double v = 0;
        if (QString e = number(0.0, 4000000.0, &v); !e.isEmpty())
            return e;
        o.baud = int(v);
        return {};
    }
    if (name == u"clock") {
        if (value == u"manual")
            o.manualClock = true;
        else if (value == u"wall")
            o.manualClock = false;
        else
            return bad(name, value, QStringLiteral("expected manual or wall"));
        return {};
    }
    if (name == u"time_scale") {
        double v = 0;
        if (QString e = number(1.0, SimClock::maxTimeScale, &v); !e.isEmpty())
            return e;
        o.timeScale = v;
        return {};
    }
    if (name == u"seed") {
        double v = 0;
        if (QString e = number(0.0, 4294967295.0, &v); !e.isEmpty())
            return e;
        r.seed = std::uint32_t(v);
        return {};
    }
    if (name == u"jam")
        return axes(&AxisFaults::jam);
    if (name == u"jam_after") {
        double v = 0;
        if (QString e = number(0.01, 3600.0, &v); !e.isEmpty())
            return e;
        o.azimuthFaults.stallSeconds = o.elevationFaults.stallSeconds = v;
        return {};
    }
    if (name == u"freeze")
        return axes(&AxisFaults::encoderFreeze);
    if (name == u"no_endstop")
        return axes(&AxisFaults::missingEndStop);
    if (name == u"reversed")
        return axes(&AxisFaults::reversedMotor);
    if (name == u"noise")
        return magnitude(&AxisFaults::encoderNoise, true, true);
    if (name == u"noise_az")
        return magnitude(&AxisFaults::encoderNoise, true, false);
    if (name == u"noise_el")
        return magnitude(&AxisFaults::encoderNoise, false, true);
    if (name == u"backlash")
        return magnitude(&AxisFaults::backlash, true, true);
    if (name == u"backlash_az")
        return magnitude(&AxisFaults::backlash, true, false);
    if (name == u"backlash_el")
        return magnitude(&AxisFaults::backlash, false, true);
    if (name == u"latency_ms") {
        double v = 0;
        if (QString e = number(0.0, 60000.0, &v); !e.isEmpty())
            return e;
        o.link.latency = v / 1000.0;
        return {};
    }
    if (name == u"drop_rate")
        return number(0.0, 1.0, &o.link.dropRate);
    if (name == u"garbage_rate")
        return number(0.0, 1.0, &o.link.garbageRate);
    if (name == u"corrupt_rate")
        return number(0.0, 1.0, &o.link.corruptRate);
    if (name == u"drop_after")
        return number(0.0, big, &o.link.dropAfter);
    return QStringLiteral("unknown option %1").arg(rawName);
}

QString checkSimulatorOptions(const SimulatorOptions &o)
{
    if (const QString conflict = protocol::firmwareDialectConflict(o.firmware, o.dialect); !conflict.isEmpty())
        return QStringLiteral("firmware: %1").arg(conflict);
    return {};
}

} // namespace slew::sim
