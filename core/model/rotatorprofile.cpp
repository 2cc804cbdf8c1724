#include "rotatorprofile.h"

#include "movegate.h"

#include "input/boundedfile.h"

#include <QFile>
#include <QJsonDocument>
#include <QObject>
#include <QSaveFile>

#include <cmath>

namespace slew::model {

namespace {

QJsonObject gainsToJson(const PidGains &g)
{
    return {{"kp", g.kp}, {"ki", g.ki}, {"kd", g.kd}};
}

bool readNumber(const QJsonObject &o, const char *key, double *out, QString *error)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return true;
    if (!v.isDouble() || !std::isfinite(v.toDouble())) {
        *error = QObject::tr("'%1' must be a number").arg(QLatin1String(key));
        return false;
    }
    *out = v.toDouble();
    return true;
}

bool readGains(const QJsonObject &o, const char *key, std::optional<PidGains> *out, QString *error)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined() || v.isNull())
        return true;
    if (!v.isObject()) {
        *error = QObject::tr("'%1' must be an object with kp, ki, kd").arg(QLatin1String(key));
        return false;
    }
    PidGains g;
    const QJsonObject go = v.toObject();
    if (!readNumber(go, "kp", &g.kp, error) || !readNumber(go, "ki", &g.ki, error)
        || !readNumber(go, "kd", &g.kd, error))
        return false;
    *out = g;
    return true;
}

} // namespace

QString RotatorProfile::validate() const
{
    if (QString e = limits.validate(); !e.isEmpty())
        return e;
    if (QString e = protocol::firmwareDialectConflict(firmware, dialect); !e.isEmpty())
        return e;
    for (const std::optional<double> &t : {stopToleranceAzDeg, stopToleranceElDeg})
        if (t && !(*t >= 0.0 && *t <= 10.0))
            return QObject::tr("the controller's stop tolerance must be 0° to 10°");
    if (!MoveGate(limits).pointing(parkAz, parkEl, std::nullopt).allowed())
        return QObject::tr("park position %1°, %2° is outside the limits").arg(parkAz).arg(parkEl);
    if (!(deadbandDeg >= 0.0 && deadbandDeg <= 10.0))
        return QObject::tr("deadband must be 0° to 10°");
    if (pollHz < 1 || pollHz > 50)
        return QObject::tr("poll rate must be 1 to 50 Hz");
    if (!(restPollHz >= 0.1 && restPollHz <= pollHz))
        return QObject::tr("poll rate at rest must be 0.1 Hz to the poll rate (%1 Hz)").arg(pollHz);
    if (!(std::abs(azOffsetDeg) <= 180.0))
        return QObject::tr("azimuth offset must be -180° to 180°");
    if (!(std::abs(elOffsetDeg) <= 20.0))
        return QObject::tr("elevation offset must be -20° to 20°");
    const RotatorMotion &m = motion;
    if (!(m.azSpeedDegS > 0.05 && m.azSpeedDegS <= 100.0 && m.elSpeedDegS > 0.05 && m.elSpeedDegS <= 100.0))
        return QObject::tr("axis speeds must be 0.05 to 100 °/s");
    if (!(m.azAccelDegS2 >= 0.0 && m.azAccelDegS2 <= 1000.0 && m.elAccelDegS2 >= 0.0 && m.elAccelDegS2 <= 1000.0))
        return QObject::tr("axis accelerations must be 0 to 1000 °/s²");
    if (!(m.responseDelayS >= 0.0 && m.responseDelayS <= 10.0))
        return QObject::tr("response delay must be 0 to 10 s");
    if (!(m.trackStepDeg >= 0.0 && m.trackStepDeg <= 10.0))
        return QObject::tr("tracking step must be 0° to 10°");
    return {};
}

QJsonObject RotatorProfile::toJson() const
{
    QJsonObject o{
        {"format", "slew-profile-1"},
        {"name", name},
        {"uri", uri},
        {"dialect", protocol::dialectName(dialect)},
        {"limits", QJsonObject{{"azMin", limits.azMin}, {"azMax", limits.azMax},
                               {"elMin", limits.elMin}, {"elMax", limits.elMax}}},
        {"park", QJsonObject{{"az", parkAz}, {"el", parkEl}}},
        {"southStop", southStop},
        {"deadbandDeg", deadbandDeg},
        {"pollHz", pollHz},
        {"restPollHz", restPollHz},
        {"offsets", QJsonObject{{"az", azOffsetDeg}, {"el", elOffsetDeg}}},
        {"motion", QJsonObject{{"azSpeedDegS", motion.azSpeedDegS}, {"elSpeedDegS", motion.elSpeedDegS},
                               {"azAccelDegS2", motion.azAccelDegS2}, {"elAccelDegS2", motion.elAccelDegS2},
                               {"responseDelayS", motion.responseDelayS},
                               {"drive", motion.drive == RotatorMotion::Drive::Relay ? "relay" : "servo"},
                               {"trackStepDeg", motion.trackStepDeg}}},
    };
    if (firmware != protocol::Firmware::Generic)
        o.insert("firmware", protocol::firmwareName(firmware));
    if (stopToleranceAzDeg || stopToleranceElDeg) {
        QJsonObject t;
        if (stopToleranceAzDeg)
            t.insert("az", *stopToleranceAzDeg);
        if (stopToleranceElDeg)
            t.insert("el", *stopToleranceElDeg);
        o.insert("stopTolerance", t);
    }
    if (azGains)
        o.insert("azGains", gainsToJson(*azGains));
    if (elGains)
        o.insert("elGains", gainsToJson(*elGains));
    return o;
}

