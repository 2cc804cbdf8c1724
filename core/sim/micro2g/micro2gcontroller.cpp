// SPDX-License-Identifier: GPL-3.0-or-later
#include "micro2gcontroller.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>

namespace slew::sim {
namespace {

constexpr int kAdcMax = 4095;          // 12 bits
constexpr int kLargestTolerance = 500; // counts; more would never move
constexpr double kLongestStep = 0.01;  // seconds: finer than any tolerance band
constexpr double kStallSeconds = 3.0;  // relays released when the reading stops changing

QString error(const QString &text)
{
    return QStringLiteral("?> ") + text;
}

double wrap360(double degrees)
{
    const double d = std::fmod(degrees, 360.0);
    return d < 0 ? d + 360.0 : d;
}

// A whole number of at most `digits` digits, or nothing.
std::optional<int> wholeNumber(QStringView text, int digits)
{
    if (text.isEmpty() || text.size() > digits)
        return std::nullopt;
    for (QChar c : text) {
        if (!c.isDigit())
            return std::nullopt;
    }
    return text.toInt();
}

std::optional<int> rotorNumber(QChar c)
{
    if (c < u'1' || c > u'4')
        return std::nullopt;
    return c.digitValue();
}

} // namespace

Micro2gController::Micro2gController() : Micro2gController(std::array<Mechanics, kRotors>{}) {}

Micro2gController::Micro2gController(const std::array<Mechanics, kRotors> &mechanics)
{
    for (int i = 0; i < kRotors; ++i)
        m_rotors[size_t(i)].mechanics = mechanics[size_t(i)];
}

int Micro2gController::adc(int n) const
{
    const Mechanics &m = rotor(n).mechanics;
    const double fraction = rotor(n).travel / m.travelDegrees;
    const double reading = m.adcAtLeftStop + fraction * (m.adcAtRightStop - m.adcAtLeftStop);
    return std::clamp(int(std::lround(reading)), 0, kAdcMax);
}

double Micro2gController::travel(int n) const
{
    return rotor(n).travel;
}

double Micro2gController::trueBearing(int n) const
{
    return wrap360(rotor(n).mechanics.leftStopBearing + rotor(n).travel);
}

double Micro2gController::heading(int n) const
{
    const Micro2gCalibration &c = rotor(n).calibration;
    const double calibratedTravel = double(adc(n) - c.leftAdc) / (c.rightAdc - c.leftAdc) * c.degreeRange;
    return wrap360(c.leftBearing + calibratedTravel);
}

Micro2gController::Drive Micro2gController::drive(int n) const
{
    return rotor(n).drive;
}

int Micro2gController::tolerance(int n) const
{
    return rotor(n).tolerance;
}

const Micro2gCalibration &Micro2gController::calibration(int n) const
{
    return rotor(n).calibration;
}

void Micro2gController::setHandDrive(int n, Drive drive)
{
    Rotor &r = rotor(n);
    r.handDrive = drive;
    if (drive != Drive::Off) {
        r.targetAdc.reset();
        r.drive = Drive::Off;
    }
}

Micro2gController::Drive Micro2gController::handDrive(int n) const
{
    return rotor(n).handDrive;
}

void Micro2gController::setMechanics(int n, const Mechanics &mechanics)
{
    rotor(n).mechanics = mechanics;
    rotor(n).travel = std::clamp(rotor(n).travel, 0.0, mechanics.travelDegrees);
}

QString Micro2gController::turnTo(int n, double bearing)
{
    Rotor &r = rotor(n);
    const Micro2gCalibration &c = r.calibration;
    const double span = c.rightAdc - c.leftAdc;
    const double now = (adc(n) - c.leftAdc) / span * c.degreeRange;
    // The bearing is reached at one travel, or two inside the overlap:
    // take the nearer, so the rotor goes the short way.
    const double first = wrap360(bearing - c.leftBearing);
    double best = first;
    for (double candidate = first + 360.0; candidate <= c.degreeRange; candidate += 360.0) {
        if (std::abs(candidate - now) < std::abs(best - now))
            best = candidate;
    }
    if (best > c.degreeRange)
        return error(QStringLiteral("bearing %1 is outside rotor %2's range").arg(bearing).arg(n));
    r.targetAdc = int(std::lround(c.leftAdc + best / c.degreeRange * span));
    r.stalledSeconds = 0;
    return {};
}

void Micro2gController::advance(double seconds)
{
    // With no rotor driven there is nothing to step through: the relays
    // are off and stay so, however long the time.
    const bool anyDriven = std::any_of(m_rotors.begin(), m_rotors.end(),
                                       [](const Rotor &r) { return r.handDrive != Drive::Off || r.targetAdc; });
    if (!anyDriven) {
        for (Rotor &r : m_rotors)
            r.drive = Drive::Off;
        return;
    }
    while (seconds > 0) {
        const double dt = std::min(seconds, kLongestStep);
        seconds -= dt;
        for (int n = 1; n <= kRotors; ++n) {
            Rotor &r = rotor(n);
            if (r.handDrive != Drive::Off) {
                // The switch turns the motor directly; the stop holds it.
                const double sign = r.handDrive == Drive::Right ? 1.0 : -1.0;
                r.travel = std::clamp(r.travel + sign * r.mechanics.degreesPerSecond * dt, 0.0,
                                      r.mechanics.travelDegrees);
                continue;
            }
            if (!r.targetAdc) {
                r.drive = Drive::Off;
                continue;
            }
            const int reading = adc(n);
            if (std::abs(reading - *r.targetAdc) <= r.tolerance) {
                r.targetAdc.reset(); // inside the tolerance: the relays drop
                r.drive = Drive::Off;
                continue;
            }
            // The program believes the left stop reads leftAdc: moving right
            // takes the reading towards rightAdc.
            const Micro2gCalibration &c = r.calibration;
            const bool towardsRight = (*r.targetAdc - reading) * (c.rightAdc - c.leftAdc) > 0;
            r.drive = towardsRight ? Drive::Right : Drive::Left;
            const double before = r.travel;
            const double step = r.mechanics.degreesPerSecond * dt * (towardsRight ? 1.0 : -1.0);
            r.travel = std::clamp(r.travel + step, 0.0, r.mechanics.travelDegrees);
            // Against a mechanical stop (a calibration that points the wrong
            // way) the motor stalls; the program gives up after a while.
            r.stalledSeconds = r.travel == before ? r.stalledSeconds + dt : 0;
            if (r.stalledSeconds >= kStallSeconds) {
                r.targetAdc.reset();
                r.drive = Drive::Off;
            }
        }
    }
}

QStringList Micro2gController::handle(const QString &received)
{
    QString line = received.trimmed().toUpper();
    if (line.isEmpty())
        return {};
    // Some logging programs put "X4" and one more character before M.
    if (line.startsWith(QLatin1String("X4"))) {
        line = line.mid(2);
        if (!line.startsWith(u'M'))
            line = line.mid(1);
        if (!line.startsWith(u'M'))
            return {error(QStringLiteral("X4 must be followed by an M command"))};
    }
    const QChar command = line.front();
    const QStringView rest = QStringView(line).mid(1);

    if (line.size() == 1 && command.isDigit()) {
        const auto n = rotorNumber(command);
        if (!n)
            return {error(QStringLiteral("rotors are 1 to 4, not %1").arg(command))};
        m_defaultRotor = *n;
        return {};
    }
    switch (command.unicode()) {
    case 'C': {
        int n = m_defaultRotor;
        if (rest.size() == 1 && rotorNumber(rest.front()))
            n = *rotorNumber(rest.front());
        else if (!rest.isEmpty())
            return {error(QStringLiteral("C or Cn, n 1 to 4"))};
        const int degrees = int(std::lround(heading(n))) % 360;
        return {QStringLiteral("+0%1").arg(degrees, 3, 10, QLatin1Char('0'))};
    }
    case 'M': {
        const auto bearing = wholeNumber(rest, 3);
        if (!bearing || *bearing > 360)
            return {error(QStringLiteral("M wants a bearing of 0 to 360, as Mqqq"))};
        const QString refused = turnTo(m_defaultRotor, *bearing % 360);
        return refused.isEmpty() ? QStringList() : QStringList{refused};
    }
    case 'P':
    case 'L': {
        int n = m_defaultRotor;
        QStringView which = rest;
        if (rest.size() == 2 && rotorNumber(rest.front())) {
            n = *rotorNumber(rest.front());
            which = rest.mid(1);
        }
        const auto preset = wholeNumber(which, 1);
        if (!preset || *preset < 1 || *preset > 3)
            return {error(QStringLiteral("%1m or %1nm, preset m 1 to 3").arg(command))};
        Rotor &r = rotor(n);
        if (command == u'L') {
            r.presets[size_t(*preset - 1)] = std::round(heading(n));
            return {};
        }
        const QString refused = turnTo(n, r.presets[size_t(*preset - 1)]);
        return refused.isEmpty() ? QStringList() : QStringList{refused};
    }
    case 'S': {
        int n = m_defaultRotor;
        if (rest.size() == 1 && rotorNumber(rest.front()))
            n = *rotorNumber(rest.front());
        else if (!rest.isEmpty())
            return {error(QStringLiteral("S or Sn, n 1 to 4"))};
        rotor(n).targetAdc.reset();
        rotor(n).drive = Drive::Off;
        return {};
    }
    case 'T': {
        if (rest.isEmpty()) {
            QStringList parts;
            for (int n = 1; n <= kRotors; ++n)
                parts << QStringLiteral("T%1=%2").arg(n).arg(rotor(n).tolerance);
            return {parts.join(u' ')};
        }
        const QStringList words = rest.toString().split(u' ', Qt::SkipEmptyParts);
        const auto n = words.size() == 2 && words[0].size() == 1 ? rotorNumber(words[0].front()) : std::nullopt;
        const auto counts = words.size() == 2 ? wholeNumber(words[1], 4) : std::nullopt;
        if (!n || !counts || *counts < 1 || *counts > kLargestTolerance)
            return {error(QStringLiteral("Tn x: rotor n 1 to 4, tolerance x 1 to %1 A/D counts").arg(kLargestTolerance))};
        rotor(*n).tolerance = *counts;
        return {};
    }
    case 'Z':
        return calibrate(line);
    case '?': {
        if (!rest.isEmpty())
            break;
        int moving = 0;
        for (int n = 1; n <= kRotors; ++n)
            moving += rotor(n).drive != Drive::Off;
        return {QStringLiteral("Micro-2g rotor controller: %1 rotors, default rotor %2, %3 turning, 9600 8N1")
                    .arg(kRotors).arg(m_defaultRotor).arg(moving)};
    }
    case 'V': {
        if (!rest.isEmpty())
            break;
        QStringList parts;
        for (int n = 1; n <= kRotors; ++n)
            parts << QStringLiteral("V%1=%2").arg(n).arg(adc(n));
        return {parts.join(u' ')};
    }
    case 'R': {
        if (!rest.isEmpty())
            break;
        QStringList parts;
        for (int n = 1; n <= kRotors; ++n) {
            const Drive d = rotor(n).drive;
            const char *bit = d == Drive::Left ? "L" : d == Drive::Right ? "R" : "-";
            parts << QStringLiteral("R%1=%2").arg(n).arg(QLatin1String(bit));
        }
        return {parts.join(u' ')};
    }
    default:
        break;
    }
    return {error(QStringLiteral("unknown command '%1'").arg(line.left(16)))};
}

QStringList Micro2gController::calibrate(const QString &line)
{
    if (line == u"Z") {
        QStringList lines;
        for (int n = 1; n <= kRotors; ++n) {
            const Micro2gCalibration &c = rotor(n).calibration;
            lines << QStringLiteral("Z%1L %2=%3 Z%1R %4=%5 Z%1D %6")
                         .arg(n)
                         .arg(c.leftAdc)
                         .arg(int(c.leftBearing), 3, 10, QLatin1Char('0'))
                         .arg(c.rightAdc)
                         .arg(int(c.rightBearing), 3, 10, QLatin1Char('0'))
                         .arg(int(c.degreeRange));
        }
        return lines;
    }
    // ZnL mmm, ZnR mmm, ZnD mmm, ZnL xxxx=yyy, ZnR xxxx=yyy
    const QString usage = QStringLiteral("ZnL mmm, ZnR mmm, ZnD mmm or ZnL/ZnR xxxx=yyy, rotor n 1 to 4");
    if (line.size() < 4 || !rotorNumber(line[1]) || line[3] != u' ')
        return {error(usage)};
    const int n = *rotorNumber(line[1]);
    const QChar which = line[2];
    const QString value = line.mid(4).trimmed();
    Micro2gCalibration c = rotor(n).calibration;
    if (which == u'D') {
        const auto range = wholeNumber(value, 3);
        if (!range || *range < 90 || *range > 540)
            return {error(QStringLiteral("Z%1D: a degree range of 90 to 540").arg(n))};
        c.degreeRange = *range;
    } else if (which == u'L' || which == u'R') {
        int counts = adc(n); // ZnL mmm: the reading where the rotor stands now
        QString bearingText = value;
        if (const qsizetype equals = value.indexOf(u'='); equals >= 0) {
            const auto manual = wholeNumber(QStringView(value).left(equals), 4);
            if (!manual || *manual > kAdcMax)
                return {error(QStringLiteral("Z%1%2: an A/D value of 0 to %3").arg(n).arg(which).arg(kAdcMax))};
            counts = *manual;
            bearingText = value.mid(equals + 1);
        }
        const auto bearing = wholeNumber(bearingText, 3);
        if (!bearing || *bearing > 359)
            return {error(QStringLiteral("Z%1%2: a bearing of 0 to 359").arg(n).arg(which))};
        (which == u'L' ? c.leftAdc : c.rightAdc) = counts;
        (which == u'L' ? c.leftBearing : c.rightBearing) = *bearing;
    } else {
        return {error(usage)};
    }
    // Two stops on one reading would divide by zero in every heading.
    if (std::abs(c.rightAdc - c.leftAdc) < 10)
        return {error(QStringLiteral("Z%1: the left and right stops must read at least 10 counts apart").arg(n))};
    rotor(n).calibration = c;
    rotor(n).targetAdc.reset(); // a target in the old scale means nothing now
    rotor(n).drive = Drive::Off;
    return {};
}

QJsonObject Micro2gController::settings() const
{
    QJsonArray rotors;
    for (int n = 1; n <= kRotors; ++n) {
        const Rotor &r = rotor(n);
        rotors.append(QJsonObject{{QStringLiteral("left_adc"), r.calibration.leftAdc},
                                  {QStringLiteral("left_bearing"), r.calibration.leftBearing},
                                  {QStringLiteral("right_adc"), r.calibration.rightAdc},
                                  {QStringLiteral("right_bearing"), r.calibration.rightBearing},
                                  {QStringLiteral("degree_range"), r.calibration.degreeRange},
                                  {QStringLiteral("tolerance"), r.tolerance},
                                  {QStringLiteral("presets"), QJsonArray{r.presets[0], r.presets[1], r.presets[2]}}});
    }
    return {{QStringLiteral("default_rotor"), m_defaultRotor}, {QStringLiteral("rotors"), rotors}};
}

QString Micro2gController::restoreSettings(const QJsonObject &settings)
{
    const QJsonArray rotors = settings.value(QStringLiteral("rotors")).toArray();
    const int defaultRotor = settings.value(QStringLiteral("default_rotor")).toInt(1);
    if (rotors.size() != kRotors || defaultRotor < 1 || defaultRotor > kRotors)
        return QStringLiteral("expected %1 rotors and a default rotor of 1 to %1").arg(kRotors);
    std::array<Rotor, kRotors> restored = m_rotors;
    for (int i = 0; i < kRotors; ++i) {
        const QJsonObject o = rotors[i].toObject();
        Rotor &r = restored[size_t(i)];
        r.calibration.leftAdc = o.value(QStringLiteral("left_adc")).toInt(-1);
        r.calibration.leftBearing = o.value(QStringLiteral("left_bearing")).toDouble(-1);
        r.calibration.rightAdc = o.value(QStringLiteral("right_adc")).toInt(-1);
        r.calibration.rightBearing = o.value(QStringLiteral("right_bearing")).toDouble(-1);
        r.calibration.degreeRange = o.value(QStringLiteral("degree_range")).toDouble(0);
        r.tolerance = o.value(QStringLiteral("tolerance")).toInt(0);
        const QJsonArray presets = o.value(QStringLiteral("presets")).toArray();
        const Micro2gCalibration &c = r.calibration;
        const bool sane = c.leftAdc >= 0 && c.leftAdc <= kAdcMax && c.rightAdc >= 0 && c.rightAdc <= kAdcMax
                          && std::abs(c.rightAdc - c.leftAdc) >= 10 && c.leftBearing >= 0 && c.leftBearing < 360
                          && c.rightBearing >= 0 && c.rightBearing < 360 && c.degreeRange >= 90
                          && c.degreeRange <= 540 && r.tolerance >= 1 && r.tolerance <= kLargestTolerance
                          && presets.size() == 3;
        if (!sane)
            return QStringLiteral("rotor %1: calibration, tolerance or presets out of range").arg(i + 1);
        for (int p = 0; p < 3; ++p)
            r.presets[size_t(p)] = wrap360(presets[p].toDouble());
    }
    m_rotors = restored;
    m_defaultRotor = defaultRotor;
    return {};
}

} // namespace slew::sim
