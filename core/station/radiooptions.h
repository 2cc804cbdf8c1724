// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The station service's radio, as its options and config file give it
// (--radio, --downlink, --uplink, --transponders, ...), and how they become
// what the radio is tuned to for the tracked satellite: a transponder from
// the files (picked by name, or the satellite's default one), or the
// frequencies given, with the modes, offsets and the choice of paths on
// top.

#include "radio/doppler.h"
#include "radio/radiolink.h"
#include "radio/radioplan.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace slew::station {

struct RadioOptions {
    QString uri;                         // --radio
    std::optional<double> downlinkHz;    // --downlink
    std::optional<double> uplinkHz;      // --uplink
    QString downlinkMode, uplinkMode;    // --downlink-mode, --uplink-mode
    radio::DopplerOn correct = radio::DopplerOn::Both;        // --doppler
    std::optional<radio::UplinkFollowsDial> uplinkFollows;    // --uplink-follows
    double downlinkOffsetHz = 0, uplinkOffsetHz = 0;          // --downlink-offset, --uplink-offset
    QStringList transponderFiles;        // --transponders: SatNOGS DB JSON lists, Gpredict .trsp files
    QString transponderName;             // --transponder: the start of a description
    bool restoreAfterPass = false;       // --radio-restore
    radio::VfoLayout vfos = radio::VfoLayout::Split; // --radio-vfos
};

// "both", "downlink" or "uplink".
std::optional<radio::DopplerOn> parseDopplerOn(const QString &text, QString *error);
// "split" or "main-sub".
std::optional<radio::VfoLayout> parseVfoLayout(const QString &text, QString *error);
// "no", "same" or "opposite".
std::optional<radio::UplinkFollowsDial> parseUplinkFollows(const QString &text, QString *error);

// What to tune for satellite `noradId`. Reads the transponder files (SatNOGS
// DB's list by its .json name, Gpredict's by .trsp), when given; *notes
// gets what the reader skipped and what was left to the operator. Nothing,
// with *error, when no frequencies can be had: no file readable, no
// transponder of that name or none alive for the satellite, no downlink.
std::optional<radio::RadioPlan> resolveRadioPlan(const RadioOptions &options, int noradId, QStringList *notes,
                                                 QString *error);

} // namespace slew::station
