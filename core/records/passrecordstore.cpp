// SPDX-License-Identifier: GPL-3.0-or-later
#include "passrecordstore.h"

#include "passrecordfile.h"
#include "passrecordschema.h"

#include "input/finitenumber.h"

#include <QDir>
#include <QFileInfo>
#include <QLockFile>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QStandardPaths>

#include <atomic>
#include <cmath>

namespace slew::records {
namespace {

constexpr int kDayMs = 24 * 3600 * 1000;

QString connectionName()
{
    static std::atomic<int> next{0};
    return QStringLiteral("slew-pass-records-%1").arg(next++);
}

// A number as stored: NULL for none or for anything not finite.
QVariant stored(const std::optional<double> &value)
{
    return value && std::isfinite(*value) ? QVariant(*value) : QVariant();
}

QVariant stored(const std::optional<int> &value)
{
    return value ? QVariant(*value) : QVariant();
}

// A highest elevation outside this is not stored (NULL).
const input::NumberRange kElevation{-90, 90, "°"};

} // namespace

QString PassRecordStore::defaultPath()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/passes.sqlite");
}

QString PassRecordStore::interruptedAtStartReason()
{
    return tr("Slew stopped during the pass (found at the next start)");
}

PassRecordStore::PassRecordStore(QObject *parent) : QObject(parent)
{
    m_commitTimer.setSingleShot(true);
    connect(&m_commitTimer, &QTimer::timeout, this, [this] { commit(); });
    m_pruneTimer.setInterval(kDayMs);
    connect(&m_pruneTimer, &QTimer::timeout, this, [this] { prune(QDateTime::currentDateTimeUtc()); });
}

PassRecordStore::~PassRecordStore()
{
    close();
}

void PassRecordStore::close()
{
    if (m_db) {
        if (m_access == Access::Record)
            commit();
        m_db->close();
        m_db.reset();
        QSqlDatabase::removeDatabase(m_connection);
    }
    m_commitTimer.stop();
    m_pruneTimer.stop();
    m_samples.clear();
    m_figures.clear();
    if (m_lock)
        m_lock->unlock();
    m_lock.reset();
}

void PassRecordStore::setKeepDays(int days)
{
    m_keepDays = std::clamp(days, 1, kMaxKeepDays);
}

bool PassRecordStore::exec(const QString &statement, QString *error) const
{
    QSqlQuery q(*m_db);
    if (q.exec(statement))
        return true;
    if (error)
        *error = tr("%1: %2").arg(m_path, q.lastError().text());
    return false;
}

std::optional<int> PassRecordStore::pragmaNumber(const char *name, QString *error) const
{
    QSqlQuery q(*m_db);
    if (!q.exec(QStringLiteral("PRAGMA %1").arg(QLatin1String(name))) || !q.next()) {
        *error = tr("%1 cannot be read as a database: %2").arg(m_path, q.lastError().text());
        return std::nullopt;
    }
    return q.value(0).toInt();
}

bool PassRecordStore::open(const QString &path, Access access, QString *error)
{
    close();
    m_notes = {};
    m_takenByAnother = false;
    m_path = path;
    m_access = access;
    QString why;
    if (path.isEmpty()) {
        *error = tr("no pass-record file named");
        return false;
    }
    if (!QSqlDatabase::isDriverAvailable(QStringLiteral("QSQLITE"))) {
        *error = tr("pass records need Qt's SQLite driver (the Debian package libqt6sql6-sqlite), "
                    "which is not installed; %1 was not opened")
                     .arg(path);
        return false;
    }
    const PassRecordFileKind kind = inspectPassRecordFile(path, &why);
    if (kind == PassRecordFileKind::Unusable) {
        *error = why;
        return false;
    }
    if (access == Access::Read && kind != PassRecordFileKind::Database) {
        *error = tr("%1 holds no pass records: none has been recorded there").arg(path);
        return false;
    }
    if (access == Access::Record) {
        const QString folder = QFileInfo(path).absolutePath();
        if (!QDir().mkpath(folder)) {
            *error = tr("%1: its folder %2 cannot be made").arg(path, folder);
            return false;
        }
        m_lock = std::make_unique<QLockFile>(path + QStringLiteral(".lock"));
        m_lock->setStaleLockTime(0); // a lock is stale only when its process is gone
        if (!m_lock->tryLock(0)) {
            qint64 pid = 0;
            QString host, app;
            m_lock->getLockInfo(&pid, &host, &app);
            m_takenByAnother = m_lock->error() == QLockFile::LockFailedError;
            *error = m_lock->error() == QLockFile::LockFailedError
                         ? tr("%1 is recording into %2 (process %3 on %4): one Slew records into a file at a time")
                               .arg(app.isEmpty() ? tr("another Slew") : app, path)
                               .arg(pid)
                               .arg(host)
                         : tr("%1: its lock file %1.lock cannot be made").arg(path);
            m_lock.reset();
            return false;
        }
    }
    if (!openDatabase(path, access, error) || !prepareSchema(error)) {
        close();
        return false;
    }
    m_notes.created = kind != PassRecordFileKind::Database;
    if (access == Access::Record) {
        m_notes.interrupted = markInterrupted(interruptedAtStartReason());
        m_notes.prunedPasses = prune(QDateTime::currentDateTimeUtc());
        m_pruneTimer.start();
    }
    return true;
}