std::optional<RotatorProfile> RotatorProfile::fromJson(const QJsonObject &o, QString *error)
{
    QString ignored;
    QString &err = error ? *error : ignored;
    RotatorProfile p;
    if (o.contains("name"))
        p.name = o.value("name").toString(p.name);
    if (o.contains("uri"))
        p.uri = o.value("uri").toString(p.uri);
    if (o.contains("dialect")) {
        const auto d = protocol::dialectFromName(o.value("dialect").toString());
        if (!d) {
            err = QObject::tr("unknown dialect '%1'").arg(o.value("dialect").toString());
            return std::nullopt;
        }
        p.dialect = *d;
    }
    if (o.contains("firmware")) {
        const auto f = protocol::firmwareFromName(o.value("firmware").toString());
        if (!f) {
            err = QObject::tr("unknown firmware '%1' (known: %2)")
                      .arg(o.value("firmware").toString(), protocol::firmwareNameList());
            return std::nullopt;
        }
        p.firmware = *f;
    }
    const QJsonObject lim = o.value("limits").toObject();
    const QJsonObject park = o.value("park").toObject();
    const QJsonObject offsets = o.value("offsets").toObject();
    const QJsonObject motion = o.value("motion").toObject();
    RotatorMotion &m = p.motion;
    double poll = p.pollHz;
    if (!readNumber(lim, "azMin", &p.limits.azMin, &err) || !readNumber(lim, "azMax", &p.limits.azMax, &err)
        || !readNumber(lim, "elMin", &p.limits.elMin, &err) || !readNumber(lim, "elMax", &p.limits.elMax, &err)
        || !readNumber(park, "az", &p.parkAz, &err) || !readNumber(park, "el", &p.parkEl, &err)
        || !readNumber(offsets, "az", &p.azOffsetDeg, &err) || !readNumber(offsets, "el", &p.elOffsetDeg, &err)
        || !readNumber(motion, "azSpeedDegS", &m.azSpeedDegS, &err)
        || !readNumber(motion, "elSpeedDegS", &m.elSpeedDegS, &err)
        || !readNumber(motion, "azAccelDegS2", &m.azAccelDegS2, &err)
        || !readNumber(motion, "elAccelDegS2", &m.elAccelDegS2, &err)
        || !readNumber(motion, "responseDelayS", &m.responseDelayS, &err)
        || !readNumber(motion, "trackStepDeg", &m.trackStepDeg, &err)
        || !readNumber(o, "deadbandDeg", &p.deadbandDeg, &err) || !readNumber(o, "pollHz", &poll, &err)
        || !readNumber(o, "restPollHz", &p.restPollHz, &err)
        || !readGains(o, "azGains", &p.azGains, &err) || !readGains(o, "elGains", &p.elGains, &err))
        return std::nullopt;
    p.pollHz = int(poll);
    const QJsonObject tolerance = o.value("stopTolerance").toObject();
    for (const auto &[key, out] : {std::pair{"az", &p.stopToleranceAzDeg}, std::pair{"el", &p.stopToleranceElDeg}}) {
        if (!tolerance.contains(QLatin1String(key)))
            continue;
        double degrees = 0.0;
        if (!readNumber(tolerance, key, &degrees, &err))
            return std::nullopt;
        *out = degrees;
    }
    p.southStop = o.value("southStop").toBool(false);
    if (const QString drive = motion.value("drive").toString(QStringLiteral("servo")); drive == QLatin1String("relay"))
        m.drive = RotatorMotion::Drive::Relay;
    else if (drive != QLatin1String("servo")) {
        err = QObject::tr("drive must be 'servo' or 'relay', not '%1'").arg(drive);
        return std::nullopt;
    }
    if (QString e = p.validate(); !e.isEmpty()) {
        err = e;
        return std::nullopt;
    }
    return p;
}

bool RotatorProfile::save(const QString &path, QString *error) const
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        if (error)
            *error = QObject::tr("%1: %2").arg(path, file.errorString());
        return false;
    }
    file.write(QJsonDocument(toJson()).toJson(QJsonDocument::Indented));
    if (!file.commit()) {
        if (error)
            *error = QObject::tr("%1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

std::optional<RotatorProfile> RotatorProfile::load(const QString &path, QString *error)
{
    // A profile is a few hundred bytes; a device, a FIFO or a huge file is
    // refused before it is read (core/input).
    const input::BoundedRead read = input::readBoundedFile(path, kLargestProfile);
    if (!read.ok()) {
        if (error)
            *error = read.error;
        return std::nullopt;
    }
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(read.bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        if (error)
            *error = QObject::tr("%1: not a profile: %2 at byte %3")
                         .arg(path, parseError.errorString())
                         .arg(parseError.offset);
        return std::nullopt;
    }
    if (!doc.isObject()) {
        if (error)
            *error = QObject::tr("%1: not a profile: the file holds JSON %2, a profile is a JSON object "
                                 "({\"uri\": …, \"limits\": …})")
                         .arg(path, doc.isArray() ? QObject::tr("an array") : QObject::tr("a single value"));
        return std::nullopt;
    }
    QString why;
    auto profile = fromJson(doc.object(), &why);
    if (!profile && error)
        *error = QObject::tr("%1: %2").arg(path, why);
    return profile;
}

} // namespace slew::model
