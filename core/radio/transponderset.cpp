// SPDX-License-Identifier: GPL-3.0-or-later
#include "transponderset.h"

#include <algorithm>

namespace slew::radio {
namespace {

QString frequencyKey(const std::optional<double> &hz)
{
    // 17 significant digits give back the same double, so equal keys are
    // equal frequencies.
    return hz ? QString::number(*hz, 'g', 17) : QStringLiteral("-");
}

// The frequencies, sense and mode as one key: equal keys, the same
// transponder (the second half of sameTransponder).
QString tuningKey(const Transponder &t)
{
    return QStringList{frequencyKey(t.uplinkLowHz), frequencyKey(t.uplinkHighHz), frequencyKey(t.downlinkLowHz),
                       frequencyKey(t.downlinkHighHz), t.inverting ? QStringLiteral("i") : QStringLiteral("n"),
                       t.mode.toCaseFolded()}
        .join(u'|');
}

} // namespace

bool sameTransponder(const Transponder &a, const Transponder &b)
{
    if (a.noradId != b.noradId)
        return false;
    if (!a.uuid.isEmpty() && a.uuid == b.uuid)
        return true;
    return tuningKey(a) == tuningKey(b);
}

int TransponderSet::merge(const QList<Transponder> &transponders)
{
    int dropped = 0;
    for (const Transponder &t : transponders) {
        Held &held = m_bySatellite[t.noradId];
        const QString tuning = tuningKey(t);
        if ((!t.uuid.isEmpty() && held.uuids.contains(t.uuid)) || held.tunings.contains(tuning)) {
            ++dropped;
            continue;
        }
        held.list.append(t);
        if (!t.uuid.isEmpty())
            held.uuids.insert(t.uuid);
        held.tunings.insert(tuning);
        ++m_size;
    }
    return dropped;
}

std::optional<Transponder> TransponderSet::defaultFor(int noradId) const
{
    const auto it = m_bySatellite.constFind(noradId);
    if (it == m_bySatellite.cend())
        return std::nullopt;
    const QList<Transponder> &list = it->list;
    const auto linear = std::find_if(list.cbegin(), list.cend(), [](const Transponder &t) { return t.alive && t.isLinear(); });
    if (linear != list.cend())
        return *linear;
    const auto alive = std::find_if(list.cbegin(), list.cend(), [](const Transponder &t) { return t.alive; });
    if (alive != list.cend())
        return *alive;
    return std::nullopt;
}

QList<int> TransponderSet::satellites() const
{
    QList<int> numbers;
    for (auto it = m_bySatellite.cbegin(); it != m_bySatellite.cend(); ++it)
        if (!it->list.isEmpty())
            numbers.append(it.key());
    std::sort(numbers.begin(), numbers.end());
    return numbers;
}

} // namespace slew::radio