bool PassRecordStore::openDatabase(const QString &path, Access access, QString *error)
{
    m_connection = connectionName();
    m_db = std::make_unique<QSqlDatabase>(QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), m_connection));
    m_db->setDatabaseName(path);
    QString options = QStringLiteral("QSQLITE_BUSY_TIMEOUT=%1").arg(kBusyTimeoutMs);
    if (access == Access::Read)
        options += QStringLiteral(";QSQLITE_OPEN_READONLY");
    m_db->setConnectOptions(options);
    if (!m_db->open()) {
        *error = tr("%1 cannot be opened: %2").arg(path, m_db->lastError().text());
        return false;
    }
    return true;
}

bool PassRecordStore::prepareSchema(QString *error)
{
    const auto applicationId = pragmaNumber("application_id", error);
    const auto version = applicationId ? pragmaNumber("user_version", error) : std::nullopt;
    if (!version)
        return false;
    QSqlQuery tables(*m_db);
    if (!tables.exec(QStringLiteral("SELECT count(*) FROM sqlite_master")) || !tables.next()) {
        *error = tr("%1 cannot be read as a database: %2").arg(m_path, tables.lastError().text());
        return false;
    }
    const bool empty = tables.value(0).toInt() == 0;
    tables.finish();
    const bool ours = *applicationId == schema::kApplicationId;
    if (!ours && !(empty && *applicationId == 0)) {
        *error = tr("%1 is another program's SQLite database, not Slew's pass records; it was left as it is")
                     .arg(m_path);
        return false;
    }
    if (ours && (*version < 1 || *version > schema::kCurrentVersion)) {
        *error = *version > schema::kCurrentVersion
                     ? tr("%1 holds pass records of schema version %2, newer than this Slew's %3: a newer Slew "
                          "wrote it; it was left as it is")
                           .arg(m_path)
                           .arg(*version)
                           .arg(schema::kCurrentVersion)
                     : tr("%1 is marked as Slew's pass records but has no schema version; it was left as it is")
                           .arg(m_path);
        return false;
    }
    if (m_access == Access::Read) {
        if (!ours) {
            *error = tr("%1 holds no pass records: none has been recorded there").arg(m_path);
            return false;
        }
        m_version = *version;
        return true;
    }
    // WAL: a commit appends to the log and waits for no disk; NORMAL syncs
    // only at checkpoints, so a crash of Slew (not of the machine) loses
    // nothing committed, and a power cut at most the last commits.
    QSqlQuery wal(*m_db);
    if (!wal.exec(QStringLiteral("PRAGMA journal_mode=WAL")) || !wal.next()
        || wal.value(0).toString().compare(QLatin1String("wal"), Qt::CaseInsensitive) != 0) {
        *error = tr("%1: the database cannot be put in WAL mode: %2").arg(m_path, wal.lastError().text());
        return false;
    }
    wal.finish();
    if (!exec(QStringLiteral("PRAGMA synchronous=NORMAL"), error) || !exec(QStringLiteral("PRAGMA foreign_keys=ON"), error))
        return false;
    QStringList steps;
    if (!ours)
        steps = schema::create(schema::kCurrentVersion);
    else
        for (int v = *version; v < schema::kCurrentVersion; ++v)
            steps += schema::upgrade(v);
    if (steps.isEmpty()) {
        m_version = *version;
        return true;
    }
    // All or nothing: a migration cut short leaves the file as it was.
    if (!m_db->transaction()) {
        *error = tr("%1: %2").arg(m_path, m_db->lastError().text());
        return false;
    }
    for (const QString &step : std::as_const(steps)) {
        if (!exec(step, error)) {
            m_db->rollback();
            return false;
        }
    }
    if (!m_db->commit()) {
        *error = tr("%1: %2").arg(m_path, m_db->lastError().text());
        m_db->rollback();
        return false;
    }
    if (ours)
        m_notes.migratedFrom = *version;
    m_version = schema::kCurrentVersion;
    return true;
}

