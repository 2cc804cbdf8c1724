// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The transponders Slew knows, by satellite (NORAD catalogue number),
// gathered from several sources (a SatNOGS DB list, Gpredict .trsp files):
// what the Radio panel lists for the tracked satellite and where the
// Doppler steering takes its frequencies from. Pure code, a value.

#include "transponder.h"

#include <QHash>
#include <QList>
#include <QSet>
#include <QString>

#include <optional>

namespace slew::radio {

// The same transponder twice: the same SatNOGS DB entry (uuid), or the same
// four frequencies, sense and mode (letter case aside), as when a Gpredict
// file made from SatNOGS DB is read beside the list itself.
bool sameTransponder(const Transponder &a, const Transponder &b);

class TransponderSet {
public:
    // Adds one source's transponders, each to its satellite's list, after
    // those already held. One that repeats a transponder already held
    // (sameTransponder) is dropped and the one held stays: merge the
    // sources a user trusts most first. Returns how many were dropped.
    int merge(const QList<Transponder> &transponders);

    // A satellite's transponders, in the order they were merged; none for a
    // satellite with none.
    QList<Transponder> forSatellite(int noradId) const { return m_bySatellite.value(noradId).list; }

    // The transponder to tune a satellite to when the user has not picked
    // one: the first alive linear transponder (the passband is what an
    // operator of a linear satellite works, and its beacon comes later in
    // most lists), else the first alive one of any kind (an FM repeater, a
    // beacon). Nothing when the satellite has no alive transponder: a dead
    // one is only tuned when picked.
    std::optional<Transponder> defaultFor(int noradId) const;

    // The satellites with at least one transponder, in increasing order.
    QList<int> satellites() const;
    int size() const { return m_size; }
    bool isEmpty() const { return m_size == 0; }

private:
    // What makes a transponder the same as another (sameTransponder), kept
    // in sets so that a merge of n transponders takes time in n, not n²: a
    // list of a hundred thousand entries for one satellite must not stall.
    struct Held {
        QList<Transponder> list;
        QSet<QString> uuids;
        QSet<QString> tunings;
    };
    QHash<int, Held> m_bySatellite;
    int m_size = 0;
};

} // namespace slew::radio
