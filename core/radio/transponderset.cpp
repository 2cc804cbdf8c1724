// SPDX-License-Identifier: GPL-3.0-or-later
#include "transponderset.h"

#include <algorithm>

namespace slew::radio {

bool sameTransponder(const Transponder &a, const Transponder &b)
{
    if (a.noradId != b.noradId)
        return false;
    if (!a.uuid.isEmpty() && a.uuid == b.uuid)
        return true;
    return a.uplinkLowHz == b.uplinkLowHz && a.uplinkHighHz == b.uplinkHighHz && a.downlinkLowHz == b.downlinkLowHz
           && a.downlinkHighHz == b.downlinkHighHz && a.inverting == b.inverting
           && a.mode.compare(b.mode, Qt::CaseInsensitive) == 0;
}

int TransponderSet::merge(const QList<Transponder> &transponders)
{
    int dropped = 0;
    for (const Transponder &t : transponders) {
        QList<Transponder> &held = m_bySatellite[t.noradId];
        const bool repeat = std::any_of(held.cbegin(), held.cend(), [&](const Transponder &h) { return sameTransponder(h, t); });
        if (repeat) {
            ++dropped;
            continue;
        }
        held.append(t);
        ++m_size;
    }
    return dropped;
}

std::optional<Transponder> TransponderSet::defaultFor(int noradId) const
{
    const auto it = m_bySatellite.constFind(noradId);
    if (it == m_bySatellite.cend())
        return std::nullopt;
    const QList<Transponder> &list = *it;
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
        if (!it->isEmpty())
            numbers.append(it.key());
    std::sort(numbers.begin(), numbers.end());
    return numbers;
}

} // namespace slew::radio
