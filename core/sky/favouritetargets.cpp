// SPDX-License-Identifier: GPL-3.0-or-later
#include "favouritetargets.h"

#include <QHash>
#include <QSettings>

#include <algorithm>
#include <optional>

namespace slew::sky {

namespace {

const QString kSun = QStringLiteral("sun");
const QString kMoon = QStringLiteral("moon");

std::optional<FavouriteTarget> parse(const QString &text)
{
    if (text == kSun)
        return FavouriteTarget::sun();
    if (text == kMoon)
        return FavouriteTarget::moon();
    if (text.startsWith(QLatin1String("azel:")) || text.startsWith(QLatin1String("radec:")))
        return FavouriteTarget::direction(text);
    const qsizetype space = text.indexOf(u' ');
    bool ok = false;
    const int number = text.left(space).toInt(&ok);
    if (!ok || number <= 0)
        return std::nullopt; // written by something else: not ours to guess
    return FavouriteTarget{FavouriteTarget::Kind::Satellite, number, space < 0 ? QString() : text.mid(space + 1)};
}

QString format(const FavouriteTarget &t)
{
    switch (t.kind) {
    case FavouriteTarget::Kind::Sun: return kSun;
    case FavouriteTarget::Kind::Moon: return kMoon;
    case FavouriteTarget::Kind::Direction: return t.name;
    case FavouriteTarget::Kind::Satellite: break;
    }
    return QStringLiteral("%1 %2").arg(t.catalogueNumber).arg(t.name);
}

QHash<int, const ElementSet *> byNumber(const QList<ElementSet> &sets)
{
    QHash<int, const ElementSet *> index;
    for (const ElementSet &t : sets)
        index.insert(t.catalogueNumber, &t);
    return index;
}

} // namespace

void FavouriteTargets::load(const QSettings &settings)
{
    m_targets.clear();
    for (const QString &text : settings.value(QLatin1String(kSettingsKey)).toStringList()) {
        const auto target = parse(text.trimmed());
        if (target && !contains(*target))
            m_targets.append(*target);
    }
}

void FavouriteTargets::save(QSettings &settings) const
{
    QStringList texts;
    for (const FavouriteTarget &t : m_targets)
        texts << format(t);
    settings.setValue(QLatin1String(kSettingsKey), texts);
}

bool FavouriteTargets::contains(const FavouriteTarget &target) const
{
    return std::any_of(m_targets.begin(), m_targets.end(),
                       [&](const FavouriteTarget &t) { return t.sameTarget(target); });
}

bool FavouriteTargets::toggle(const FavouriteTarget &target)
{
    const auto was = std::find_if(m_targets.begin(), m_targets.end(),
                                  [&](const FavouriteTarget &t) { return t.sameTarget(target); });
    if (was != m_targets.end()) {
        m_targets.erase(was);
        return false;
    }
    m_targets.append(target);
    return true;
}

QList<FavouriteTarget> FavouriteTargets::missingFrom(const QList<ElementSet> &sets) const
{
    const QHash<int, const ElementSet *> index = byNumber(sets);
    QList<FavouriteTarget> missing;
    for (const FavouriteTarget &t : m_targets) {
        if (t.kind == FavouriteTarget::Kind::Satellite && !index.contains(t.catalogueNumber))
            missing.append(t);
    }
    return missing;
}

bool FavouriteTargets::renameFrom(const QList<ElementSet> &sets)
{
    const QHash<int, const ElementSet *> index = byNumber(sets);
    bool changed = false;
    for (FavouriteTarget &t : m_targets) {
        const ElementSet *found = t.kind == FavouriteTarget::Kind::Satellite ? index.value(t.catalogueNumber) : nullptr;
        if (found && found->displayName() != t.name) {
            t.name = found->displayName();
            changed = true;
        }
    }
    return changed;
}

} // namespace slew::sky
