// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A small 3-vector and the angles and time scales the sky code shares.

#include <cmath>
#include <numbers>

namespace slew::sky {

struct Vec3 {
    double x = 0, y = 0, z = 0;

    Vec3 operator+(const Vec3 &o) const { return {x + o.x, y + o.y, z + o.z}; }
    Vec3 operator-(const Vec3 &o) const { return {x - o.x, y - o.y, z - o.z}; }
    Vec3 operator*(double k) const { return {x * k, y * k, z * k}; }
    double dot(const Vec3 &o) const { return x * o.x + y * o.y + z * o.z; }
    double norm() const { return std::sqrt(dot(*this)); }
};

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline constexpr double kDegree = std::numbers::pi / 180.0;
inline constexpr double kMinutesPerDay = 1440.0;
inline constexpr double kSecondsPerDay = 86400.0;
inline constexpr double kJ2000 = 2451545.0;           // Julian date of 2000-01-01 12:00 TT
inline constexpr double kUnixEpochJulian = 2440587.5; // 1970-01-01 00:00 UTC

inline double degrees(double radians) { return radians / kDegree; }
inline double radians(double degreesValue) { return degreesValue * kDegree; }

// Angle into [0, 2π).
inline double wrapTwoPi(double a)
{
    a = std::fmod(a, kTwoPi);
    return a < 0 ? a + kTwoPi : a;
}

// Degrees into [0, 360).
inline double wrap360(double a)
{
    a = std::fmod(a, 360.0);
    return a < 0 ? a + 360.0 : a;
}

inline double julianFromUnixSeconds(double seconds) { return kUnixEpochJulian + seconds / kSecondsPerDay; }
inline double unixSecondsFromJulian(double jd) { return (jd - kUnixEpochJulian) * kSecondsPerDay; }

} // namespace slew::sky
