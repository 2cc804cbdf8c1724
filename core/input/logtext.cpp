// SPDX-License-Identifier: GPL-3.0-or-later
#include "logtext.h"

#include <algorithm>

namespace slew::input {

QString loggableText(const QString &text, int maxChars)
{
    QString out;
    out.reserve(std::min<qsizetype>(text.size(), maxChars) + 24);
    qsizetype used = 0;
    for (; used < text.size(); ++used) {
        const char16_t c = text.at(used).unicode();
        const bool control = c < 0x20 || (c >= 0x7f && c < 0xa0);
        const QString piece = control ? QStringLiteral("\\x%1").arg(int(c), 2, 16, QLatin1Char('0')) : QString(QChar(c));
        if (out.size() + piece.size() > maxChars)
            break;
        out += piece;
    }
    if (used < text.size())
        out += QStringLiteral("… (%1 more bytes)").arg(text.size() - used);
    return out;
}

bool LogAllowance::take(qint64 nowMs)
{
    if (m_lastMs >= 0)
        m_tokens = std::min(m_burst, m_tokens + std::max<qint64>(0, nowMs - m_lastMs) / 1000.0 * m_perSecond);
    m_lastMs = nowMs;
    if (m_tokens >= 1.0) {
        m_tokens -= 1.0;
        return true;
    }
    ++m_suppressed;
    return false;
}

int LogAllowance::takeSuppressed()
{
    const int n = m_suppressed;
    m_suppressed = 0;
    return n;
}

} // namespace slew::input
