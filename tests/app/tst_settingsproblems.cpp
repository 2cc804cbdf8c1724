// SPDX-License-Identifier: GPL-3.0-or-later
// The real `slew` program and a settings file that is not what it should
// be: a garbage slew.conf is moved aside (never deleted) with a message on
// stderr, by the window and by the sky commands alike; one that cannot be
// written makes `slew --qth` fail, naming the file, instead of saying the
// station is kept. Settings live in a temporary XDG_CONFIG_HOME.
//
// Runs as root on the build machines, where permission bits stop nothing:
// the unwritable cases are a file where the Slew directory goes (ENOTDIR)
// and, where chattr can set it, an immutable slew.conf.

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace {

struct Run {
    int exitCode = -1;
    QByteArray out, err;
};

// The program to its end, on the event loop (no waitFor*).
Run run(const QString &program, const QStringList &arguments, const QString &configHome = {})
{
    Run r;
    QProcess p;
    if (!configHome.isEmpty()) {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), configHome);
        env.insert(QStringLiteral("HOME"), configHome);
        p.setProcessEnvironment(env);
    }
    QSignalSpy finished(&p, &QProcess::finished);
    // A program that cannot start (chattr is not in a minimal Debian 13)
    // never finishes: its failure ends the wait too.
    QSignalSpy failedToStart(&p, &QProcess::errorOccurred);
    p.start(program, arguments);
    const bool ended = QTest::qWaitFor([&] { return finished.count() > 0 || failedToStart.count() > 0; }, 120000);
    if (!ended || finished.isEmpty() || p.exitStatus() != QProcess::NormalExit)
        return r;
    r.exitCode = p.exitCode();
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

Run slew(const QStringList &arguments, const QString &configHome)
{
    return run(qEnvironmentVariable("SLEW_BIN"), arguments, configHome);
}

QStringList windowWithQth(const QString &qth, const QString &dir)
{
    return {QStringLiteral("--qth"), qth, QStringLiteral("--screenshot"), QDir(dir).filePath(QStringLiteral("w.png")),
            QStringLiteral("--settle-ms"), QStringLiteral("0")};
}

const QStringList kWhere{QStringLiteral("--where"), QStringLiteral("sun"), QStringLiteral("--time"),
                         QStringLiteral("2024-06-20T12:00:00Z"), QStringLiteral("--json")};

const QByteArray kGarbage("[General\n\x01\x02station=\"\xff\n==\n[\n\x1b[2J");

QStringList brokenCopies(const QString &slewDir)
{
    return QDir(slewDir).entryList({QStringLiteral("slew.conf.broken-*")}, QDir::Files | QDir::Dirs | QDir::System);
}

} // namespace

class SettingsProblemsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY2(!qEnvironmentVariable("SLEW_BIN").isEmpty(), "SLEW_BIN is not set (tests/CMakeLists.txt sets it)");
    }

    // The window: the garbage is kept aside, stderr says where, and the
    // station given is saved in a fresh file that the sky commands read.
    void aGarbageFileIsMovedAsideByTheWindow()
    {
        QTemporaryDir home;
        const QString slewDir = home.filePath(QStringLiteral("Slew"));
        QVERIFY(QDir().mkpath(slewDir));
        QFile conf(slewDir + QStringLiteral("/slew.conf"));
        QVERIFY(conf.open(QIODevice::WriteOnly));
        conf.write(kGarbage);
        conf.close();

        const Run window = slew(windowWithQth(QStringLiteral("FN31pr"), home.path()), home.path());
        QVERIFY2(window.exitCode == 0, window.err.constData());
        const QStringList aside = brokenCopies(slewDir);
        QCOMPARE(aside.size(), 1);
        QVERIFY2(window.err.contains("moved aside") && window.err.contains(aside.first().toUtf8()), window.err.constData());
        QFile kept(slewDir + QLatin1Char('/') + aside.first());
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), kGarbage);
        const Run where = slew(kWhere, home.path());
        QVERIFY2(where.exitCode == 0, where.err.constData());
        QVERIFY2(where.err.isEmpty(), where.err.constData()); // nothing more to move
    }

    // The sky commands read the saved station: they check the file first.
    void aGarbageFileIsMovedAsideByTheSkyCommands()
    {
        QTemporaryDir home;
        const QString slewDir = home.filePath(QStringLiteral("Slew"));
        QVERIFY(QDir().mkpath(slewDir + QStringLiteral("/slew.conf"))); // a directory in its place
        const Run where = slew(kWhere, home.path());
        QCOMPARE(where.exitCode, 2); // no station: the file held none that could be read
        QVERIFY2(where.err.contains("moved aside") && where.err.contains("not a regular file"), where.err.constData());
        QCOMPARE(brokenCopies(slewDir).size(), 1);
        QVERIFY(!QFileInfo::exists(slewDir + QStringLiteral("/slew.conf")));
    }

    // Nowhere to write: `--qth` fails and names the file; the window does
    // not open (no screenshot), and nothing later claims a station.
    void aQthThatCannotBeSavedFails()
    {
        QTemporaryDir home;
        QFile notADirectory(home.filePath(QStringLiteral("Slew")));
        QVERIFY(notADirectory.open(QIODevice::WriteOnly));
        notADirectory.close();
        const Run window = slew(windowWithQth(QStringLiteral("FN31pr"), home.path()), home.path());
        QVERIFY2(window.exitCode != 0, window.err.constData());
        QVERIFY2(window.err.contains("Slew/slew.conf"), window.err.constData());
        QVERIFY2(window.err.contains("not saved"), window.err.constData());
        QVERIFY(!QFileInfo::exists(home.filePath(QStringLiteral("w.png"))));
    }

    void aQthToAnImmutableFileFails()
    {
        QTemporaryDir home;
        const QString slewDir = home.filePath(QStringLiteral("Slew"));
        QVERIFY(QDir().mkpath(slewDir));
        const QString path = slewDir + QStringLiteral("/slew.conf");
        const Run first = slew(windowWithQth(QStringLiteral("JO65hq"), home.path()), home.path());
        QVERIFY2(first.exitCode == 0, first.err.constData());
        const QByteArray before = [&] {
            QFile f(path);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        }();
        QVERIFY(before.contains("JO65hq"));
        if (run(QStringLiteral("chattr"), {QStringLiteral("+i"), path}).exitCode != 0)
            QSKIP("chattr +i is not possible here (not root, or the file system has no immutable flag)");
        const Run window = slew(windowWithQth(QStringLiteral("FN31pr"), home.path()), home.path());
        const Run where = slew(kWhere, home.path());
        QCOMPARE(run(QStringLiteral("chattr"), {QStringLiteral("-i"), path}).exitCode, 0);
        QVERIFY2(window.exitCode != 0, window.err.constData());
        QVERIFY2(window.err.contains(path.toUtf8()), window.err.constData());
        // The station kept is the one the file holds, and it says so.
        QVERIFY2(where.exitCode == 0 && where.out == slew(kWhere + QStringList{QStringLiteral("--qth"),
                                                                               QStringLiteral("JO65hq")},
                                                          home.path()).out,
                 where.err.constData());
    }
};

QTEST_GUILESS_MAIN(SettingsProblemsTest)
#include "tst_settingsproblems.moc"
