// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The record of every pass, in an SQLite database (Qt SQL's QSQLITE
// driver; on Debian, libqt6sql6-sqlite).
//
// Written as the pass goes: a pass's row when it begins, its samples and
// figures gathered and committed together every kCommitIntervalMs, its
// outcome when it ends. The database runs in WAL mode with synchronous
// NORMAL, so a commit costs no wait for the disk and a Slew killed mid-pass
// loses at most the last seconds; a pass it left "in progress" is marked
// interrupted when the next store opens the file to record.
//
// One store records into a file at a time: it holds `FILE.lock` (QLockFile)
// while open to record, and another (the window beside the station service,
// on the same file) is refused, naming the process; readers need no lock.
//
// A file that is not an SQLite database, is another program's, or is of a
// newer schema is refused with a message that names it, and is left as it
// is: nothing here ever replaces or renames a database it cannot read.
// Samples of passes recorded more than keepDays() ago are removed when the
// store opens and daily after; the passes' own rows (a few hundred bytes
// each) stay.
//
// Nothing waits: SQLite is asked for no busy wait beyond kBusyTimeoutMs.

#include "passrecord.h"

#include <QObject>
#include <QTimer>

#include <map>
#include <memory>
#include <optional>
#include <vector>

class QLockFile;
class QSqlDatabase;

namespace slew::records {

class PassRecordStore : public QObject {
    Q_OBJECT
public:
    enum class Access { Record, Read };

    static constexpr int kCommitIntervalMs = 2000;
    static constexpr int kDefaultKeepDays = 90;
    static constexpr int kMaxKeepDays = 36500;
    static constexpr int kBusyTimeoutMs = 200;
    // Samples gathered past this between two commits are not kept: a store
    // whose commits fail does not grow without end.
    static constexpr int kMaxBuffered = 20000;
    static constexpr int kMaxTargetChars = 200;
    static constexpr int kMaxReasonChars = 500;

    // The application's data directory + "/passes.sqlite".
    static QString defaultPath();

    explicit PassRecordStore(QObject *parent = nullptr);
    ~PassRecordStore() override; // commits what is gathered

    // Opens the database at `path`: to record, making it (and its folder)
    // when absent, migrating an older schema, marking passes left in
    // progress as interrupted and pruning; or only to read. False, with a
    // message naming the file, when it cannot be used.
    bool open(const QString &path, Access access, QString *error);
    bool isOpen() const { return m_db != nullptr; }
    QString path() const { return m_path; }
    Access access() const { return m_access; }
    bool canRecord() const { return isOpen() && m_access == Access::Record; }
    // The last open() to record failed because another Slew records there.
    bool takenByAnother() const { return m_takenByAnother; }

    // What open() found and did, for the log.
    struct OpenNotes {
        int migratedFrom = 0;     // the schema version it had, when migrated
        int interrupted = 0;      // passes found in progress and marked interrupted
        int prunedPasses = 0;     // passes whose samples were removed for their age
        bool created = false;
    };
    const OpenNotes &openNotes() const { return m_notes; }

    // How long samples are kept, 1..kMaxKeepDays days.
    void setKeepDays(int days);
    int keepDays() const { return m_keepDays; }

    // --- Recording (Access::Record) --------------------------------------
    // A new pass "in progress"; its id, or nothing with *error.
    std::optional<qint64> beginPass(const PassPlanned &planned, QString *error = nullptr);
    // Gathered and committed with the next commit. A sample with a value
    // that is not a finite number in range (passrecord.h) is not kept.
    void addSample(qint64 id, const PassSample &sample);
    // The figures so far; the latest are written with the next commit.
    void setFigures(qint64 id, const PassFigures &figures);
    // Commits what is gathered, then the outcome, and the time it ended.
    bool finishPass(qint64 id, Outcome outcome, const QString &reason, const QDateTime &endedUtc,
                    QString *error = nullptr);
    // A pass that was not tracked, and why (another pass took the rotator,
    // the link was down...): its row only, outcome dropped.
    std::optional<qint64> recordDropped(const PassPlanned &planned, const QString &reason, QString *error = nullptr);
    // Writes what is gathered in one transaction; the timer does this
    // every kCommitIntervalMs.
    bool commit(QString *error = nullptr);
    // Removes the samples of passes recorded before nowUtc - keepDays();
    // the number of passes that lost theirs.
    int prune(const QDateTime &nowUtc);
    // Marks every pass in progress as interrupted, for `reason`; how many.
    int markInterrupted(const QString &reason);

    // --- Reading ---------------------------------------------------------
    // Newest first; those whose target contains `targetContains` (any
    // case) when it is given; at most `limit`.
    QList<PassRecord> passes(const QString &targetContains = {}, int limit = 5000) const;
    std::optional<PassRecord> pass(qint64 id) const;
    // In time order. Rows whose values are out of range (a damaged or
    // hand-edited file) are left out and counted in *skipped.
    QList<PassSample> samples(qint64 id, int *skipped = nullptr) const;

    // The reason open() gives the passes it finds in progress.
    static QString interruptedAtStartReason();

signals:
    // A pass was begun, finished or dropped: a list of passes may read again.
    void passChanged(qint64 id);
    // A write failed (a full disk, a file removed underneath): said once
    // per run of failures, naming the file.
    void writeFailed(const QString &error);

private:
    bool openDatabase(const QString &path, Access access, QString *error);
    bool prepareSchema(QString *error);
    bool exec(const QString &statement, QString *error) const;
    std::optional<int> pragmaNumber(const char *name, QString *error) const;
    std::optional<qint64> insertPass(const PassPlanned &planned, Outcome outcome, const QString &reason,
                                     QString *error);
    void scheduleCommit();
    void failed(const QString &error);
    void close();

    QString m_path;
    QString m_connection;
    std::unique_ptr<QSqlDatabase> m_db;
    std::unique_ptr<QLockFile> m_lock;
    Access m_access = Access::Read;
    int m_version = 0;
    int m_keepDays = kDefaultKeepDays;
    OpenNotes m_notes;
    struct Gathered {
        qint64 id;
        PassSample sample;
    };
    std::vector<Gathered> m_samples;
    std::map<qint64, PassFigures> m_figures;
    int m_droppedSamples = 0;
    bool m_failing = false;
    bool m_takenByAnother = false;
    QTimer m_commitTimer;
    QTimer m_pruneTimer;
};

} // namespace slew::records
