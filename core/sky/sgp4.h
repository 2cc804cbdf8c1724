// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// SGP4/SDP4: NORAD's analytic propagator for its general-perturbations element sets, as
// published in Hoots & Roehrich, "Spacetrack Report #3" (1980), with the
// corrections of Vallado, Crawford, Hujsak & Kelso, "Revisiting Spacetrack
// Report #3" (AIAA 2006-6753): WGS-72 constants, the "improved" operation
// mode, the Lyddane choice for low inclinations and the resonance integrator
// stepped from epoch. Elements must be propagated with the same model that
// fitted them, so the constants here are not a choice.
//
// Orbits with periods of 225 minutes or more get the deep-space terms: the
// secular and long-period pulls of the sun and moon, and the resonances of
// 12-hour and 24-hour orbits with the earth's gravity field.
//
// A propagator is built once per element set and is then a pure function of
// time: propagate() is const and safe to call from any thread. For one set
// at many times in a row, Sgp4Propagator (sgp4propagator.h) carries the
// resonance integration from one call to the next, with the same results.

#include "skyvector.h"
#include "elementset.h"

namespace slew::sky {

class Sgp4Propagator;

enum class Sgp4Error {
    None = 0,
    MeanEccentricity = 1,      // mean eccentricity left [0, 1): the elements are unusable at this time
    MeanMotion = 2,            // mean motion went negative
    PerturbedEccentricity = 3, // eccentricity after lunar-solar periodics left [0, 1]
    SemiLatusRectum = 4,       // the orbit degenerated (p < 0)
    Decayed = 6,               // the position is below the earth's surface
    TimeOutOfRange = 7,        // not a finite time, or more than kMaxYearsFromEpoch from the epoch
};

// The furthest from its epoch a set is propagated: far beyond any use of a
// set, and it bounds the deep-space resonance integration (half-day steps)
// to some 73,000 steps rather than looping for ever on a time like 1e300.
constexpr double kMaxYearsFromEpoch = 100.0;

QString sgp4ErrorText(Sgp4Error error);

struct Sgp4State {
    Vec3 positionKm;     // TEME frame
    Vec3 velocityKmS;
    Sgp4Error error = Sgp4Error::None;
    bool ok() const { return error == Sgp4Error::None; }
};

class Sgp4 {
public:
    explicit Sgp4(const ElementSet &elements);

    // State at a number of minutes after the element set's epoch (negative
    // is before it).
    Sgp4State propagate(double minutesSinceEpoch) const;
    // State at a Julian date (UTC).
    Sgp4State propagateToJulian(double julianDate) const;

    double epochJulian() const { return m_epochJd + m_epochFraction; }
    double minutesSinceEpoch(double julianDate) const;
    bool isDeepSpace() const { return m_deepSpace; }
    const ElementSet &elements() const { return m_elements; }
    // Error already present at epoch (an impossible set): nothing to propagate.
    Sgp4Error initialError() const { return m_initialError; }

    // The parts of the model, in the report's own symbols where it has them.
    struct MeanElements {
        double eccentricity = 0, inclination = 0, node = 0, argPerigee = 0, meanAnomaly = 0;
        double meanMotion = 0; // rad/min, Brouwer ("un-Kozai'd")
    };
    struct ThirdBody {        // long-period periodic amplitudes of the sun or the moon
        double e2 = 0, e3 = 0, i2 = 0, i3 = 0, l2 = 0, l3 = 0, l4 = 0;
        double gh2 = 0, gh3 = 0, gh4 = 0, h2 = 0, h3 = 0;
        double meanAnomalyAtEpoch = 0, meanMotion = 0, eccentricity = 0;
    };
    struct Resonance {
        int kind = 0;         // 0 none, 1 one-day (geosynchronous), 2 half-day (Molniya)
        double del1 = 0, del2 = 0, del3 = 0;
        double d2201 = 0, d2211 = 0, d3210 = 0, d3222 = 0, d4410 = 0, d4422 = 0;
        double d5220 = 0, d5232 = 0, d5421 = 0, d5433 = 0;
        double lambdaAtEpoch = 0; // xlamo
        double rateOffset = 0;    // xfact
    };
    struct DeepSecular {      // secular rates from the sun and moon, rad/min
        double eccentricity = 0, inclination = 0, meanAnomaly = 0, argPerigee = 0, node = 0;
    };
    // One point of the resonance integration: the mean longitude λ and the
    // mean motion a whole number of half-day steps from epoch, with their
    // rates there (which the next step and the Taylor series to t both use).
    struct ResonancePoint {
        double time = 0;      // minutes from epoch
        double lambda = 0, meanMotion = 0;
        double lambdaDot = 0, meanMotionDot = 0, meanMotionDdot = 0;
    };

private:
    friend class Sgp4Propagator;
    // The state at t, the resonance integration going on from `carried`
    // when that is on the way from epoch to t, else from epoch; `carried`
    // is left at the last point reached.
    Sgp4State propagate(double minutesSinceEpoch, ResonancePoint &carried) const;
    void initialiseNearEarth(double perigeeKm);
    void initialiseDeepSpace(double epochSince1950);
    void addThirdBodyPeriodics(double t, MeanElements &e) const;
    void resonanceRates(ResonancePoint &p) const;
    void integrateResonance(double t, ResonancePoint &carried, MeanElements &e, double &meanMotion) const;
    Sgp4State positionAndVelocity(const MeanElements &m, double semiMajorAxis, double meanMotion) const;

    ElementSet m_elements;
    double m_epochJd = 0;
    double m_epochFraction = 0;
    bool m_deepSpace = false;
    bool m_simpleDrag = false;   // perigee under 220 km: fewer drag terms
    Sgp4Error m_initialError = Sgp4Error::None;

    MeanElements m_epoch;        // mean elements at epoch
    double m_bstar = 0;
    double m_gmstAtEpoch = 0;
    double m_semiMajorAtEpoch = 0; // earth radii, from the Brouwer mean motion

    // Secular rates and drag coefficients (Spacetrack Report #3 symbols).
    double m_meanAnomalyRate = 0, m_argPerigeeRate = 0, m_nodeRate = 0;
    double m_c1 = 0, m_c4 = 0, m_c5 = 0, m_eta = 0;
    double m_argPerigeeDragCoeff = 0, m_meanAnomalyDragCoeff = 0, m_nodeDragCoeff = 0;
    double m_d2 = 0, m_d3 = 0, m_d4 = 0;
    double m_t2 = 0, m_t3 = 0, m_t4 = 0, m_t5 = 0;
    double m_delta0Cubed = 0, m_sinMeanAnomalyAtEpoch = 0;
    double m_lCoefficient = 0, m_ayCoefficient = 0;  // long-period J3 terms
    double m_cosI = 0, m_sinI = 0;

    ThirdBody m_sun, m_moon;
    DeepSecular m_deepSecular;
    Resonance m_resonance;
    ResonancePoint m_resonanceAtEpoch; // where every integration starts
};

// Greenwich mean sidereal time, IAU-82 (radians, 0..2π), for a UT1 Julian date.
double gmstIau82(double julianDateUt1);

} // namespace slew::sky
