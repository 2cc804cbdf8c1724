// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The rotator's last reading, as rotctld clients are told it, readable from
// any thread.
//
// The rotctld server answers `p` on each client's own thread (rotctldclient.h
// says why) while the session that reads the rotator lives on the main one.
// The session's thread writes a reading here whenever it has a new one;
// client threads read it. Azimuth and elevation are always a pair from one
// reading, never the azimuth of one and the elevation of the next.

#include <mutex>

namespace slew::bridge {

class SharedPosition {
public:
    struct Reading {
        // False while there is no link or no reading yet: `p` is answered
        // RPRT -6 (input/output error), as Hamlib's rotctld does when its
        // rotator does not answer.
        bool known = false;
        double azimuth = 0.0; // 0..360: trackers do not speak overlap
        double elevation = 0.0;
    };

    void set(const Reading &reading)
    {
        const std::lock_guard lock(m_mutex);
        m_reading = reading;
    }
    Reading get() const
    {
        const std::lock_guard lock(m_mutex);
        return m_reading;
    }

private:
    mutable std::mutex m_mutex;
    Reading m_reading;
};

} // namespace slew::bridge
