// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The site's horizon: the lowest usable elevation at each azimuth, where
// trees, buildings and hills hide the sky. It is given as points (azimuth,
// elevation) and read between them as straight lines, round through north;
// a wall is two points at one azimuth (the foot and the top, in either
// order), and at that azimuth the mask is the higher of the two.
//
// A file of it is one `azimuth elevation` pair a line, in degrees, with `#`
// starting a comment (docs/sky.md):
//
//     # the barn to the south-east
//     120  0
//     120 18
//     150 18
//     150  0
//
// AOS and LOS are where the target rises above the mask (or the minimum
// elevation asked for, whichever is higher) and sets below it: passes.h
// applies the mask that sky::Site carries. Pure code.

#include <QList>
#include <QString>

#include <memory>
#include <optional>

namespace slew::sky {

struct HorizonPoint {
    double azimuthDeg = 0;   // 0..360
    double elevationDeg = 0; // -5..90
};

class HorizonMask {
public:
    // The points in file order; false with *error when they cannot make a
    // mask: none, a number out of range, more than two at one azimuth.
    static std::optional<HorizonMask> fromPoints(const QList<HorizonPoint> &points, QString *error);

    // The mask's elevation at `azimuthDeg` (any finite bearing; wrapped).
    double elevationAt(double azimuthDeg) const;
    // The lowest and highest elevations the mask holds.
    double lowestDeg() const { return m_lowest; }
    double highestDeg() const { return m_highest; }
    // The points sorted by azimuth, a wall's two in file order.
    const QList<HorizonPoint> &points() const { return m_points; }
    // "14 points, 0.0° to 25.0° (highest at 140.0°)"
    QString describe() const;

private:
    QList<HorizonPoint> m_points;
    double m_lowest = 0;
    double m_highest = 0;
};

// The limits of a mask file.
inline constexpr qint64 kMaxHorizonFileBytes = 1024 * 1024;
inline constexpr int kMaxHorizonPoints = 7200;

struct HorizonFile {
    std::shared_ptr<const HorizonMask> mask; // null when refused
    QString error;                           // "PATH:LINE: why", or why the file cannot be read
};

// Reads a mask file as above: a regular file of at most 1 MiB (input/
// boundedfile.h), every number finite and in range, each refusal naming the
// file and the line. Nothing is kept of a file with any fault.
HorizonFile readHorizonFile(const QString &path);
// The same from text already read; `source` names it in messages.
HorizonFile parseHorizonText(const QString &text, const QString &source);

} // namespace slew::sky
