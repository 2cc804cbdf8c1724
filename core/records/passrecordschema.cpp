// SPDX-License-Identifier: GPL-3.0-or-later
#include "passrecordschema.h"

namespace slew::records::schema {
namespace {

// Times of a pass are ISO 8601 UTC text with milliseconds: they sort as
// text and read as they are in any sqlite3 shell. A sample's time is
// milliseconds since 1970 (an integer of 8 bytes or fewer, against 24 of
// text): samples are most of the file, and are only ever read by number.
const char *const kPassesV1 =
    "CREATE TABLE passes ("
    " id INTEGER PRIMARY KEY,"
    " target TEXT NOT NULL,"
    " norad INTEGER,"                      // NULL for the sun, the moon, a fixed direction
    " aos_utc TEXT NOT NULL,"
    " tca_utc TEXT,"
    " los_utc TEXT NOT NULL,"
    " max_el_deg REAL,"
    " planned_worst_deg REAL,"
    " rms_deg REAL,"
    " worst_deg REAL,"
    " commands INTEGER,"
    " outcome TEXT NOT NULL,"              // in progress, tracked, interrupted, dropped
    " reason TEXT,"
    " recorded_utc TEXT NOT NULL,"         // the wall clock when begun: what pruning goes by
    " ended_utc TEXT,"
    " rehearsal INTEGER NOT NULL DEFAULT 0"
    ")";
const char *const kSamplesV1 =
    "CREATE TABLE pass_samples ("
    " pass_id INTEGER NOT NULL REFERENCES passes(id) ON DELETE CASCADE,"
    " unix_ms INTEGER NOT NULL,"
    " antenna_az_deg REAL NOT NULL,"
    " antenna_el_deg REAL NOT NULL,"
    " target_az_deg REAL NOT NULL,"
    " target_el_deg REAL NOT NULL,"
    " error_deg REAL NOT NULL"
    ")";

QString versionStatement(int version)
{
    return QStringLiteral("PRAGMA user_version = %1").arg(version);
}

} // namespace

QStringList create(int version)
{
    QStringList statements{
        QString::fromLatin1(kPassesV1),
        QStringLiteral("CREATE INDEX passes_by_target ON passes(target)"),
        QStringLiteral("CREATE INDEX passes_by_outcome ON passes(outcome)"),
        QString::fromLatin1(kSamplesV1),
        QStringLiteral("CREATE INDEX pass_samples_by_pass ON pass_samples(pass_id, unix_ms)"),
        QStringLiteral("PRAGMA application_id = %1").arg(kApplicationId),
        versionStatement(1),
    };
    for (int v = 1; v < version && v < kCurrentVersion; ++v)
        statements += upgrade(v);
    return statements;
}

QStringList upgrade(int from)
{
    switch (from) {
    case 1:
        return {QStringLiteral("ALTER TABLE passes ADD COLUMN doppler_rms_hz REAL"),
                QStringLiteral("ALTER TABLE passes ADD COLUMN doppler_worst_hz REAL"), versionStatement(2)};
    default: return {};
    }
}

QString passColumns(int version)
{
    QString columns = QStringLiteral(
        "id, target, norad, aos_utc, tca_utc, los_utc, max_el_deg, planned_worst_deg, rms_deg, worst_deg, commands, "
        "outcome, reason, recorded_utc, ended_utc, rehearsal, ");
    columns += version >= 2 ? QStringLiteral("doppler_rms_hz, doppler_worst_hz")
                            : QStringLiteral("NULL AS doppler_rms_hz, NULL AS doppler_worst_hz");
    return columns;
}

} // namespace slew::records::schema
