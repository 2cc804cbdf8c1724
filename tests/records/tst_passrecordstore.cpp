// SPDX-License-Identifier: GPL-3.0-or-later
// The pass records' store: a pass written as it goes and read back with its
// samples; a version 1 file made by hand migrated with its rows kept; a
// file that is not SQLite, another program's database and a newer schema
// each refused and left byte for byte as they were; passes left in
// progress marked interrupted at the next open; old samples pruned; a
// second recorder on the same file refused; figures that are not numbers
// stored as NULL, samples that are not numbers not stored.

#include "records/passrecordschema.h"
#include "records/passrecordstore.h"

#include <QCryptographicHash>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <limits>

using namespace slew::records;

namespace {

const QDateTime kAos = QDateTime::fromString(QStringLiteral("2018-01-22T09:17:51.250Z"), Qt::ISODateWithMs);

PassPlanned flock()
{
    PassPlanned p;
    p.target = QStringLiteral("FLOCK 2P-1");
    p.norad = 41618;
    p.aos = kAos;
    p.tca = kAos.addSecs(210);
    p.los = kAos.addSecs(433);
    p.maxElevationDeg = 56.2;
    p.plannedWorstDeg = 0.22;
    p.rehearsal = true;
    return p;
}

PassSample sampleAt(int second)
{
    return PassSample{kAos.addSecs(second).toMSecsSinceEpoch(), 120.0 + second * 0.1, 10.0 + second * 0.05,
                      120.05 + second * 0.1, 10.02 + second * 0.05, 0.06};
}

QByteArray digest(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256);
}

// Runs statements on a database of the test's own, outside any store.
bool runSql(const QString &path, const QStringList &statements)
{
    bool ok = true;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("test-by-hand"));
        db.setDatabaseName(path);
        ok = db.open();
        for (const QString &s : statements) {
            QSqlQuery q(db);
            if (ok && !q.exec(s)) {
                qWarning("%s: %s", qPrintable(s), qPrintable(q.lastError().text()));
                ok = false;
            }
        }
        db.close();
    }
    QSqlDatabase::removeDatabase(QStringLiteral("test-by-hand"));
    return ok;
}

QVariant sqlValue(const QString &path, const QString &query)
{
    QVariant value;
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), QStringLiteral("test-look"));
        db.setDatabaseName(path);
        db.setConnectOptions(QStringLiteral("QSQLITE_OPEN_READONLY"));
        if (db.open()) {
            QSqlQuery q(db);
            if (q.exec(query) && q.next())
                value = q.value(0);
        }
        db.close();
    }
    QSqlDatabase::removeDatabase(QStringLiteral("test-look"));
    return value;
}

} // namespace

