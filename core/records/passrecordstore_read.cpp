// SPDX-License-Identifier: GPL-3.0-or-later
// PassRecordStore's reading: what a file says, believed only as far as
// its values are numbers in range and times in the form written.
#include "passrecordstore.h"

#include "passrecordschema.h"

#include "input/finitenumber.h"

#include <QSqlDatabase>
#include <QSqlQuery>

#include <algorithm>

namespace slew::records {
namespace {

// Enough for a fixed direction held for days at a few samples a second.
constexpr int kMaxSamplesRead = 2'000'000;

// A number read back, believed only when finite and in range.
std::optional<double> readNumber(const QVariant &value, const input::NumberRange &range)
{
    if (value.isNull())
        return std::nullopt;
    bool ok = false;
    const double x = value.toDouble(&ok);
    return ok && range.contains(x) ? std::optional<double>(x) : std::nullopt;
}

std::optional<int> readWhole(const QVariant &value, int min, int max)
{
    if (value.isNull())
        return std::nullopt;
    bool ok = false;
    const qint64 x = value.toLongLong(&ok);
    return ok && x >= min && x <= max ? std::optional<int>(int(x)) : std::nullopt;
}

const input::NumberRange kElevation{-90, 90, "°"};
const input::NumberRange kAngle{0, 180, "°"};
const input::NumberRange kHertz{0, 1e9, " Hz"};

PassRecord readPass(const QSqlQuery &q)
{
    PassRecord r;
    r.id = q.value(0).toLongLong();
    r.planned.target = boundedText(q.value(1).toString(), PassRecordStore::kMaxTargetChars);
    r.planned.norad = readWhole(q.value(2), 1, 999'999'999);
    r.planned.aos = timeFromStored(q.value(3).toString());
    r.planned.tca = timeFromStored(q.value(4).toString());
    r.planned.los = timeFromStored(q.value(5).toString());
    r.planned.maxElevationDeg = readNumber(q.value(6), kElevation);
    r.planned.plannedWorstDeg = readNumber(q.value(7), kAngle);
    r.figures.rmsDeg = readNumber(q.value(8), kAngle);
    r.figures.worstDeg = readNumber(q.value(9), kAngle);
    r.figures.commands = readWhole(q.value(10), 0, 100'000'000);
    const QString outcome = q.value(11).toString();
    r.reason = boundedText(q.value(12).toString(), PassRecordStore::kMaxReasonChars);
    if (const auto o = outcomeFromName(outcome)) {
        r.outcome = *o;
    } else {
        r.outcome = Outcome::Interrupted;
        r.reason = QStringLiteral("the record says '%1', which is not an outcome Slew writes")
                       .arg(boundedText(outcome, 40));
    }
    r.recorded = timeFromStored(q.value(13).toString());
    r.ended = timeFromStored(q.value(14).toString());
    r.planned.rehearsal = q.value(15).toInt() != 0;
    r.figures.dopplerRmsHz = readNumber(q.value(16), kHertz);
    r.figures.dopplerWorstHz = readNumber(q.value(17), kHertz);
    r.samples = int(std::clamp<qint64>(q.value(18).toLongLong(), 0, kMaxSamplesRead));
    return r;
}

} // namespace

QList<PassRecord> PassRecordStore::passes(const QString &targetContains, int limit) const
{
    QList<PassRecord> out;
    if (!m_db)
        return out;
    QString sql = QStringLiteral("SELECT %1, (SELECT count(*) FROM pass_samples WHERE pass_id = passes.id) FROM passes")
                      .arg(schema::passColumns(m_version));
    QString pattern = targetContains.trimmed();
    if (!pattern.isEmpty()) {
        // LIKE is blind to ASCII case; its wildcards in the filter are taken as they are.
        pattern.replace(u'\\', QLatin1String("\\\\")).replace(u'%', QLatin1String("\\%")).replace(u'_', QLatin1String("\\_"));
        sql += QStringLiteral(" WHERE target LIKE ? ESCAPE '\\'");
    }
    sql += QStringLiteral(" ORDER BY id DESC LIMIT ?");
    QSqlQuery q(*m_db);
    q.setForwardOnly(true);
    q.prepare(sql);
    if (!pattern.isEmpty())
        q.addBindValue(QLatin1Char('%') + pattern + QLatin1Char('%'));
    q.addBindValue(std::max(limit, 0));
    if (!q.exec())
        return out;
    while (q.next())
        out.append(readPass(q));
    return out;
}

std::optional<PassRecord> PassRecordStore::pass(qint64 id) const
{
    if (!m_db)
        return std::nullopt;
    QSqlQuery q(*m_db);
    q.setForwardOnly(true);
    q.prepare(QStringLiteral("SELECT %1, (SELECT count(*) FROM pass_samples WHERE pass_id = passes.id) FROM passes "
                             "WHERE id = ?")
                  .arg(schema::passColumns(m_version)));
    q.addBindValue(id);
    if (!q.exec() || !q.next())
        return std::nullopt;
    return readPass(q);
}

QList<PassSample> PassRecordStore::samples(qint64 id, int *skipped) const
{
    QList<PassSample> out;
    int bad = 0;
    if (m_db) {
        QSqlQuery q(*m_db);
        q.setForwardOnly(true);
        q.prepare(QStringLiteral("SELECT unix_ms, antenna_az_deg, antenna_el_deg, target_az_deg, target_el_deg, "
                                 "error_deg FROM pass_samples WHERE pass_id = ? ORDER BY unix_ms LIMIT ?"));
        q.addBindValue(id);
        q.addBindValue(kMaxSamplesRead);
        if (q.exec()) {
            while (q.next()) {
                bool ok[6] = {};
                PassSample s{q.value(0).toLongLong(&ok[0]), q.value(1).toDouble(&ok[1]), q.value(2).toDouble(&ok[2]),
                             q.value(3).toDouble(&ok[3]), q.value(4).toDouble(&ok[4]), q.value(5).toDouble(&ok[5])};
                if (std::all_of(std::begin(ok), std::end(ok), [](bool b) { return b; }) && plausibleSample(s))
                    out.append(s);
                else
                    ++bad;
            }
        }
    }
    if (skipped)
        *skipped = bad;
    return out;
}

} // namespace slew::records
