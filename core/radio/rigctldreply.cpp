// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigctldreply.h"

#include "input/finitenumber.h"
#include "input/logtext.h"

namespace slew::radio {

namespace {

// A line from the peer, quoted for a message: short, control characters escaped.
QString quoted(QByteArrayView line)
{
    return QLatin1Char('\'') + input::loggableText(QString::fromLatin1(line), 40) + QLatin1Char('\'');
}

} // namespace

RigctldReply::RigctldReply(QByteArray longName, QByteArray valueKey, Form form)
    : m_longName(std::move(longName)), m_valueKey(std::move(valueKey)), m_form(form)
{
}

RigctldReply::Status RigctldReply::broken(const QString &why)
{
    m_problem = why;
    m_status = Status::Broken;
    return m_status;
}

RigctldReply::Status RigctldReply::take(QByteArrayView line)
{
    if (m_status != Status::Incomplete)
        return m_status;
    if (++m_lines > kMaxLines)
        return broken(QStringLiteral("no RPRT within %1 lines").arg(kMaxLines));
    if (line.endsWith('\r'))
        line.chop(1);

    if (line.isEmpty())
        return m_status; // nothing in either form; counted against kMaxLines

    const bool first = !m_started;
    m_started = true;
    const bool echo = line.startsWith(m_longName) && line.size() > m_longName.size() && line[m_longName.size()] == ':';
    if (first && echo) {
        if (m_form == Form::Default)
            return broken(QStringLiteral("expected the default form, got %1").arg(quoted(line)));
        m_extended = true; // the echo of the command: the extended form
        return m_status;
    }
    if (first && m_form == Form::Extended)
        return broken(QStringLiteral("expected '%1:', got %2").arg(QString::fromLatin1(m_longName), quoted(line)));

    if (line.startsWith("RPRT")) {
        // The end of every extended answer, and of a set or an error in the default form.
        const std::optional<int> code = line.size() > 4 && line[4] == ' '
            ? input::wholeNumber(QString::fromLatin1(line.sliced(5)))
            : std::nullopt;
        if (!code)
            return broken(QStringLiteral("%1 has no error code").arg(quoted(line)));
        // In the default form a get that worked answers with its value alone.
        if (!m_extended && *code == 0 && !m_valueKey.isEmpty())
            return broken(QStringLiteral("%1 where a value was due").arg(quoted(line)));
        m_code = *code;
        m_status = Status::Complete;
        return m_status;
    }

    // A record `Key: value`, the extended form's; the default form may carry one too.
    const QByteArray keyed = m_valueKey + ": ";
    const bool ours = !m_valueKey.isEmpty() && line.startsWith(keyed);
    if (m_extended) {
        if (ours) {
            if (m_value)
                return broken(QStringLiteral("two %1 records").arg(QString::fromLatin1(m_valueKey)));
            m_value = QString::fromLatin1(line.sliced(keyed.size()));
        }
        return m_status; // another record of the answer: not asked for
    }

    // The default form: a get's value alone on its line, and nothing after it.
    if (m_valueKey.isEmpty())
        return broken(QStringLiteral("expected RPRT, got %1").arg(quoted(line)));
    m_value = QString::fromLatin1(ours ? line.sliced(keyed.size()) : line);
    m_status = Status::Complete;
    return m_status;
}

} // namespace slew::radio