class PassRecordStoreTest : public QObject {
    Q_OBJECT
private slots:
    void writesAPassAsItGoesAndReadsItBack()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("deep/er/passes.sqlite"));
        PassRecordStore store;
        QString error;
        QVERIFY2(store.open(path, PassRecordStore::Access::Record, &error), qPrintable(error));
        QVERIFY(store.openNotes().created);
        QCOMPARE(sqlValue(path, QStringLiteral("PRAGMA journal_mode")).toString(), QStringLiteral("wal"));
        QCOMPARE(sqlValue(path, QStringLiteral("PRAGMA user_version")).toInt(), schema::kCurrentVersion);

        const auto id = store.beginPass(flock(), &error);
        QVERIFY2(id, qPrintable(error));
        // Readable at once, by another reader too: in progress.
        PassRecordStore reader;
        QVERIFY2(reader.open(path, PassRecordStore::Access::Read, &error), qPrintable(error));
        QCOMPARE(reader.pass(*id)->outcome, Outcome::InProgress);

        for (int s = 0; s < 10; ++s)
            store.addSample(*id, sampleAt(s));
        PassSample bad = sampleAt(11);
        bad.errorDeg = std::numeric_limits<double>::quiet_NaN();
        store.addSample(*id, bad); // not a number: not kept
        bad = sampleAt(12);
        bad.antennaAzDeg = std::numeric_limits<double>::infinity();
        store.addSample(*id, bad);
        PassFigures figures;
        figures.rmsDeg = std::numeric_limits<double>::quiet_NaN(); // stored as NULL, never as NaN
        figures.worstDeg = 0.31;
        figures.commands = 57;
        figures.dopplerRmsHz = 1.4;
        figures.dopplerWorstHz = 8.0;
        store.setFigures(*id, figures);
        // Nothing of it is in the file until the commit (every 2 s).
        QCOMPARE(reader.samples(*id).size(), 0);
        QVERIFY(store.commit(&error));
        QCOMPARE(reader.samples(*id).size(), 10);
        QVERIFY(sqlValue(path, QStringLiteral("SELECT rms_deg FROM passes")).isNull());
        QCOMPARE(sqlValue(path, QStringLiteral("SELECT typeof(rms_deg) FROM passes")).toString(), QStringLiteral("null"));

        // The timer commits by itself.
        store.addSample(*id, sampleAt(10));
        QTRY_COMPARE_WITH_TIMEOUT(reader.samples(*id).size(), 11, PassRecordStore::kCommitIntervalMs + 3000);

        const QDateTime ended = kAos.addSecs(433);
        QVERIFY(store.finishPass(*id, Outcome::Tracked, {}, ended, &error));
        const std::optional<PassRecord> r = reader.pass(*id);
        QVERIFY(r);
        QCOMPARE(r->planned.target, QStringLiteral("FLOCK 2P-1"));
        QCOMPARE(r->planned.norad, 41618);
        QCOMPARE(r->planned.aos, kAos);
        QCOMPARE(r->planned.tca, kAos.addSecs(210));
        QCOMPARE(r->planned.los, kAos.addSecs(433));
        QCOMPARE(*r->planned.maxElevationDeg, 56.2);
        QCOMPARE(*r->planned.plannedWorstDeg, 0.22);
        QVERIFY(r->planned.rehearsal);
        QVERIFY(!r->figures.rmsDeg);
        QCOMPARE(*r->figures.worstDeg, 0.31);
        QCOMPARE(*r->figures.commands, 57);
        QCOMPARE(*r->figures.dopplerRmsHz, 1.4);
        QCOMPARE(*r->figures.dopplerWorstHz, 8.0);
        QCOMPARE(r->outcome, Outcome::Tracked);
        QCOMPARE(r->ended, ended);
        QCOMPARE(r->samples, 11);
        QVERIFY(std::abs(r->recorded.secsTo(QDateTime::currentDateTimeUtc())) < 60);
        const QList<PassSample> samples = reader.samples(*id);
        QCOMPARE(samples.first().unixMs, kAos.toMSecsSinceEpoch());
        QCOMPARE(samples.last().antennaAzDeg, 121.0);
        QCOMPARE(sqlValue(path, QStringLiteral("SELECT aos_utc FROM passes")).toString(),
                 QStringLiteral("2018-01-22T09:17:51.250Z"));

        // A pass of the sun: no catalogue number.
        PassPlanned sun = flock();
        sun.target = QStringLiteral("sun");
        sun.norad.reset();
        QVERIFY(store.recordDropped(sun, QStringLiteral("another pass had the rotator"), &error));
        QCOMPARE(reader.passes().size(), 2);
        QVERIFY(!reader.passes().first().planned.norad);
        QCOMPARE(reader.passes().first().outcome, Outcome::Dropped);
        QCOMPARE(reader.passes().first().reason, QStringLiteral("another pass had the rotator"));
        // Filtered by target, in any case; a wildcard in the filter is a character.
        QCOMPARE(reader.passes(QStringLiteral("flock")).size(), 1);
        QCOMPARE(reader.passes(QStringLiteral("%")).size(), 0);
        QCOMPARE(reader.passes(QStringLiteral("SU")).first().planned.target, QStringLiteral("sun"));
        // A pass needs its target and times.
        PassPlanned nameless = flock();
        nameless.target = QStringLiteral("  ");
        QVERIFY(!store.beginPass(nameless, &error));
        // A reader cannot write.
        QVERIFY(!reader.beginPass(flock()));
    }

    // What a commit costs the event loop it runs on: two seconds of a pass
    // (four samples and the figures), in one transaction.
    void aCommitIsQuick()
    {
        QTemporaryDir dir;
        PassRecordStore store;
        QString error;
        QVERIFY(store.open(dir.filePath(QStringLiteral("passes.sqlite")), PassRecordStore::Access::Record, &error));
        const qint64 id = *store.beginPass(flock());
        PassFigures figures;
        figures.rmsDeg = 0.1;
        figures.worstDeg = 0.3;
        QElapsedTimer timer;
        timer.start();
        constexpr int kCommits = 300; // ten minutes of a pass
        for (int c = 0; c < kCommits; ++c) {
            for (int s = 0; s < 4; ++s)
                store.addSample(id, sampleAt(c * 4 + s));
            figures.commands = c;
            store.setFigures(id, figures);
            QVERIFY(store.commit(&error));
        }
        const double ms = double(timer.nsecsElapsed()) / 1e6 / kCommits;
        qInfo("a commit of 4 samples and the figures: %.3f ms on average over %d", ms, kCommits);
        QVERIFY2(ms < 100, qPrintable(QString::number(ms)));
        QCOMPARE(store.samples(id).size(), kCommits * 4);
    }

    void migratesAVersion1FileAndKeepsItsRows()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("v1.sqlite"));
        QStringList v1 = schema::create(1);
        // Recorded now: samples older than the keep days would be pruned at open.
        v1 << QStringLiteral("INSERT INTO passes (target, norad, aos_utc, los_utc, max_el_deg, rms_deg, worst_deg, "
                             "commands, outcome, recorded_utc) VALUES ('ISS (ZARYA)', 25544, '2024-06-20T12:00:00.000Z', "
                             "'2024-06-20T12:10:00.000Z', 45.5, 0.1, 0.3, 80, 'tracked', '%1')")
                  .arg(storedTime(QDateTime::currentDateTimeUtc()))
           << QStringLiteral("INSERT INTO pass_samples VALUES (1, 1718884800000, 100, 10, 100.1, 10.1, 0.14)");
        QVERIFY(runSql(path, v1));
        QCOMPARE(sqlValue(path, QStringLiteral("PRAGMA user_version")).toInt(), 1);
        // Version 1 has no Doppler columns.
        QVERIFY(!sqlValue(path, QStringLiteral("SELECT count(*) FROM pragma_table_info('passes') WHERE name = "
                                               "'doppler_rms_hz'"))
                     .toBool());

        // A reader takes it as it is, the Doppler figures as not there.
        QString error;
        {
            PassRecordStore reader;
            QVERIFY2(reader.open(path, PassRecordStore::Access::Read, &error), qPrintable(error));
            QCOMPARE(reader.passes().size(), 1);
            QVERIFY(!reader.passes().first().figures.dopplerRmsHz);
            QCOMPARE(sqlValue(path, QStringLiteral("PRAGMA user_version")).toInt(), 1);
        }

        PassRecordStore store;
        QVERIFY2(store.open(path, PassRecordStore::Access::Record, &error), qPrintable(error));
        QCOMPARE(store.openNotes().migratedFrom, 1);
        QCOMPARE(sqlValue(path, QStringLiteral("PRAGMA user_version")).toInt(), 2);
        const QList<PassRecord> passes = store.passes();
        QCOMPARE(passes.size(), 1);
        QCOMPARE(passes.first().planned.target, QStringLiteral("ISS (ZARYA)"));
        QCOMPARE(*passes.first().figures.commands, 80);
        QVERIFY(!passes.first().figures.dopplerRmsHz);
        QCOMPARE(store.samples(passes.first().id).size(), 1);
        // And the new columns take figures.
        PassFigures f = passes.first().figures;
        f.dopplerRmsHz = 2.5;
        store.setFigures(passes.first().id, f);
        QVERIFY(store.commit(&error));
        QCOMPARE(*store.pass(passes.first().id)->figures.dopplerRmsHz, 2.5);
    }

    void refusesAFileThatIsNotADatabaseAndLeavesItAlone()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("passes.sqlite"));
        QFile text(path);
        QVERIFY(text.open(QIODevice::WriteOnly));
        text.write("# my notes on passes\nISS 12:00 good\n");
        text.close();
        const QByteArray before = digest(path);
        for (auto access : {PassRecordStore::Access::Record, PassRecordStore::Access::Read}) {
            PassRecordStore store;
            QString error;
            QVERIFY(!store.open(path, access, &error));
            QVERIFY2(error.contains(path) && error.contains(QStringLiteral("not an SQLite database")), qPrintable(error));
            QVERIFY(!store.isOpen());
        }
        QCOMPARE(digest(path), before);
        // Nothing beside it either: no log, no lock left behind.
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("passes.sqlite")});

        // A directory is not a file.
        PassRecordStore store;
        QString error;
        QVERIFY(!store.open(dir.path(), PassRecordStore::Access::Record, &error));
        QVERIFY2(error.contains(QStringLiteral("a directory")), qPrintable(error));
    }

    void refusesAnotherProgramsDatabase()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("other.sqlite"));
        QVERIFY(runSql(path, {QStringLiteral("CREATE TABLE contacts (call TEXT)"),
                              QStringLiteral("INSERT INTO contacts VALUES ('OZ1ABC')")}));
        const QByteArray before = digest(path);
        PassRecordStore store;
        QString error;
        QVERIFY(!store.open(path, PassRecordStore::Access::Record, &error));
        QVERIFY2(error.contains(path) && error.contains(QStringLiteral("another program's")), qPrintable(error));
        QCOMPARE(digest(path), before);
    }

    void refusesANewerSchemaAndLeavesItAlone()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("newer.sqlite"));
        QStringList newer = schema::create(schema::kCurrentVersion);
        newer << QStringLiteral("PRAGMA user_version = %1").arg(schema::kCurrentVersion + 1);
        QVERIFY(runSql(path, newer));
        const QByteArray before = digest(path);
        for (auto access : {PassRecordStore::Access::Record, PassRecordStore::Access::Read}) {
            PassRecordStore store;
            QString error;
            QVERIFY(!store.open(path, access, &error));
            QVERIFY2(error.contains(path) && error.contains(QStringLiteral("newer than this Slew's 2")), qPrintable(error));
        }
        QCOMPARE(digest(path), before);
        QVERIFY(!QFile::exists(path + QStringLiteral(".lock")));
    }

    void marksAPassLeftInProgressAsInterrupted()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("passes.sqlite"));
        QString error;
        qint64 id = 0;
        {
            PassRecordStore store;
            QVERIFY(store.open(path, PassRecordStore::Access::Record, &error));
            id = *store.beginPass(flock());
            for (int s = 0; s < 30; ++s)
                store.addSample(id, sampleAt(s));
            QVERIFY(store.commit());
            // Gone without finishing the pass.
        }
        PassRecordStore store;
        QVERIFY(store.open(path, PassRecordStore::Access::Record, &error));
        QCOMPARE(store.openNotes().interrupted, 1);
        const PassRecord r = *store.pass(id);
        QCOMPARE(r.outcome, Outcome::Interrupted);
        QCOMPARE(r.reason, QStringLiteral("Slew stopped during the pass (found at the next start)"));
        QCOMPARE(r.ended, kAos.addSecs(29)); // its last sample
        QCOMPARE(r.samples, 30);
    }

    void prunesOldSamplesAndKeepsThePasses()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("passes.sqlite"));
        PassRecordStore store;
        QString error;
        QVERIFY(store.open(path, PassRecordStore::Access::Record, &error));
        QCOMPARE(store.keepDays(), 90);
        const qint64 done = *store.beginPass(flock());
        const qint64 going = *store.beginPass(flock());
        for (int s = 0; s < 5; ++s) {
            store.addSample(done, sampleAt(s));
            store.addSample(going, sampleAt(s));
        }
        QVERIFY(store.finishPass(done, Outcome::Tracked, {}, kAos.addSecs(433)));
        const QDateTime now = QDateTime::currentDateTimeUtc();
        QCOMPARE(store.prune(now.addDays(89)), 0);
        QCOMPARE(store.samples(done).size(), 5);
        // Recorded 91 days before: its samples go, its row stays; a pass
        // still in progress keeps everything.
        QCOMPARE(store.prune(now.addDays(91)), 1);
        QCOMPARE(store.samples(done).size(), 0);
        QVERIFY(store.pass(done));
        QCOMPARE(*store.pass(done)->planned.maxElevationDeg, 56.2);
        QCOMPARE(store.samples(going).size(), 5);
        store.setKeepDays(7);
        QVERIFY(store.finishPass(going, Outcome::Tracked, {}, kAos.addSecs(433)));
        QCOMPARE(store.prune(now.addDays(8)), 1);
        store.setKeepDays(0);
        QCOMPARE(store.keepDays(), 1);
    }

    void oneRecorderAtATime()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("passes.sqlite"));
        PassRecordStore first, second, reader;
        QString error;
        QVERIFY(first.open(path, PassRecordStore::Access::Record, &error));
        QVERIFY(!second.open(path, PassRecordStore::Access::Record, &error));
        QVERIFY2(error.contains(QString::number(QCoreApplication::applicationPid())) && error.contains(path),
                 qPrintable(error));
        QVERIFY2(reader.open(path, PassRecordStore::Access::Read, &error), qPrintable(error));
    }

    void aReaderNeedsAFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("none.sqlite"));
        PassRecordStore reader;
        QString error;
        QVERIFY(!reader.open(path, PassRecordStore::Access::Read, &error));
        QVERIFY2(error.contains(QStringLiteral("no pass records")), qPrintable(error));
        QVERIFY(!QFile::exists(path));
    }

    void numbersReadBackAreChecked()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("edited.sqlite"));
        QStringList rows = schema::create(schema::kCurrentVersion);
        rows << QStringLiteral("INSERT INTO passes (target, aos_utc, los_utc, max_el_deg, rms_deg, worst_deg, commands, "
                               "outcome, recorded_utc) VALUES ('X', '2024-06-20T12:00:00.000Z', 'yesterday', 400, -1, "
                               "'abc', -5, 'great', '2024-06-20T12:00:01.000Z')")
             << QStringLiteral("INSERT INTO pass_samples VALUES (1, 1718884800000, 100, 10, 100.1, 10.1, 0.14)")
             << QStringLiteral("INSERT INTO pass_samples VALUES (1, 1718884801000, 9e999, 10, 100.1, 10.1, 0.14)")
             << QStringLiteral("INSERT INTO pass_samples VALUES (1, 1718884802000, 100, 10, 100.1, 10.1, 'x')");
        QVERIFY(runSql(path, rows));
        PassRecordStore reader;
        QString error;
        QVERIFY2(reader.open(path, PassRecordStore::Access::Read, &error), qPrintable(error));
        const PassRecord r = *reader.pass(1);
        QVERIFY(!r.planned.los.isValid());
        QVERIFY(!r.planned.maxElevationDeg);
        QVERIFY(!r.figures.rmsDeg);
        QVERIFY(!r.figures.worstDeg);
        QVERIFY(!r.figures.commands);
        QCOMPARE(r.outcome, Outcome::Interrupted);
        QVERIFY(r.reason.contains(QStringLiteral("'great'")));
        int skipped = 0;
        QCOMPARE(reader.samples(1, &skipped).size(), 1);
        QCOMPARE(skipped, 2);
    }
};

QTEST_GUILESS_MAIN(PassRecordStoreTest)
#include "tst_passrecordstore.moc"
