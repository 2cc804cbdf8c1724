// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The answer to a tracker's `p`, formatted once for each position and kept
// for the next asker. Trackers ask far more often than the position changes
// (ten of them at 10 Hz while a resting rotator is polled once a second),
// and printing two numbers was most of the work of an answer.
//
// Only the plain form is kept: the extended one echoes the request's own
// header and is rare enough to be formatted every time.

#include "rotctldrequest.h"

#include <QByteArray>
#include <QtGlobal>

namespace slew::bridge {

class PositionAnswer {
public:
    // formatPosition(request, az, el), reused while the position is the same.
    QByteArray answer(const RotctldRequest &request, double az, double el);

private:
    // The same to the bit: -0.0 prints as "-0.00", which == would take for 0.
    bool holds(double az, double el) const;

    bool m_valid = false;
    double m_az = 0.0, m_el = 0.0;
    QByteArray m_plain;
};

} // namespace slew::bridge
