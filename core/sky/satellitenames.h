// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The names operators call satellites by, beside the names their element
// sets carry: "AO-91" for "FOX-1B (AO-91)", "ZARYA" for "ISS (ZARYA)",
// "OSCAR7" typed without its space, and the AMSAT OSCAR numbers and former
// names of amateur satellites whose sets do not say them: a table kept as
// data (satellite-names.txt, with its source), which an operator's own
// file extends. findSatellites (elementset.h) searches by these.

#include <QHash>
#include <QString>
#include <QStringList>
#include <QStringView>

#include <optional>

namespace slew::sky {

// A name as searched: letters and digits only, upper case ("AO-91",
// "ao 91" and "AO91" are all "AO91").
QString satelliteNameKey(QStringView name);

// The keys a set's name may be named by whole: the name, the part before
// its parentheses, and each designation inside them ("FOX-1B (AO-91)":
// FOX1BAO91, FOX1B, AO91).
QStringList satelliteNameKeys(const QString &name);

// Names for catalogue numbers, read from text of lines "NUMBER NAME" ('#'
// begins a comment). A later text's name for another satellite replaces
// the earlier one: the operator's file has the last word.
class SatelliteNameTable
{
public:
    // A line that is not a number and a name is skipped, and said in
    // *problems as "ORIGIN:LINE: why"; the other lines are kept.
    void read(QStringView text, const QString &origin, QStringList *problems);
    // The catalogue number a name's key stands for ("AO7", "JAS2").
    std::optional<int> catalogueNumber(const QString &key) const;
    qsizetype size() const { return m_numbers.size(); }

private:
    QHash<QString, int> m_numbers; // by satelliteNameKey
};

// The table every search uses: the built-in names, then the operator's
// file if there is one (userSatelliteNamesPath()); read once, at first use.
const SatelliteNameTable &satelliteNames();
// What was wrong in the operator's file, each "PATH:LINE: why" (or the file
// as a whole: unreadable, too large); empty when it was read whole or is
// absent. Faces show these at start.
const QStringList &satelliteNameProblems();
// ~/.config/Slew/satellite-names.txt (following XDG_CONFIG_HOME).
QString userSatelliteNamesPath();

// The text of satellite-names.txt, compiled in (satellitenames_builtin.cpp,
// made from it by CMake).
QStringView builtInSatelliteNames();

} // namespace slew::sky
