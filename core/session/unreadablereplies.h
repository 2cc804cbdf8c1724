// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Whether a controller's replies are unreadable as a condition rather than
// reply by reply: a stream of garbage (a wrong baud rate, a wrong dialect, a
// failing controller) raises it once, and it clears when readable replies
// have come back for a whole window with no unreadable one among them. A
// stray bad reply now and then does not raise it, and readable replies
// mixed into the garbage do not make it flap.
//
// Counts are kept per second over the last window, so memory is fixed
// however long the stream lasts. Pure code: the session gives it the time.

#include <QtGlobal>

#include <array>

namespace slew::session {

class UnreadableReplies {
public:
    static constexpr int kWindowSeconds = 10;
    static constexpr int kRaiseAt = 10; // unreadable replies within the window

    // One unreadable reply at `nowMs`: true when this raises the condition.
    bool noteUnreadable(qint64 nowMs);
    // One readable reply at `nowMs`: true when this clears the condition.
    bool noteReadable(qint64 nowMs);
    bool raised() const { return m_raised; }
    // Unreadable replies within the window that ends at `nowMs`.
    int inWindow(qint64 nowMs) const;
    // A new link: its clock may start again from zero.
    void reset() { *this = UnreadableReplies{}; }

private:
    struct Second {
        qint64 second = -1;
        int count = 0;
    };
    std::array<Second, kWindowSeconds> m_seconds{};
    qint64 m_lastUnreadableMs = -1;
    bool m_raised = false;
};

} // namespace slew::session
