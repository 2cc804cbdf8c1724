// SPDX-License-Identifier: GPL-3.0-or-later
#include "controllerlogallowance.h"

#include <QCoreApplication>

namespace slew::session {

QStringList ControllerLogAllowance::take(Kind kind, qint64 nowMs, const QString &line)
{
    if (!m_allowance.take(nowMs)) {
        ++m_held[size_t(kind)];
        m_allowance.takeSuppressed(); // counted here, in 64 bits
        return {};
    }
    QStringList lines;
    if (const QString summary = takeSummary(); !summary.isEmpty())
        lines << summary;
    lines << line;
    return lines;
}

QString ControllerLogAllowance::takeSummary()
{
    auto tr = [](const char *text) { return QCoreApplication::translate("ControllerLogAllowance", text); };
    QStringList parts;
    auto part = [&](Kind kind, const char *one, const char *many) {
        const qint64 n = m_held[size_t(kind)];
        if (n > 0)
            parts << tr(n == 1 ? one : many).arg(n);
        m_held[size_t(kind)] = 0;
    };
    part(Kind::Unreadable, "%1 more unreadable reply", "%1 more unreadable replies");
    part(Kind::Alarm, "%1 more alarm", "%1 more alarms");
    part(Kind::Damaged, "%1 more damaged reply", "%1 more damaged replies");
    if (parts.isEmpty())
        return {};
    return tr("%1 from the controller suppressed").arg(parts.join(QStringLiteral(", ")));
}

bool ControllerLogAllowance::holdsBack() const
{
    for (const qint64 n : m_held) {
        if (n > 0)
            return true;
    }
    return false;
}

} // namespace slew::session
