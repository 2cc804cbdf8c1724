// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The log lines about what a controller sent (unreadable replies, alarms,
// damaged frames): a burst, then one now and then, and the rest counted by
// kind and reported as a summary ("N more unreadable replies from the
// controller suppressed"). A faulty controller can send thousands of bad
// replies a second; this keeps the window's event log and the station's
// journal to a few lines a minute, and no line is lost without a count.
// Pure code: the session gives it the time and emits what it returns.

#include "input/logtext.h"

#include <QString>
#include <QStringList>

#include <array>

namespace slew::session {

class ControllerLogAllowance {
public:
    enum class Kind { Unreadable, Alarm, Damaged };

    static constexpr double kBurst = 10.0;
    static constexpr double kPerSecond = 1.0 / 30.0;
    // How long a count may wait for the next allowed line before it is
    // reported on its own (the session's summary timer).
    static constexpr int kSummaryMs = 30000;

    // The lines to log for one more line of this kind at `nowMs`: nothing
    // when it is over the allowance (it is counted), else the summary of
    // what was held back, if anything, and then the line itself.
    QStringList take(Kind kind, qint64 nowMs, const QString &line);
    // What was held back since the last summary, as one line (empty if
    // nothing), and the counts start again.
    QString takeSummary();
    bool holdsBack() const;
    qint64 heldBack(Kind kind) const { return m_held[size_t(kind)]; }

private:
    input::LogAllowance m_allowance{kBurst, kPerSecond};
    std::array<qint64, 3> m_held{}; // 64 bits: a flood may last for days
};

} // namespace slew::session
