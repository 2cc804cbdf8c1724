// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Some controllers echo every line they hear before they answer it. An echo
// must not be taken for a reply: a set-position coming back reads exactly
// like a position report. EchoFilter keeps the last few set-commands sent
// and tells an echo from a reply:
//   - a command, or a query form, coming back is an echo, and says that
//     this controller echoes;
//   - speeds as VL..VD are an echo (controllers report speed in IP7/IP8);
//   - a position that repeats one sent within the last second is an echo,
//     but only from a controller already seen echoing.

#include "protocol/message.h"

#include <QtGlobal>

#include <array>

namespace slew::session {

class EchoFilter {
public:
    static constexpr qint64 kWindowMs = 1000;

    // A new link: nothing sent yet, nothing known about echoing.
    void reset();
    void noteSent(const protocol::Message &m, qint64 nowMs);
    // Whether `m` is an echo; counted in ignored() when it is.
    bool isEcho(const protocol::Message &m, qint64 nowMs);
    bool controllerEchoes() const { return m_controllerEchoes; }
    int ignored() const { return m_ignored; }

private:
    bool judge(const protocol::Message &m, qint64 nowMs);

    struct Sent {
        protocol::Message message;
        qint64 atMs = 0;
    };
    std::array<Sent, 8> m_sent{};
    int m_next = 0;
    bool m_controllerEchoes = false;
    int m_ignored = 0; // over the session's life, as before a reconnect
};

} // namespace slew::session