std::optional<qint64> PassRecordStore::insertPass(const PassPlanned &planned, Outcome outcome, const QString &reason,
                                                  QString *error)
{
    QString why;
    if (!canRecord())
        why = tr("no pass-record file is open to record");
    else if (planned.target.trimmed().isEmpty() || !planned.aos.isValid() || !planned.los.isValid())
        why = tr("%1: a pass is recorded with its target, AOS and LOS").arg(m_path);
    if (!why.isEmpty()) {
        if (error)
            *error = why;
        return std::nullopt;
    }
    QSqlQuery q(*m_db);
    q.prepare(QStringLiteral(
        "INSERT INTO passes (target, norad, aos_utc, tca_utc, los_utc, max_el_deg, planned_worst_deg, outcome, "
        "reason, recorded_utc, rehearsal) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"));
    q.addBindValue(boundedText(planned.target, kMaxTargetChars));
    q.addBindValue(planned.norad && *planned.norad > 0 ? QVariant(*planned.norad) : QVariant());
    q.addBindValue(storedTime(planned.aos));
    q.addBindValue(planned.tca.isValid() ? QVariant(storedTime(planned.tca)) : QVariant());
    q.addBindValue(storedTime(planned.los));
    const auto elevation = planned.maxElevationDeg && kElevation.contains(*planned.maxElevationDeg)
                               ? planned.maxElevationDeg
                               : std::nullopt;
    q.addBindValue(stored(elevation));
    q.addBindValue(stored(planned.plannedWorstDeg));
    q.addBindValue(outcomeName(outcome));
    q.addBindValue(reason.isEmpty() ? QVariant() : QVariant(boundedText(reason, kMaxReasonChars)));
    q.addBindValue(storedTime(QDateTime::currentDateTimeUtc()));
    q.addBindValue(planned.rehearsal ? 1 : 0);
    if (!q.exec()) {
        const QString text = tr("%1: the pass could not be recorded: %2").arg(m_path, q.lastError().text());
        if (error)
            *error = text;
        failed(text);
        return std::nullopt;
    }
    const qint64 id = q.lastInsertId().toLongLong();
    emit passChanged(id);
    return id;
}

std::optional<qint64> PassRecordStore::beginPass(const PassPlanned &planned, QString *error)
{
    return insertPass(planned, Outcome::InProgress, {}, error);
}

std::optional<qint64> PassRecordStore::recordDropped(const PassPlanned &planned, const QString &reason, QString *error)
{
    return insertPass(planned, Outcome::Dropped, reason, error);
}

void PassRecordStore::addSample(qint64 id, const PassSample &sample)
{
    if (!canRecord() || !plausibleSample(sample))
        return;
    if (int(m_samples.size()) >= kMaxBuffered) {
        ++m_droppedSamples;
        return;
    }
    m_samples.push_back({id, sample});
    scheduleCommit();
}

void PassRecordStore::setFigures(qint64 id, const PassFigures &figures)
{
    if (!canRecord())
        return;
    m_figures[id] = figures;
    scheduleCommit();
}

void PassRecordStore::scheduleCommit()
{
    if (!m_commitTimer.isActive())
        m_commitTimer.start(kCommitIntervalMs);
}

void PassRecordStore::failed(const QString &error)
{
    if (m_failing)
        return;
    m_failing = true;
    emit writeFailed(error);
}

