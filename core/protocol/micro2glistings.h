// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the Micro-2g program's `Z` and `V` listings say, as numbers.
//
// The parser (parser_micro2g.cpp) checks the listings' form and hands them
// on as text; these read that text into values a page or a test can use.
// The forms are in docs/protocol.md ("Micro-2g"): a calibration line is
// `Z1L 3990=000 Z1R 2440=090 Z1D 450`, an A/D listing `V1=3990 V2=3990 ...`.

#include <QByteArrayView>
#include <QList>
#include <QMetaType>

#include <optional>

namespace slew::protocol {

// One rotor's two-point calibration as the controller holds it.
struct Micro2gCalibration {
    int rotor = 0;         // 1..4
    int leftAdc = 0;       // the A/D reading at the left (counter-clockwise) stop
    int leftBearing = 0;   // the bearing there, 0..359
    int rightAdc = 0;      // the reading at the right stop
    int rightBearing = 0;  // the bearing there, as entered
    int degreeRange = 0;   // degrees of travel from the left stop to the right

    friend bool operator==(const Micro2gCalibration &, const Micro2gCalibration &) = default;
};

// One rotor's A/D reading.
struct Micro2gAdcReading {
    int rotor = 0;  // 1..4
    int counts = 0; // 0..4095
};

// A line of the `Z` answer, in any case and with any blanks between its six
// words; nothing when it is not one.
std::optional<Micro2gCalibration> readMicro2gCalibration(QByteArrayView line);

// The `V` answer (`V1=3990 V2=...`, blanks or commas between); empty when
// any item does not read.
QList<Micro2gAdcReading> readMicro2gAdcReadings(QByteArrayView listing);

} // namespace slew::protocol

Q_DECLARE_METATYPE(slew::protocol::Micro2gCalibration)
