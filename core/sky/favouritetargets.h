// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The targets an operator marked as favourites in the Tracking tab: the sun,
// the moon, and satellites. A satellite is kept by its catalogue number,
// with the name it had when marked: the number outlives an element-set
// reload (names change, a source may be dropped), and the name lets a
// favourite that no loaded set holds be shown as missing instead of
// silently vanishing.
//
// In the settings: one string a favourite, "sun", "moon" or "NUMBER NAME".

#include "elementset.h"

#include <QList>
#include <QString>

class QSettings;

namespace slew::sky {

struct FavouriteTarget {
    // Direction: a fixed azimuth and elevation or a J2000 source, kept as
    // the text that names it ("azel:180,45", "radec:23:23:24,+58:48:54").
    enum class Kind { Satellite, Sun, Moon, Direction };
    Kind kind = Kind::Satellite;
    int catalogueNumber = 0; // a satellite's
    QString name;            // a satellite's, as it was last seen

    static FavouriteTarget sun() { return {Kind::Sun, 0, {}}; }
    static FavouriteTarget moon() { return {Kind::Moon, 0, {}}; }
    static FavouriteTarget satellite(const ElementSet &elements)
    {
        return {Kind::Satellite, elements.catalogueNumber, elements.displayName()};
    }
    static FavouriteTarget direction(const QString &spec) { return {Kind::Direction, 0, spec.trimmed()}; }
    // The same target: a satellite's name does not count; a direction is its text.
    bool sameTarget(const FavouriteTarget &other) const
    {
        return kind == other.kind && (kind != Kind::Satellite || catalogueNumber == other.catalogueNumber)
            && (kind != Kind::Direction || name.compare(other.name, Qt::CaseInsensitive) == 0);
    }
};

class FavouriteTargets {
public:
    static constexpr const char *kSettingsKey = "tracking/favourites";

    void load(const QSettings &settings);
    void save(QSettings &settings) const;

    QList<FavouriteTarget> list() const { return m_targets; }
    bool contains(const FavouriteTarget &target) const;
    // Marks or unmarks it; true when it is a favourite afterwards.
    bool toggle(const FavouriteTarget &target);
    // Satellites that no set in `sets` holds, in the order they were marked.
    QList<FavouriteTarget> missingFrom(const QList<ElementSet> &sets) const;
    // Takes the names the sets give now (a launch's "OBJECT A" gets its
    // real name later); true when one changed.
    bool renameFrom(const QList<ElementSet> &sets);

private:
    QList<FavouriteTarget> m_targets;
};

} // namespace slew::sky
