// SPDX-License-Identifier: GPL-3.0-or-later
#include "positionanswer.h"

#include <cstring>

namespace slew::bridge {

QByteArray PositionAnswer::answer(const RotctldRequest &request, double az, double el)
{
    if (request.extended)
        return formatPosition(request, az, el);
    if (!holds(az, el)) {
        m_plain = formatPosition(request, az, el);
        m_az = az;
        m_el = el;
        m_valid = true;
    }
    return m_plain; // shared, not copied
}

bool PositionAnswer::holds(double az, double el) const
{
    return m_valid && std::memcmp(&az, &m_az, sizeof az) == 0 && std::memcmp(&el, &m_el, sizeof el) == 0;
}

} // namespace slew::bridge
