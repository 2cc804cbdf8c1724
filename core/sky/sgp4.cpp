// SPDX-License-Identifier: GPL-3.0-or-later
#include "sgp4.h"

#include <QString>

#include <algorithm>
#include <cmath>

namespace slew::sky {
namespace {

// WGS-72: the earth model the element sets are fitted with.
constexpr double kEarthRadiusKm = 6378.135;
constexpr double kMuKm3S2 = 398600.8;
constexpr double kJ2 = 0.001082616;
constexpr double kJ3 = -0.00000253881;
constexpr double kJ4 = -0.00000165597;
constexpr double kJ3OverJ2 = kJ3 / kJ2;
// sqrt(mu) in earth radii^1.5 per minute.
const double kXke = 60.0 / std::sqrt(kEarthRadiusKm * kEarthRadiusKm * kEarthRadiusKm / kMuKm3S2);
const double kVelocityKmS = kEarthRadiusKm * kXke / 60.0;
constexpr double kTwoThirds = 2.0 / 3.0;

// The density model's reference altitudes: s = 78 km, q0 = 120 km.
constexpr double kDensityS = 78.0 / kEarthRadiusKm + 1.0;
const double kDensityQ0MinusS4 = std::pow((120.0 - 78.0) / kEarthRadiusKm, 4);

// Orbits of 225 minutes or more need the deep-space terms.
constexpr double kDeepSpacePeriodMinutes = 225.0;

// Sun and moon constants of the deep-space model.
constexpr double kSolarMeanMotion = 1.19459e-5;   // rad/min
constexpr double kLunarMeanMotion = 1.5835218e-4; // rad/min
constexpr double kSolarEccentricity = 0.01675;
constexpr double kLunarEccentricity = 0.05490;
constexpr double kSiderealRate = 4.37526908801129966e-3; // earth rotation, rad/min
// Days from 1949 December 31 00:00 (the model's epoch base) to 1950 Jan 0.5.
constexpr double kJulian1950Base = 2433281.5;

// The geometry of one perturbing body relative to the orbit, in the
// report's notation: s1..s7 scale by the body's strength, z* are the
// direction-cosine products.
struct BodyFactors {
    double s1, s2, s3, s4, s5, s6, s7;
    double z1, z2, z3, z11, z12, z13, z21, z22, z23, z31, z32, z33;
};

struct BodyOrientation {
    double cosG, sinG;   // the body's argument of perigee on its own orbit
    double cosI, sinI;   // its inclination to the equator
    double cosH, sinH;   // its node relative to the satellite's node
    double strength;     // C1 (solar) or C1L (lunar)
};

BodyFactors bodyFactors(const BodyOrientation &b, double cosInc, double sinInc, double cosArgp, double sinArgp,
                        double ecc, double meanMotion)
{
    const double eccSq = ecc * ecc;
    const double betaSq = 1.0 - eccSq;
    const double beta = std::sqrt(betaSq);

    // Direction cosines of the body's orbit axes in the satellite's orbit frame.
    const double a1 = b.cosG * b.cosH + b.sinG * b.cosI * b.sinH;
    const double a3 = -b.sinG * b.cosH + b.cosG * b.cosI * b.sinH;
    const double a7 = -b.cosG * b.sinH + b.sinG * b.cosI * b.cosH;
    const double a8 = b.sinG * b.sinI;
    const double a9 = b.sinG * b.sinH + b.cosG * b.cosI * b.cosH;
    const double a10 = b.cosG * b.sinI;
    const double a2 = cosInc * a7 + sinInc * a8;
    const double a4 = cosInc * a9 + sinInc * a10;
    const double a5 = -sinInc * a7 + cosInc * a8;
    const double a6 = -sinInc * a9 + cosInc * a10;

    const double x1 = a1 * cosArgp + a2 * sinArgp;
    const double x2 = a3 * cosArgp + a4 * sinArgp;
    const double x3 = -a1 * sinArgp + a2 * cosArgp;
    const double x4 = -a3 * sinArgp + a4 * cosArgp;
    const double x5 = a5 * sinArgp;
    const double x6 = a6 * sinArgp;
    const double x7 = a5 * cosArgp;
    const double x8 = a6 * cosArgp;

    BodyFactors f;
    f.z31 = 12.0 * x1 * x1 - 3.0 * x3 * x3;
    f.z32 = 24.0 * x1 * x2 - 6.0 * x3 * x4;
    f.z33 = 12.0 * x2 * x2 - 3.0 * x4 * x4;
    f.z1 = 3.0 * (a1 * a1 + a2 * a2) + f.z31 * eccSq;
    f.z2 = 6.0 * (a1 * a3 + a2 * a4) + f.z32 * eccSq;
    f.z3 = 3.0 * (a3 * a3 + a4 * a4) + f.z33 * eccSq;
    f.z11 = -6.0 * a1 * a5 + eccSq * (-24.0 * x1 * x7 - 6.0 * x3 * x5);
    f.z12 = -6.0 * (a1 * a6 + a3 * a5) + eccSq * (-24.0 * (x2 * x7 + x1 * x8) - 6.0 * (x3 * x6 + x4 * x5));
    f.z13 = -6.0 * a3 * a6 + eccSq * (-24.0 * x2 * x8 - 6.0 * x4 * x6);
    f.z21 = 6.0 * a2 * a5 + eccSq * (24.0 * x1 * x5 - 6.0 * x3 * x7);
    f.z22 = 6.0 * (a4 * a5 + a2 * a6) + eccSq * (24.0 * (x2 * x5 + x1 * x6) - 6.0 * (x4 * x7 + x3 * x8));
    f.z23 = 6.0 * a4 * a6 + eccSq * (24.0 * x2 * x6 - 6.0 * x4 * x8);
    f.z1 = 2.0 * f.z1 + betaSq * f.z31;
    f.z2 = 2.0 * f.z2 + betaSq * f.z32;
    f.z3 = 2.0 * f.z3 + betaSq * f.z33;

    f.s3 = b.strength / meanMotion;
    f.s2 = -0.5 * f.s3 / beta;
    f.s4 = f.s3 * beta;
    f.s1 = -15.0 * ecc * f.s4;
    f.s5 = x1 * x3 + x2 * x4;
    f.s6 = x2 * x3 + x1 * x4;
    f.s7 = x2 * x4 - x1 * x3;
    return f;
}

Sgp4::ThirdBody periodicAmplitudes(const BodyFactors &f, double ecc, double bodyEccentricity)
{
    const double eccSq = ecc * ecc;
    Sgp4::ThirdBody p;
    p.e2 = 2.0 * f.s1 * f.s6;
    p.e3 = 2.0 * f.s1 * f.s7;
    p.i2 = 2.0 * f.s2 * f.z12;
    p.i3 = 2.0 * f.s2 * (f.z13 - f.z11);
    p.l2 = -2.0 * f.s3 * f.z2;
    p.l3 = -2.0 * f.s3 * (f.z3 - f.z1);
    p.l4 = -2.0 * f.s3 * (-21.0 - 9.0 * eccSq) * bodyEccentricity;
    p.gh2 = 2.0 * f.s4 * f.z32;
    p.gh3 = 2.0 * f.s4 * (f.z33 - f.z31);
    p.gh4 = -18.0 * f.s4 * bodyEccentricity;
    p.h2 = -2.0 * f.s2 * f.z22;
    p.h3 = -2.0 * f.s2 * (f.z23 - f.z21);
    p.eccentricity = bodyEccentricity;
    return p;
}

// Secular rates one body causes: de/dt, di/dt, dM/dt, and the parts of dω/dt
// and dΩ/dt before they are divided by sin i.
struct BodySecular {
    double ecc, inc, meanAnomaly, argPerigeePart, nodePart;
};

BodySecular bodySecular(const BodyFactors &f, double bodyMeanMotion, double eccSq)
{
    return {f.s1 * bodyMeanMotion * f.s5,
            f.s2 * bodyMeanMotion * (f.z11 + f.z13),
            -bodyMeanMotion * f.s3 * (f.z1 + f.z3 - 14.0 - 6.0 * eccSq),
            f.s4 * bodyMeanMotion * (f.z31 + f.z33 - 6.0),
            -bodyMeanMotion * f.s2 * (f.z21 + f.z23)};
}

// The long-period periodic changes one body makes at time t.
struct PeriodicChange {
    double ecc = 0, inc = 0, meanLongitude = 0, argPerigee = 0, node = 0;
};

PeriodicChange periodicChange(const Sgp4::ThirdBody &p, double t)
{
    const double meanAnomaly = p.meanAnomalyAtEpoch + p.meanMotion * t;
    const double trueish = meanAnomaly + 2.0 * p.eccentricity * std::sin(meanAnomaly);
    const double sinF = std::sin(trueish);
    const double f2 = 0.5 * sinF * sinF - 0.25;
    const double f3 = -0.5 * sinF * std::cos(trueish);
    return {p.e2 * f2 + p.e3 * f3,
            p.i2 * f2 + p.i3 * f3,
            p.l2 * f2 + p.l3 * f3 + p.l4 * sinF,
            p.gh2 * f2 + p.gh3 * f3 + p.gh4 * sinF,
            p.h2 * f2 + p.h3 * f3};
}

// The "G" functions of eccentricity in the half-day resonance (Molniya
// orbits), fitted piecewise by the report's authors.
struct HalfDayG {
    double g201, g211, g310, g322, g410, g422, g520, g521, g532, g533;
};

HalfDayG halfDayG(double e)
{
    const double e2 = e * e, e3 = e2 * e;
    HalfDayG g;
    g.g201 = -0.306 - (e - 0.64) * 0.440;
    if (e <= 0.65) {
        g.g211 = 3.616 - 13.2470 * e + 16.2900 * e2;
        g.g310 = -19.302 + 117.3900 * e - 228.4190 * e2 + 156.5910 * e3;
        g.g322 = -18.9068 + 109.7927 * e - 214.6334 * e2 + 146.5816 * e3;
        g.g410 = -41.122 + 242.6940 * e - 471.0940 * e2 + 313.9530 * e3;
        g.g422 = -146.407 + 841.8800 * e - 1629.014 * e2 + 1083.4350 * e3;
        g.g520 = -532.114 + 3017.977 * e - 5740.032 * e2 + 3708.2760 * e3;
    } else {
        g.g211 = -72.099 + 331.819 * e - 508.738 * e2 + 266.724 * e3;
        g.g310 = -346.844 + 1582.851 * e - 2415.925 * e2 + 1246.113 * e3;
        g.g322 = -342.585 + 1554.908 * e - 2366.899 * e2 + 1215.972 * e3;
        g.g410 = -1052.797 + 4758.686 * e - 7193.992 * e2 + 3651.957 * e3;
        g.g422 = -3581.690 + 16178.110 * e - 24462.770 * e2 + 12422.520 * e3;
        g.g520 = e > 0.715 ? -5149.66 + 29936.92 * e - 54087.36 * e2 + 31324.56 * e3
                           : 1464.74 - 4664.75 * e + 3763.64 * e2;
    }
    if (e < 0.7) {
        g.g533 = -919.22770 + 4988.6100 * e - 9064.7700 * e2 + 5542.21 * e3;
        g.g521 = -822.71072 + 4568.6173 * e - 8491.4146 * e2 + 5337.524 * e3;
        g.g532 = -853.66600 + 4690.2500 * e - 8624.7700 * e2 + 5341.4 * e3;
    } else {
        g.g533 = -37995.780 + 161616.52 * e - 229838.20 * e2 + 109377.94 * e3;
        g.g521 = -51752.104 + 218913.95 * e - 309468.16 * e2 + 146349.42 * e3;
        g.g532 = -40023.880 + 170470.89 * e - 242699.48 * e2 + 115605.82 * e3;
    }
    return g;
}

// Kepler's equation in the report's equinoctial form, by Newton steps that
// are limited so a poor start cannot throw the iteration off.
double solveKepler(double u, double axn, double ayn)
{
    double eccentricAnomalyPlusArgp = u;
    for (int step = 0; step < 10; ++step) {
        const double s = std::sin(eccentricAnomalyPlusArgp);
        const double c = std::cos(eccentricAnomalyPlusArgp);
        double delta = (u - ayn * c + axn * s - eccentricAnomalyPlusArgp) / (1.0 - c * axn - s * ayn);
        delta = std::clamp(delta, -0.95, 0.95);
        eccentricAnomalyPlusArgp += delta;
        if (std::fabs(delta) < 1e-12)
            break;
    }
    return eccentricAnomalyPlusArgp;
}

} // namespace

double gmstIau82(double julianDateUt1)
{
    const double centuries = (julianDateUt1 - kJ2000) / 36525.0;
    const double seconds = -6.2e-6 * centuries * centuries * centuries + 0.093104 * centuries * centuries
                           + (876600.0 * 3600.0 + 8640184.812866) * centuries + 67310.54841;
    // 240 seconds of time per degree.
    return wrapTwoPi(seconds * kDegree / 240.0);
}

QString sgp4ErrorText(Sgp4Error error)
{
    switch (error) {
    case Sgp4Error::None: return QStringLiteral("no error");
    case Sgp4Error::MeanEccentricity: return QStringLiteral("mean eccentricity out of range");
    case Sgp4Error::MeanMotion: return QStringLiteral("mean motion below zero");
    case Sgp4Error::PerturbedEccentricity: return QStringLiteral("perturbed eccentricity out of range");
    case Sgp4Error::SemiLatusRectum: return QStringLiteral("semi-latus rectum below zero");
    case Sgp4Error::Decayed: return QStringLiteral("decayed: the orbit is inside the earth");
    case Sgp4Error::TimeOutOfRange: return QStringLiteral("time not finite, or over 100 years from the epoch");
    }
    return QStringLiteral("unknown error");
}

Sgp4::Sgp4(const ElementSet &elements)
    : m_elements(elements)
{
    m_epochJd = elements.epochJulianDay;
    m_epochFraction = elements.epochDayFraction;
    m_bstar = elements.bstar;

    const double revPerDayToRadPerMin = kTwoPi / kMinutesPerDay;
    m_epoch.eccentricity = elements.eccentricity;
    m_epoch.inclination = radians(elements.inclinationDeg);
    m_epoch.node = radians(elements.raanDeg);
    m_epoch.argPerigee = radians(elements.argPerigeeDeg);
    m_epoch.meanAnomaly = radians(elements.meanAnomalyDeg);
    const double kozaiMeanMotion = elements.meanMotionRevPerDay * revPerDayToRadPerMin;

    // The element sets carry Kozai's mean motion; the theory needs Brouwer's.
    const double ecc = m_epoch.eccentricity;
    const double betaSq = 1.0 - ecc * ecc;
    m_cosI = std::cos(m_epoch.inclination);
    m_sinI = std::sin(m_epoch.inclination);
    const double cosSq = m_cosI * m_cosI;
    const double a1 = std::pow(kXke / kozaiMeanMotion, kTwoThirds);
    const double j2Factor = 0.75 * kJ2 * (3.0 * cosSq - 1.0) / (std::sqrt(betaSq) * betaSq);
    double delta = j2Factor / (a1 * a1);
    const double a0 = a1 * (1.0 - delta * delta - delta * (1.0 / 3.0 + 134.0 * delta * delta / 81.0));
    delta = j2Factor / (a0 * a0);
    m_epoch.meanMotion = kozaiMeanMotion / (1.0 + delta);
    const double semiMajorAxis = std::pow(kXke / m_epoch.meanMotion, kTwoThirds);
    m_semiMajorAtEpoch = semiMajorAxis;
    const double perigeeKm = (semiMajorAxis * (1.0 - ecc) - 1.0) * kEarthRadiusKm;

    m_gmstAtEpoch = gmstIau82(m_epochJd + m_epochFraction);
    m_simpleDrag = perigeeKm < 220.0;
    initialiseNearEarth(perigeeKm);

    if (kTwoPi / m_epoch.meanMotion >= kDeepSpacePeriodMinutes) {
        m_deepSpace = true;
        m_simpleDrag = true;
        initialiseDeepSpace(m_epochJd + m_epochFraction - kJulian1950Base);
    }
    if (!m_simpleDrag) {
        const double c1Sq = m_c1 * m_c1;
        const double semiMajor = std::pow(kXke / m_epoch.meanMotion, kTwoThirds);
        double sFour = kDensityS;
        if (perigeeKm < 156.0)
            sFour = (perigeeKm < 98.0 ? 20.0 : perigeeKm - 78.0) / kEarthRadiusKm + 1.0;
        const double xi = 1.0 / (semiMajor - sFour);
        m_d2 = 4.0 * semiMajor * xi * c1Sq;
        const double k = m_d2 * xi * m_c1 / 3.0;
        m_d3 = (17.0 * semiMajor + sFour) * k;
        m_d4 = 0.5 * k * semiMajor * xi * (221.0 * semiMajor + 31.0 * sFour) * m_c1;
        m_t3 = m_d2 + 2.0 * c1Sq;
        m_t4 = 0.25 * (3.0 * m_d3 + m_c1 * (12.0 * m_d2 + 10.0 * c1Sq));
        m_t5 = 0.2 * (3.0 * m_d4 + 12.0 * m_c1 * m_d3 + 6.0 * m_d2 * m_d2 + 15.0 * c1Sq * (2.0 * m_d2 + c1Sq));
    }
    m_initialError = propagate(0.0).error;
}

void Sgp4::initialiseNearEarth(double perigeeKm)
{
    const double ecc = m_epoch.eccentricity;
    const double n0 = m_epoch.meanMotion;
    const double a0 = std::pow(kXke / n0, kTwoThirds);
    const double betaSq = 1.0 - ecc * ecc;
    const double beta = std::sqrt(betaSq);
    const double cosSq = m_cosI * m_cosI;
    const double theta2Term = 3.0 * cosSq - 1.0; // 3cos²i − 1
    const double semiLatus = a0 * betaSq;

    // Low perigees see a denser atmosphere: the density model's s and
    // (q0 − s)^4 are lowered with the perigee.
    double sFour = kDensityS;
    double q0MinusS4 = kDensityQ0MinusS4;
    if (perigeeKm < 156.0) {
        double s = perigeeKm < 98.0 ? 20.0 : perigeeKm - 78.0;
        q0MinusS4 = std::pow((120.0 - s) / kEarthRadiusKm, 4);
        sFour = s / kEarthRadiusKm + 1.0;
    }
    const double xi = 1.0 / (a0 - sFour);
    m_eta = a0 * ecc * xi;
    const double etaSq = m_eta * m_eta;
    const double eEta = ecc * m_eta;
    const double psiSq = std::fabs(1.0 - etaSq);
    const double coef = q0MinusS4 * std::pow(xi, 4);
    const double coef1 = coef / std::pow(psiSq, 3.5);

    const double c2 = coef1 * n0
                      * (a0 * (1.0 + 1.5 * etaSq + eEta * (4.0 + etaSq))
                         + 0.375 * kJ2 * xi / psiSq * theta2Term * (8.0 + 3.0 * etaSq * (8.0 + etaSq)));
    m_c1 = m_bstar * c2;
    const double c3 = ecc > 1e-4 ? -2.0 * coef * xi * kJ3OverJ2 * n0 * m_sinI / ecc : 0.0;
    const double sinSq = 1.0 - cosSq;
    m_c4 = 2.0 * n0 * coef1 * a0 * betaSq
           * (m_eta * (2.0 + 0.5 * etaSq) + ecc * (0.5 + 2.0 * etaSq)
              - kJ2 * xi / (a0 * psiSq)
                    * (-3.0 * theta2Term * (1.0 - 2.0 * eEta + etaSq * (1.5 - 0.5 * eEta))
                       + 0.75 * sinSq * (2.0 * etaSq - eEta * (1.0 + etaSq)) * std::cos(2.0 * m_epoch.argPerigee)));
    m_c5 = 2.0 * coef1 * a0 * betaSq * (1.0 + 2.75 * (etaSq + eEta) + eEta * etaSq);

    // Secular rates from J2 and J4.
    const double cos4 = cosSq * cosSq;
    const double k1 = 1.5 * kJ2 / (semiLatus * semiLatus) * n0;
    const double k2 = 0.5 * k1 * kJ2 / (semiLatus * semiLatus);
    const double k4 = -0.46875 * kJ4 / (semiLatus * semiLatus * semiLatus * semiLatus) * n0;
    m_meanAnomalyRate = n0 + 0.5 * k1 * beta * theta2Term + 0.0625 * k2 * beta * (13.0 - 78.0 * cosSq + 137.0 * cos4);
    m_argPerigeeRate = -0.5 * k1 * (1.0 - 5.0 * cosSq) + 0.0625 * k2 * (7.0 - 114.0 * cosSq + 395.0 * cos4)
                       + k4 * (3.0 - 36.0 * cosSq + 49.0 * cos4);
    const double nodeRateJ2 = -k1 * m_cosI;
    m_nodeRate = nodeRateJ2 + (0.5 * k2 * (4.0 - 19.0 * cosSq) + 2.0 * k4 * (3.0 - 7.0 * cosSq)) * m_cosI;

    m_argPerigeeDragCoeff = m_bstar * c3 * std::cos(m_epoch.argPerigee);
    m_meanAnomalyDragCoeff = ecc > 1e-4 ? -kTwoThirds * coef * m_bstar / eEta : 0.0;
    m_nodeDragCoeff = 3.5 * betaSq * nodeRateJ2 * m_c1;
    m_t2 = 1.5 * m_c1;

    // The J3 long-period terms divide by 1 + cos i, which vanishes for
    // retrograde equatorial orbits; the report's revision bounds it.
    const double onePlusCos = std::fabs(m_cosI + 1.0) > 1.5e-12 ? 1.0 + m_cosI : 1.5e-12;
    m_lCoefficient = -0.25 * kJ3OverJ2 * m_sinI * (3.0 + 5.0 * m_cosI) / onePlusCos;
    m_ayCoefficient = -0.5 * kJ3OverJ2 * m_sinI;
    m_delta0Cubed = std::pow(1.0 + m_eta * std::cos(m_epoch.meanAnomaly), 3);
    m_sinMeanAnomalyAtEpoch = std::sin(m_epoch.meanAnomaly);
}

void Sgp4::initialiseDeepSpace(double epochSince1950)
{
    const double ecc = m_epoch.eccentricity;
    const double eccSq = ecc * ecc;
    const double n0 = m_epoch.meanMotion;
    const double cosArgp = std::cos(m_epoch.argPerigee);
    const double sinArgp = std::sin(m_epoch.argPerigee);
    const double cosNode = std::cos(m_epoch.node);
    const double sinNode = std::sin(m_epoch.node);

    // The moon's orbit at epoch: its node regresses along the ecliptic.
    const double day = epochSince1950 + 18261.5; // days since 1900 Jan 0.5
    const double lunarNode = wrapTwoPi(4.5236020 - 9.2422029e-4 * day);
    const double sinLunarNode = std::sin(lunarNode);
    const double cosLunarNode = std::cos(lunarNode);
    const double cosLunarInc = 0.91375164 - 0.03568096 * cosLunarNode;
    const double sinLunarInc = std::sqrt(1.0 - cosLunarInc * cosLunarInc);
    const double sinLunarH = 0.089683511 * sinLunarNode / sinLunarInc;
    const double cosLunarH = std::sqrt(1.0 - sinLunarH * sinLunarH);
    const double lunarPerigeeLongitude = 5.8351514 + 0.0019443680 * day;
    const double lunarArg = lunarPerigeeLongitude
                            + std::atan2(0.39785416 * sinLunarNode / sinLunarInc,
                                         cosLunarH * cosLunarNode + 0.91744867 * sinLunarH * sinLunarNode)
                            - lunarNode;

    const BodyOrientation sun{0.1945905, -0.98088458, 0.91744867, 0.39785416, cosNode, sinNode, 2.9864797e-6};
    const BodyOrientation moon{std::cos(lunarArg),
                               std::sin(lunarArg),
                               cosLunarInc,
                               sinLunarInc,
                               cosLunarH * cosNode + sinLunarH * sinNode,
                               sinNode * cosLunarH - cosNode * sinLunarH,
                               4.7968065e-7};
    const BodyFactors solarFactors = bodyFactors(sun, m_cosI, m_sinI, cosArgp, sinArgp, ecc, n0);
    const BodyFactors lunarFactors = bodyFactors(moon, m_cosI, m_sinI, cosArgp, sinArgp, ecc, n0);

    m_sun = periodicAmplitudes(solarFactors, ecc, kSolarEccentricity);
    m_sun.meanAnomalyAtEpoch = wrapTwoPi(6.2565837 + 0.017201977 * day);
    m_sun.meanMotion = kSolarMeanMotion;
    m_moon = periodicAmplitudes(lunarFactors, ecc, kLunarEccentricity);
    m_moon.meanAnomalyAtEpoch = std::fmod(4.7199672 + 0.22997150 * day - lunarPerigeeLongitude, kTwoPi);
    m_moon.meanMotion = kLunarMeanMotion;

    // Secular rates. Near the equator the node is ill-defined, so the
    // node terms are left out below 3 degrees (and above 177).
    const BodySecular solar = bodySecular(solarFactors, kSolarMeanMotion, eccSq);
    const BodySecular lunar = bodySecular(lunarFactors, kLunarMeanMotion, eccSq);
    const bool nearEquatorial = m_epoch.inclination < 5.2359877e-2 || m_epoch.inclination > kPi - 5.2359877e-2;
    double solarNode = nearEquatorial ? 0.0 : solar.nodePart;
    const double lunarNode2 = nearEquatorial ? 0.0 : lunar.nodePart;
    if (m_sinI != 0.0)
        solarNode /= m_sinI;
    m_deepSecular.eccentricity = solar.ecc + lunar.ecc;
    m_deepSecular.inclination = solar.inc + lunar.inc;
    m_deepSecular.meanAnomaly = solar.meanAnomaly + lunar.meanAnomaly;
    m_deepSecular.argPerigee = solar.argPerigeePart - m_cosI * solarNode + lunar.argPerigeePart;
    m_deepSecular.node = solarNode;
    if (m_sinI != 0.0) {
        m_deepSecular.argPerigee -= m_cosI / m_sinI * lunarNode2;
        m_deepSecular.node += lunarNode2 / m_sinI;
    }

    // Resonances with the earth's tesseral harmonics.
    Resonance &r = m_resonance;
    if (n0 < 0.0052359877 && n0 > 0.0034906585)
        r.kind = 1;
    if (n0 >= 8.26e-3 && n0 <= 9.24e-3 && ecc >= 0.5)
        r.kind = 2;
    if (r.kind == 0)
        return;
    const double theta = m_gmstAtEpoch;
    const double aOverN = std::pow(n0 / kXke, kTwoThirds);
    const double sinI = m_sinI, cosI = m_cosI;
    if (r.kind == 2) {
        const double cosSq = cosI * cosI;
        const double sinSq = sinI * sinI;
        const HalfDayG g = halfDayG(ecc);
        const double f220 = 0.75 * (1.0 + 2.0 * cosI + cosSq);
        const double f221 = 1.5 * sinSq;
        const double f321 = 1.875 * sinI * (1.0 - 2.0 * cosI - 3.0 * cosSq);
        const double f322 = -1.875 * sinI * (1.0 + 2.0 * cosI - 3.0 * cosSq);
        const double f441 = 35.0 * sinSq * f220;
        const double f442 = 39.3750 * sinSq * sinSq;
        const double f522 = 9.84375 * sinI
                            * (sinSq * (1.0 - 2.0 * cosI - 5.0 * cosSq) + 0.33333333 * (-2.0 + 4.0 * cosI + 6.0 * cosSq));
        const double f523 = sinI * (4.92187512 * sinSq * (-2.0 - 4.0 * cosI + 10.0 * cosSq)
                                    + 6.56250012 * (1.0 + 2.0 * cosI - 3.0 * cosSq));
        const double f542 = 29.53125 * sinI * (2.0 - 8.0 * cosI + cosSq * (-12.0 + 8.0 * cosI + 10.0 * cosSq));
        const double f543 = 29.53125 * sinI * (-2.0 - 8.0 * cosI + cosSq * (12.0 + 8.0 * cosI - 10.0 * cosSq));
        // Each degree of the harmonic brings another power of a/n.
        double k = 3.0 * n0 * n0 * aOverN * aOverN;
        r.d2201 = k * 1.7891679e-6 * f220 * g.g201;
        r.d2211 = k * 1.7891679e-6 * f221 * g.g211;
        k *= aOverN;
        r.d3210 = k * 3.7393792e-7 * f321 * g.g310;
        r.d3222 = k * 3.7393792e-7 * f322 * g.g322;
        k *= aOverN;
        r.d4410 = 2.0 * k * 7.3636953e-9 * f441 * g.g410;
        r.d4422 = 2.0 * k * 7.3636953e-9 * f442 * g.g422;
        k *= aOverN;
        r.d5220 = k * 1.1428639e-7 * f522 * g.g520;
        r.d5232 = k * 1.1428639e-7 * f523 * g.g532;
        r.d5421 = 2.0 * k * 2.1765803e-9 * f542 * g.g521;
        r.d5433 = 2.0 * k * 2.1765803e-9 * f543 * g.g533;
        r.lambdaAtEpoch = std::fmod(m_epoch.meanAnomaly + 2.0 * m_epoch.node - 2.0 * theta, kTwoPi);
        r.rateOffset = m_meanAnomalyRate + m_deepSecular.meanAnomaly
                       + 2.0 * (m_nodeRate + m_deepSecular.node - kSiderealRate) - n0;
    } else {
        const double g200 = 1.0 + eccSq * (-2.5 + 0.8125 * eccSq);
        const double g310 = 1.0 + 2.0 * eccSq;
        const double g300 = 1.0 + eccSq * (-6.0 + 6.60937 * eccSq);
        const double f220 = 0.75 * (1.0 + cosI) * (1.0 + cosI);
        const double f311 = 0.9375 * sinI * sinI * (1.0 + 3.0 * cosI) - 0.75 * (1.0 + cosI);
        const double f330 = 1.875 * std::pow(1.0 + cosI, 3);
        const double k = 3.0 * n0 * n0 * aOverN * aOverN;
        r.del1 = k * f311 * g310 * 2.1460748e-6 * aOverN;
        r.del2 = 2.0 * k * f220 * g200 * 1.7891679e-6;
        r.del3 = 3.0 * k * f330 * g300 * 2.2123015e-7 * aOverN;
        r.lambdaAtEpoch = std::fmod(m_epoch.meanAnomaly + m_epoch.node + m_epoch.argPerigee - theta, kTwoPi);
        r.rateOffset = m_meanAnomalyRate + (m_argPerigeeRate + m_nodeRate) - kSiderealRate + m_deepSecular.meanAnomaly
                       + m_deepSecular.argPerigee + m_deepSecular.node - n0;
    }
    // Every integration starts here, so its rates are worked out once.
    m_resonanceAtEpoch.lambda = r.lambdaAtEpoch;
    m_resonanceAtEpoch.meanMotion = n0;
    resonanceRates(m_resonanceAtEpoch);
}

void Sgp4::addThirdBodyPeriodics(double t, MeanElements &e) const
{
    const PeriodicChange s = periodicChange(m_sun, t);
    const PeriodicChange l = periodicChange(m_moon, t);
    // Applied whole, as the 2006 revision does (its offsets at epoch are
    // zero), so the states match the element sets' own propagator.
    const double dEcc = s.ecc + l.ecc;
    const double dInc = s.inc + l.inc;
    const double dL = s.meanLongitude + l.meanLongitude;
    double dArgp = s.argPerigee + l.argPerigee;
    double dNode = s.node + l.node;

    e.inclination += dInc;
    e.eccentricity += dEcc;
    const double sinI = std::sin(e.inclination);
    const double cosI = std::cos(e.inclination);
    if (e.inclination >= 0.2) {
        dNode /= sinI;
        dArgp -= cosI * dNode;
        e.argPerigee += dArgp;
        e.node += dNode;
        e.meanAnomaly += dL;
        return;
    }
    // Near the equator the node and perigee are nearly undefined: apply the
    // changes to the vector (sin i sin Ω, sin i cos Ω) and the longitude
    // instead (Lyddane's modification).
    const double sinNode = std::sin(e.node);
    const double cosNode = std::cos(e.node);
    const double alpha = sinI * sinNode + dNode * cosNode + dInc * cosI * sinNode;
    const double beta = sinI * cosNode - dNode * sinNode + dInc * cosI * cosNode;
    e.node = std::fmod(e.node, kTwoPi);
    const double longitude = e.meanAnomaly + e.argPerigee + cosI * e.node + dL + dArgp - dInc * e.node * sinI;
    const double previousNode = e.node;
    e.node = std::atan2(alpha, beta);
    // Keep the node on the same turn as before, so the longitude stays continuous.
    if (std::fabs(previousNode - e.node) > kPi)
        e.node += e.node < previousNode ? kTwoPi : -kTwoPi;
    e.meanAnomaly += dL;
    e.argPerigee = longitude - e.meanAnomaly - cosI * e.node;
}

void Sgp4::resonanceRates(ResonancePoint &p) const
{
    const Resonance &r = m_resonance;
    const double lambda = p.lambda;
    p.lambdaDot = p.meanMotion + r.rateOffset;
    if (r.kind == 1) {
        constexpr double kFasx2 = 0.13130908, kFasx4 = 2.8843198, kFasx6 = 0.37448087;
        p.meanMotionDot = r.del1 * std::sin(lambda - kFasx2) + r.del2 * std::sin(2.0 * (lambda - kFasx4))
                          + r.del3 * std::sin(3.0 * (lambda - kFasx6));
        p.meanMotionDdot = (r.del1 * std::cos(lambda - kFasx2) + 2.0 * r.del2 * std::cos(2.0 * (lambda - kFasx4))
                            + 3.0 * r.del3 * std::cos(3.0 * (lambda - kFasx6)))
                           * p.lambdaDot;
        return;
    }
    constexpr double kG22 = 5.7686396, kG32 = 0.95240898, kG44 = 1.8014998, kG52 = 1.0508330, kG54 = 4.4108898;
    const double w = m_epoch.argPerigee + m_argPerigeeRate * p.time;
    const double w2 = 2.0 * w;
    const double l2 = 2.0 * lambda;
    p.meanMotionDot = r.d2201 * std::sin(w2 + lambda - kG22) + r.d2211 * std::sin(lambda - kG22)
                      + r.d3210 * std::sin(w + lambda - kG32) + r.d3222 * std::sin(-w + lambda - kG32)
                      + r.d4410 * std::sin(w2 + l2 - kG44) + r.d4422 * std::sin(l2 - kG44)
                      + r.d5220 * std::sin(w + lambda - kG52) + r.d5232 * std::sin(-w + lambda - kG52)
                      + r.d5421 * std::sin(w + l2 - kG54) + r.d5433 * std::sin(-w + l2 - kG54);
    p.meanMotionDdot = (r.d2201 * std::cos(w2 + lambda - kG22) + r.d2211 * std::cos(lambda - kG22)
                        + r.d3210 * std::cos(w + lambda - kG32) + r.d3222 * std::cos(-w + lambda - kG32)
                        + r.d5220 * std::cos(w + lambda - kG52) + r.d5232 * std::cos(-w + lambda - kG52)
                        + 2.0
                              * (r.d4410 * std::cos(w2 + l2 - kG44) + r.d4422 * std::cos(l2 - kG44)
                                 + r.d5421 * std::cos(w + l2 - kG54) + r.d5433 * std::cos(-w + l2 - kG54)))
                       * p.lambdaDot;
}

void Sgp4::integrateResonance(double t, ResonancePoint &carried, MeanElements &e, double &meanMotion) const
{
    // The resonant terms have no closed form: the mean longitude λ and the
    // mean motion are integrated with second-order Taylor steps of half a
    // day from epoch towards t, then a Taylor series from the last point to
    // t. The points lie at whole steps from epoch whatever t is asked for,
    // so the state is a function of t alone (the 2006 revision's fix of the
    // original's dependence on the previous call). That also makes a point
    // reached on the way to an earlier t as good a start as epoch, with
    // bit-for-bit the same result, as long as it lies between epoch and t:
    // the steps cannot be run backwards exactly, so a t on the other side
    // of epoch, or nearer to it, starts again from epoch, as the revision's
    // own code does.
    constexpr double kStep = 720.0;
    const bool onTheWay = t * carried.time > 0.0 && std::fabs(t) >= std::fabs(carried.time);
    ResonancePoint p = onTheWay ? carried : m_resonanceAtEpoch;
    const double step = t > 0 ? kStep : -kStep;
    while (std::fabs(t - p.time) >= kStep) {
        p.lambda += p.lambdaDot * step + p.meanMotionDot * kStep * kStep / 2.0;
        p.meanMotion += p.meanMotionDot * step + p.meanMotionDdot * kStep * kStep / 2.0;
        p.time += step;
        resonanceRates(p);
    }
    carried = p;

    const double ft = t - p.time;
    meanMotion = p.meanMotion + p.meanMotionDot * ft + p.meanMotionDdot * ft * ft * 0.5;
    const double longitude = p.lambda + p.lambdaDot * ft + p.meanMotionDot * ft * ft * 0.5;
    const double theta = wrapTwoPi(m_gmstAtEpoch + t * kSiderealRate);
    e.meanAnomaly = m_resonance.kind == 1 ? longitude - e.node - e.argPerigee + theta
                                          : longitude - 2.0 * e.node + 2.0 * theta;
}

double Sgp4::minutesSinceEpoch(double julianDate) const
{
    return ((julianDate - m_epochJd) - m_epochFraction) * kMinutesPerDay;
}

Sgp4State Sgp4::propagateToJulian(double julianDate) const
{
    return propagate(minutesSinceEpoch(julianDate));
}

Sgp4State Sgp4::propagate(double t) const
{
    ResonancePoint fromEpoch; // at time 0: never taken as a start, so epoch's is used
    return propagate(t, fromEpoch);
}

Sgp4State Sgp4::propagate(double t, ResonancePoint &carried) const
{
    if (!std::isfinite(t) || std::abs(t) > kMaxYearsFromEpoch * 365.25 * kMinutesPerDay) {
        Sgp4State refused;
        refused.error = Sgp4Error::TimeOutOfRange;
        return refused;
    }
    // Secular gravity and drag.
    const double meanAnomalyDf = m_epoch.meanAnomaly + m_meanAnomalyRate * t;
    const double argPerigeeDf = m_epoch.argPerigee + m_argPerigeeRate * t;
    const double nodeDf = m_epoch.node + m_nodeRate * t;
    const double t2 = t * t;

    MeanElements m;
    m.meanAnomaly = meanAnomalyDf;
    m.argPerigee = argPerigeeDf;
    m.node = nodeDf + m_nodeDragCoeff * t2;
    m.eccentricity = m_epoch.eccentricity;
    m.inclination = m_epoch.inclination;
    double tempA = 1.0 - m_c1 * t;
    double tempE = m_bstar * m_c4 * t;
    double tempL = m_t2 * t2;
    if (!m_simpleDrag) {
        const double dArgp = m_argPerigeeDragCoeff * t;
        const double delta = 1.0 + m_eta * std::cos(meanAnomalyDf);
        const double dM = m_meanAnomalyDragCoeff * (delta * delta * delta - m_delta0Cubed);
        m.meanAnomaly = meanAnomalyDf + dArgp + dM;
        m.argPerigee = argPerigeeDf - dArgp - dM;
        const double t3 = t2 * t, t4 = t3 * t;
        tempA -= m_d2 * t2 + m_d3 * t3 + m_d4 * t4;
        tempE += m_bstar * m_c5 * (std::sin(m.meanAnomaly) - m_sinMeanAnomalyAtEpoch);
        tempL += m_t3 * t3 + t4 * (m_t4 + t * m_t5);
    }

    double meanMotion = m_epoch.meanMotion;
    if (m_deepSpace) {
        m.eccentricity += m_deepSecular.eccentricity * t;
        m.inclination += m_deepSecular.inclination * t;
        m.argPerigee += m_deepSecular.argPerigee * t;
        m.node += m_deepSecular.node * t;
        m.meanAnomaly += m_deepSecular.meanAnomaly * t;
        if (m_resonance.kind != 0)
            integrateResonance(t, carried, m, meanMotion);
    }

    Sgp4State state;
    if (meanMotion <= 0.0) {
        state.error = Sgp4Error::MeanMotion;
        return state;
    }
    // Without resonance the mean motion is the epoch's, and so is its
    // semi-major axis: no need for the power every time.
    const double unperturbedAxis = meanMotion == m_epoch.meanMotion ? m_semiMajorAtEpoch
                                                                    : std::pow(kXke / meanMotion, kTwoThirds);
    const double semiMajor = unperturbedAxis * tempA * tempA;
    meanMotion = kXke / (semiMajor * std::sqrt(semiMajor));
    m.eccentricity -= tempE;
    if (m.eccentricity >= 1.0 || m.eccentricity < -0.001) {
        state.error = Sgp4Error::MeanEccentricity;
        return state;
    }
    m.eccentricity = std::max(m.eccentricity, 1e-6);
    m.meanAnomaly += m_epoch.meanMotion * tempL;
    const double longitude = m.meanAnomaly + m.argPerigee + m.node;
    m.node = std::fmod(m.node, kTwoPi);
    m.argPerigee = std::fmod(m.argPerigee, kTwoPi);
    m.meanAnomaly = std::fmod(std::fmod(longitude, kTwoPi) - m.argPerigee - m.node, kTwoPi);

    if (m_deepSpace) {
        addThirdBodyPeriodics(t, m);
        if (m.inclination < 0.0) {
            m.inclination = -m.inclination;
            m.node += kPi;
            m.argPerigee -= kPi;
        }
        if (m.eccentricity < 0.0 || m.eccentricity > 1.0) {
            state.error = Sgp4Error::PerturbedEccentricity;
            return state;
        }
    }
    return positionAndVelocity(m, semiMajor, meanMotion);
}

Sgp4State Sgp4::positionAndVelocity(const MeanElements &m, double a, double meanMotion) const
{
    Sgp4State state;
    const double sinI = std::sin(m.inclination);
    const double cosI = std::cos(m.inclination);
    double lCoefficient = m_lCoefficient;
    double ayCoefficient = m_ayCoefficient;
    if (m_deepSpace) {
        // The inclination moved with the sun and moon: refresh the J3 terms.
        ayCoefficient = -0.5 * kJ3OverJ2 * sinI;
        const double onePlusCos = std::fabs(cosI + 1.0) > 1.5e-12 ? 1.0 + cosI : 1.5e-12;
        lCoefficient = -0.25 * kJ3OverJ2 * sinI * (3.0 + 5.0 * cosI) / onePlusCos;
    }

    // Long-period periodics (J3), in equinoctial elements.
    const double e = m.eccentricity;
    const double axn = e * std::cos(m.argPerigee);
    const double k = 1.0 / (a * (1.0 - e * e));
    const double ayn = e * std::sin(m.argPerigee) + k * ayCoefficient;
    const double meanLongitude = m.meanAnomaly + m.argPerigee + m.node + k * lCoefficient * axn;

    const double u = std::fmod(meanLongitude - m.node, kTwoPi);
    const double ea = solveKepler(u, axn, ayn);
    const double sinEa = std::sin(ea), cosEa = std::cos(ea);

    // Short-period periodics (J2).
    const double eCosE = axn * cosEa + ayn * sinEa;
    const double eSinE = axn * sinEa - ayn * cosEa;
    const double eLSq = axn * axn + ayn * ayn;
    const double semiLatus = a * (1.0 - eLSq);
    if (semiLatus < 0.0) {
        state.error = Sgp4Error::SemiLatusRectum;
        return state;
    }
    const double r = a * (1.0 - eCosE);
    const double rDot = std::sqrt(a) * eSinE / r;
    const double rfDot = std::sqrt(semiLatus) / r;
    const double betaL = std::sqrt(1.0 - eLSq);
    const double w = eSinE / (1.0 + betaL);
    const double sinU = a / r * (sinEa - ayn - axn * w);
    const double cosU = a / r * (cosEa - axn + ayn * w);
    double argLatitude = std::atan2(sinU, cosU);
    const double sin2u = 2.0 * cosU * sinU;
    const double cos2u = 1.0 - 2.0 * sinU * sinU;
    const double k1 = 0.5 * kJ2 / semiLatus;
    const double k2 = k1 / semiLatus;

    const double cosSq = cosI * cosI;
    const double theta2Term = 3.0 * cosSq - 1.0;
    const double sinSq = 1.0 - cosSq;
    const double sevenCosSqMinusOne = 7.0 * cosSq - 1.0;

    const double radius = r * (1.0 - 1.5 * k2 * betaL * theta2Term) + 0.5 * k1 * sinSq * cos2u;
    argLatitude -= 0.25 * k2 * sevenCosSqMinusOne * sin2u;
    const double node = m.node + 1.5 * k2 * cosI * sin2u;
    const double inclination = m.inclination + 1.5 * k2 * cosI * sinI * cos2u;
    const double radiusDot = rDot - meanMotion * k1 * sinSq * sin2u / kXke;
    const double rfDotTotal = rfDot + meanMotion * k1 * (sinSq * cos2u + 1.5 * theta2Term) / kXke;

    // Orientation vectors: U points at the satellite, V along its track.
    const double sinArgLat = std::sin(argLatitude), cosArgLat = std::cos(argLatitude);
    const double sinNode = std::sin(node), cosNode = std::cos(node);
    const double sinInc = std::sin(inclination), cosInc = std::cos(inclination);
    const double mx = -sinNode * cosInc;
    const double my = cosNode * cosInc;
    const Vec3 uVec{mx * sinArgLat + cosNode * cosArgLat, my * sinArgLat + sinNode * cosArgLat, sinInc * sinArgLat};
    const Vec3 vVec{mx * cosArgLat - cosNode * sinArgLat, my * cosArgLat - sinNode * sinArgLat, sinInc * cosArgLat};

    state.positionKm = uVec * (radius * kEarthRadiusKm);
    state.velocityKmS = (uVec * radiusDot + vVec * rfDotTotal) * kVelocityKmS;
    if (radius < 1.0)
        state.error = Sgp4Error::Decayed;
    return state;
}

} // namespace slew::sky
