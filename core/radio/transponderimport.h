// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Transponders from the two places amateur stations keep them:
//
// - SatNOGS DB's transmitter list (its API's /api/transmitters/, saved as
//   a file): a JSON array of objects, one a transmitter, with uplink_low,
//   uplink_high, downlink_low and downlink_high (whole hertz, or null),
//   mode (a name, or null), invert and alive (true/false) and norad_cat_id
//   (null for an object with no catalogue number yet), besides uuid, type,
//   status, baud and others that are not read.
// - Gpredict's .trsp files: a key file (the GLib key-file format), one
//   [group] a transponder, named by the group, with UP_LOW, UP_HIGH,
//   DOWN_LOW, DOWN_HIGH (hertz), INVERT (true/false, 1/0) and MODE. One
//   file a satellite, named after its catalogue number (25544.trsp). A
//   missing HIGH means a single frequency; 0 means none, as Gpredict
//   writes an absent frequency.
//
// Reading never gives up on a whole file for one bad entry: the entry is
// skipped with a message naming the source, the entry and the field
// ("transmitters.json: entry 12 (ISS voice): downlink_low 'abc' is not a
// number"), and the good entries are kept. Every number goes through the
// input rule (core/input/finitenumber.h): not a number, NaN, infinity,
// negative, above kHighestFrequencyHz, and a low edge above its high edge
// are refused. Text from the file is escaped in every message. A source
// that is not the format, not UTF-8 text, over its cap, or yields nothing
// usable is refused whole, with the reason. Pure code, but for the two
// file readers, which read through the bounded file reader (no devices, no
// FIFOs, a cap) and so may run on any thread, and should run on a worker:
// a 16 MiB list of 24,000 transmitters takes about 0.3 s, the worst 16 MiB
// can be (eight million one-byte entries) about 3 s and 150 MB, on the
// development machine.

#include "transponder.h"

#include <QByteArray>
#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

namespace slew::radio {

// The largest files read: SatNOGS DB's whole transmitter list is a few
// MiB, so a cap of 16 MiB leaves it room to grow; a
// .trsp file holds a handful of groups (Gpredict's own are under 2 KiB).
inline constexpr qint64 kLargestTransmitterList = 16 * 1024 * 1024;
inline constexpr qint64 kLargestTrspFile = 1024 * 1024;
// Messages kept about skipped entries; the rest are counted. A file of a
// million bad entries must not become a million strings.
inline constexpr int kMostSkipMessages = 100;

struct TransponderImport {
    QList<Transponder> transponders; // in the order of the source
    QStringList skipped;             // one message an entry or line skipped, at most kMostSkipMessages
    int skippedCount = 0;            // every one skipped, past the messages kept too
    QString error;                   // the whole source refused, and why; transponders is then empty

    bool ok() const { return error.isEmpty(); }
    // The messages, and "… and 12 more skipped" when some were not kept.
    QStringList skipReport() const;
};

// A SatNOGS DB transmitter list. `sourceName` starts every message (a file
// name, a URL).
TransponderImport readSatnogsTransmitters(const QByteArray &json, const QString &sourceName);
TransponderImport readSatnogsTransmittersFile(const QString &path);

// A Gpredict .trsp file's text, for the satellite `noradId`.
TransponderImport readGpredictTrsp(const QByteArray &text, const QString &sourceName, int noradId);
// A .trsp file; the satellite is `noradId` when given, else the number the
// file is named after (25544.trsp), else the file is refused saying so.
TransponderImport readGpredictTrspFile(const QString &path, std::optional<int> noradId = std::nullopt);
// The catalogue number in a .trsp file's name ("/x/25544.trsp" -> 25544).
std::optional<int> noradIdFromTrspFileName(const QString &path);

// The catalogue numbers read: 1 to 999999999 (NORAD's five digits, Alpha-5
// up to 339999, and the nine digits the catalogue is moving to).
inline constexpr int kLargestNoradId = 999999999;

} // namespace slew::radio