bool PassRecordStore::commit(QString *error)
{
    m_commitTimer.stop();
    if (!canRecord() || (m_samples.empty() && m_figures.empty()))
        return canRecord();
    auto give = [&](const QString &text) {
        if (error)
            *error = text;
        failed(text);
        return false;
    };
    // Gathered is let go of whatever happens: a file that cannot take it
    // now must not make Slew grow.
    const std::vector<Gathered> samples = std::exchange(m_samples, {});
    const std::map<qint64, PassFigures> figures = std::exchange(m_figures, {});
    if (!m_db->transaction())
        return give(tr("%1: %2").arg(m_path, m_db->lastError().text()));
    QSqlQuery insert(*m_db);
    insert.prepare(QStringLiteral("INSERT INTO pass_samples (pass_id, unix_ms, antenna_az_deg, antenna_el_deg, "
                                  "target_az_deg, target_el_deg, error_deg) VALUES (?, ?, ?, ?, ?, ?, ?)"));
    for (const Gathered &g : samples) {
        insert.addBindValue(g.id);
        insert.addBindValue(g.sample.unixMs);
        insert.addBindValue(g.sample.antennaAzDeg);
        insert.addBindValue(g.sample.antennaElDeg);
        insert.addBindValue(g.sample.targetAzDeg);
        insert.addBindValue(g.sample.targetElDeg);
        insert.addBindValue(g.sample.errorDeg);
        if (!insert.exec()) {
            const QString why = insert.lastError().text();
            m_db->rollback();
            return give(tr("%1: samples could not be recorded: %2").arg(m_path, why));
        }
    }
    QSqlQuery update(*m_db);
    update.prepare(QStringLiteral("UPDATE passes SET rms_deg = ?, worst_deg = ?, commands = ?, doppler_rms_hz = ?, "
                                  "doppler_worst_hz = ? WHERE id = ?"));
    for (const auto &[id, f] : figures) {
        update.addBindValue(stored(f.rmsDeg));
        update.addBindValue(stored(f.worstDeg));
        update.addBindValue(f.commands && *f.commands >= 0 ? stored(f.commands) : QVariant());
        update.addBindValue(stored(f.dopplerRmsHz));
        update.addBindValue(stored(f.dopplerWorstHz));
        update.addBindValue(id);
        if (!update.exec()) {
            const QString why = update.lastError().text();
            m_db->rollback();
            return give(tr("%1: figures could not be recorded: %2").arg(m_path, why));
        }
    }
    if (!m_db->commit()) {
        const QString why = m_db->lastError().text();
        m_db->rollback();
        return give(tr("%1: %2").arg(m_path, why));
    }
    m_failing = false;
    return true;
}

bool PassRecordStore::finishPass(qint64 id, Outcome outcome, const QString &reason, const QDateTime &endedUtc,
                                 QString *error)
{
    if (!canRecord()) {
        if (error)
            *error = tr("no pass-record file is open to record");
        return false;
    }
    commit(error);
    QSqlQuery q(*m_db);
    q.prepare(QStringLiteral("UPDATE passes SET outcome = ?, reason = ?, ended_utc = ? WHERE id = ?"));
    q.addBindValue(outcomeName(outcome));
    q.addBindValue(reason.isEmpty() ? QVariant() : QVariant(boundedText(reason, kMaxReasonChars)));
    q.addBindValue(endedUtc.isValid() ? QVariant(storedTime(endedUtc)) : QVariant());
    q.addBindValue(id);
    if (!q.exec()) {
        const QString text = tr("%1: the end of pass %2 could not be recorded: %3").arg(m_path).arg(id).arg(q.lastError().text());
        if (error)
            *error = text;
        failed(text);
        return false;
    }
    emit passChanged(id);
    return true;
}

int PassRecordStore::markInterrupted(const QString &reason)
{
    if (!canRecord())
        return 0;
    QSqlQuery q(*m_db);
    // It ended, as far as anyone can tell, at its last sample.
    q.prepare(QStringLiteral(
        "UPDATE passes SET outcome = 'interrupted', reason = ?, ended_utc = COALESCE("
        "(SELECT strftime('%Y-%m-%dT%H:%M:%fZ', max(unix_ms) / 1000.0, 'unixepoch') FROM pass_samples "
        "WHERE pass_id = passes.id), ended_utc) WHERE outcome = 'in progress'"));
    q.addBindValue(boundedText(reason, kMaxReasonChars));
    if (!q.exec()) {
        failed(tr("%1: %2").arg(m_path, q.lastError().text()));
        return 0;
    }
    return q.numRowsAffected();
}

int PassRecordStore::prune(const QDateTime &nowUtc)
{
    if (!canRecord())
        return 0;
    const QString cutoff = storedTime(nowUtc.addDays(-m_keepDays));
    const QString old = QStringLiteral("SELECT id FROM passes WHERE recorded_utc < ? AND outcome != 'in progress'");
    QSqlQuery count(*m_db);
    count.prepare(QStringLiteral("SELECT count(DISTINCT pass_id) FROM pass_samples WHERE pass_id IN (%1)").arg(old));
    count.addBindValue(cutoff);
    if (!count.exec() || !count.next())
        return 0;
    const int passes = count.value(0).toInt();
    count.finish();
    if (passes == 0)
        return 0;
    QSqlQuery remove(*m_db);
    remove.prepare(QStringLiteral("DELETE FROM pass_samples WHERE pass_id IN (%1)").arg(old));
    remove.addBindValue(cutoff);
    if (!remove.exec()) {
        failed(tr("%1: old samples could not be removed: %2").arg(m_path, remove.lastError().text()));
        return 0;
    }
    return passes;
}

} // namespace slew::records
