// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Text from a client or a device, made safe for a terminal or a journal:
// control characters (C0, DEL, C1, so no escape sequences) are written as
// \xNN, and a line longer than `maxChars` is cut with a note of how much
// was left out. Pure code.

#include <QString>

namespace slew::input {

inline constexpr int kMaxLoggedChars = 200;

QString loggableText(const QString &text, int maxChars = kMaxLoggedChars);

// A per-client allowance of log lines: a burst, then a steady rate. Lines
// over it are counted, not written, and the count is reported later.
class LogAllowance {
public:
    static constexpr double kBurst = 20.0;
    static constexpr double kPerSecond = 2.0;

    LogAllowance() = default;
    // A source that may speak thousands of times a second (a controller)
    // gets a smaller burst and a slower rate than a client typing commands.
    LogAllowance(double burst, double perSecond) : m_burst(burst), m_perSecond(perSecond), m_tokens(burst) {}

    // Whether one more line may be written at time `nowMs`.
    bool take(qint64 nowMs);
    // Lines refused since the last call, and resets the count.
    int takeSuppressed();
    int suppressed() const { return m_suppressed; }

private:
    double m_burst = kBurst;
    double m_perSecond = kPerSecond;
    double m_tokens = kBurst;
    qint64 m_lastMs = -1;
    int m_suppressed = 0;
};

} // namespace slew::input
