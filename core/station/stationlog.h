// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The station service's face: one time-stamped line on a file (stdout) for
// everything a Station's parts report — the links, the controller's errors
// and versions, refusals, the alarm monitor's judgements in the banner's
// words, the rotctld servers, the tracker. Device and client text is
// escaped and bounded before it is written (input/logtext.h).

#include <QObject>
#include <QString>

#include <cstdio>

namespace slew::station {

class Station;

class StationLog : public QObject {
    Q_OBJECT
public:
    // `station` must outlive this.
    StationLog(Station *station, std::FILE *file, QObject *parent = nullptr);

    // One line, stamped with the UTC time, escaped, flushed.
    void write(const QString &line);

private:
    void followRotor(int index);

    Station *m_station;
    std::FILE *m_file;
};

} // namespace slew::station
