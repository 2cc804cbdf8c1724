#include "registerreadback.h"

#include "input/finitenumber.h"

#include "session/rotatorsession.h"

#include <cmath>

namespace slew::tuning {

QString RegisterCheck::describe() const
{
    const QString read = answered ? QStringLiteral("CR%1 = %2").arg(reg).arg(readBack)
                                  : QObject::tr("CR%1 not answered").arg(reg);
    const QString verdict = ok ? QObject::tr("ok") : QObject::tr("MISMATCH");
    if (written.isEmpty())
        return answered ? read : read + QStringLiteral(" — ") + verdict;
    return QStringLiteral("CW%1 %2 → %3 — %4").arg(reg).arg(written, read, verdict);
}

RegisterReadback::RegisterReadback(session::RotatorSession *session, QObject *parent)
    : QObject(parent), m_session(session)
{
    m_timer.setSingleShot(true);
    // Each CR already retries inside the session; this only ends the wait
    // for a controller that never answers at all.
    m_timer.setInterval(4000);
    connect(&m_timer, &QTimer::timeout, this, &RegisterReadback::finish);
    connect(m_session, &session::RotatorSession::configValueReceived, this, &RegisterReadback::onValue);
}

QString RegisterReadback::format(double value)
{
    QString text = QString::number(value, 'f', 4);
    while (text.contains(u'.') && (text.endsWith(u'0') || text.endsWith(u'.')))
        text.chop(1);
    return text;
}

bool RegisterReadback::matches(const QString &written, const QString &readBack)
{
    const std::optional<double> w = input::finiteNumber(written);
    const std::optional<double> r = input::finiteNumber(readBack);
    if (w && r)
        return std::fabs(*w - *r) <= std::max(0.0051, 1e-4 * std::fabs(*w));
    return written.trimmed() == readBack.trimmed();
}

bool RegisterReadback::allOk() const
{
    for (const RegisterCheck &c : m_results) {
        if (!c.ok)
            return false;
    }
    return !m_results.isEmpty();
}

std::optional<double> RegisterReadback::number(int reg) const
{
    for (const RegisterCheck &c : m_results) {
        if (c.reg == reg && c.answered) {
            if (const std::optional<double> v = input::finiteNumber(c.readBack))
                return v;
        }
    }
    return std::nullopt;
}

bool RegisterReadback::run(const QMap<int, QString> &writes, const QList<int> &reads)
{
    m_error.clear();
    if (m_running) {
        m_error = tr("a register read-back is already running");
        return false;
    }
    m_results.clear();
    for (auto it = writes.begin(); it != writes.end(); ++it)
        m_results.append(RegisterCheck{it.key(), it.value(), {}, false, false});
    for (int reg : reads) {
        if (!writes.contains(reg))
            m_results.append(RegisterCheck{reg, {}, {}, false, false});
    }
    if (m_results.isEmpty()) {
        m_error = tr("no registers to write or read");
        return false;
    }
    // The first refusal stops the run; what was sent before it stands.
    QString refusal;
    for (auto it = writes.begin(); it != writes.end() && refusal.isEmpty(); ++it)
        refusal = m_session->writeConfig(it.key(), it.value()).refusal;
    for (int i = 0; i < m_results.size() && refusal.isEmpty(); ++i)
        refusal = m_session->readConfig(m_results[i].reg).refusal;
    if (!refusal.isEmpty()) {
        m_error = refusal;
        m_results.clear();
        return false;
    }
    m_running = true;
    m_timer.start();
    return true;
}

void RegisterReadback::onValue(int reg, const QString &value)
{
    if (!m_running)
        return;
    bool waiting = false;
    for (RegisterCheck &c : m_results) {
        if (c.reg == reg && !c.answered) {
            c.answered = true;
            c.readBack = value.trimmed();
            c.ok = c.written.isEmpty() || matches(c.written, c.readBack);
        }
        waiting = waiting || !c.answered;
    }
    if (!waiting)
        finish();
}

void RegisterReadback::finish()
{
    if (!m_running)
        return;
    m_running = false;
    m_timer.stop();
    emit finished(allOk());
}

} // namespace slew::tuning
