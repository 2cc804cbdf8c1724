// SPDX-License-Identifier: GPL-3.0-or-later
// The settings file's guard (model/settingsfile.h): a file that is not
// settings (garbage, a directory, a FIFO) is moved aside under a dated name
// and never deleted; a readable one, or none, is left alone; and a save is
// reported failed when the file cannot take it, as a directory above it
// that is a file does, or an immutable file (chattr +i; that case is
// skipped, saying so, where the file system or the user cannot set it).
//
// This runs as root on the build machines, so no permission bits stop a
// write: only the cases above are honest ones.

#include "model/settingsfile.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace slew::model;

namespace {

const QDateTime kNow(QDate(2024, 3, 5), QTime(6, 7, 8));
const QString kStamp = QStringLiteral(".broken-20240305-060708");

void write(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(bytes);
}

QByteArray contents(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// chattr, run to its end on the event loop: whether it did what was asked.
bool chattr(const QString &flag, const QString &path)
{
    QProcess p;
    QSignalSpy finished(&p, &QProcess::finished);
    p.start(QStringLiteral("chattr"), {flag, path});
    return finished.wait(10000) && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
}

} // namespace

class SettingsFileTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QCoreApplication::setOrganizationName(QStringLiteral("SlewTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_settingsfile"));
        QVERIFY(m_home.isValid());
        qputenv("XDG_CONFIG_HOME", QFile::encodeName(m_home.path()));
    }

    void thePathIsTheOneQSettingsUses()
    {
        QCOMPARE(settingsFilePath(), m_home.filePath(QStringLiteral("SlewTest/tst_settingsfile.conf")));
        QCOMPARE(settingsFilePath(), QSettings().fileName());
    }

    void unreadableFilesAreMovedAsideNeverDeleted_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("why");
        QTest::newRow("garbage") << QStringLiteral("garbage") << QStringLiteral("not in the settings format");
        // Random bytes: QSettings reads them without a FormatError, as a few
        // odd keys, and would drop the rest at the next save.
        QTest::newRow("random bytes") << QStringLiteral("random") << QStringLiteral("not in the settings format");
        QTest::newRow("text that is no INI") << QStringLiteral("prose") << QStringLiteral("not in the settings format");
        QTest::newRow("directory") << QStringLiteral("directory") << QStringLiteral("not a regular file");
        QTest::newRow("FIFO") << QStringLiteral("fifo") << QStringLiteral("not a regular file");
    }

    void unreadableFilesAreMovedAsideNeverDeleted()
    {
        QFETCH(QString, kind);
        QFETCH(QString, why);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("slew.conf"));
        QByteArray garbage("[General\n\x01\x02=\"\xff\n==\n[\n");
        if (kind == QLatin1String("random")) {
            garbage.clear();
            quint32 x = 2463534242u; // xorshift: the same bytes every run
            for (int i = 0; i < 3000; ++i) {
                x ^= x << 13;
                x ^= x >> 17;
                x ^= x << 5;
                garbage.append(char(x & 0xff));
            }
        } else if (kind == QLatin1String("prose")) {
            garbage = "My station notes\nconnect the rotator first\n";
        }
        if (kind == QLatin1String("garbage") || kind == QLatin1String("random") || kind == QLatin1String("prose"))
            write(path, garbage);
        else if (kind == QLatin1String("directory"))
            QVERIFY(QDir().mkdir(path));
        else
            QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0); // opening it would block
        const SettingsCheck check = setAsideUnreadableSettings(path, kNow);
        const QString aside = path + kStamp;
        QCOMPARE(check.movedTo, aside);
        QVERIFY(!QFileInfo::exists(path));
        QVERIFY(QFileInfo::exists(aside));
        if (kind == QLatin1String("garbage") || kind == QLatin1String("random") || kind == QLatin1String("prose"))
            QCOMPARE(contents(aside), garbage);
        QVERIFY2(check.message.contains(why) && check.message.contains(aside) && check.message.contains(path),
                 qPrintable(check.message));

        // The next one the same second gets a name of its own.
        write(path, garbage);
        const SettingsCheck again = setAsideUnreadableSettings(path, kNow);
        QCOMPARE(again.movedTo, aside + QStringLiteral("-2"));
        QVERIFY(QFileInfo::exists(aside));
    }

    void readableOrMissingFilesAreLeftAlone()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("slew.conf"));
        QCOMPARE(setAsideUnreadableSettings(path, kNow).message, QString());
        const QByteArray good("[General]\nstation=FN31pr\n");
        write(path, good);
        write(dir.filePath(QStringLiteral("empty.conf")), {});
        // Everything Slew keeps, as QSettings itself writes it: lists, JSON
        // with quotes, bytes that are not text, names with spaces, unicode.
        const QString written = dir.filePath(QStringLiteral("written.conf"));
        {
            QSettings settings(written, QSettings::IniFormat);
            settings.setValue(QStringLiteral("sky/elementSetUrls"),
                              QStringList{QStringLiteral("https://a.example/x?GROUP=amateur&FORMAT=tle"),
                                          QStringLiteral("file:///srv/t l e.txt")});
            settings.setValue(QStringLiteral("presets/list"), QByteArray("[{\"name\":\"Mast \\\"north\\\"\",\"az\":0}]"));
            settings.setValue(QStringLiteral("binary"), QByteArray("\x00\x01\xff\x1b", 4));
            settings.setValue(QStringLiteral("a key with spaces"), QStringLiteral("Ærø – 55.6° N; #1 = yes"));
            settings.sync();
            QCOMPARE(settings.status(), QSettings::NoError);
        }
        for (const QString &p : {path, dir.filePath(QStringLiteral("empty.conf")), written}) {
            const SettingsCheck check = setAsideUnreadableSettings(p, kNow);
            QVERIFY2(check.message.isEmpty() && check.movedTo.isEmpty(), qPrintable(check.message));
        }
        QCOMPARE(contents(path), good);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 3);
    }

    void aSaveThatReachesTheFileSucceeds()
    {
        QTemporaryDir dir;
        QSettings settings(dir.filePath(QStringLiteral("s.conf")), QSettings::IniFormat);
        QCOMPARE(saveSetting(settings, QStringLiteral("sky/station"), QStringLiteral("FN31pr")), QString());
        QCOMPARE(saveSetting(settings, QStringLiteral("n"), 5), QString());
        QCOMPARE(saveSetting(settings, QStringLiteral("l"), QStringList{QStringLiteral("a"), QStringLiteral("b")}), QString());
        QVERIFY(contents(settings.fileName()).contains("station=FN31pr"));
    }

    void aSaveUnderAFileFails()
    {
        QTemporaryDir dir;
        write(dir.filePath(QStringLiteral("Slew")), "a file where the directory goes");
        QSettings settings(dir.filePath(QStringLiteral("Slew/slew.conf")), QSettings::IniFormat);
        const QString why = saveSetting(settings, QStringLiteral("station"), QStringLiteral("FN31pr"));
        QVERIFY2(why.contains(settings.fileName()), qPrintable(why));
    }

    void aSaveToAnImmutableFileFails()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("slew.conf"));
        write(path, "[General]\nstation=AA00aa\n");
        if (!chattr(QStringLiteral("+i"), path))
            QSKIP("chattr +i is not possible here (not root, or the file system has no immutable flag)");
        QString why;
        {
            // Gone before the flag is: QSettings writes again when it is
            // destroyed, and on the event loop that chattr's wait runs.
            QSettings settings(path, QSettings::IniFormat);
            why = saveSetting(settings, QStringLiteral("station"), QStringLiteral("FN31pr"));
        }
        const QByteArray held = contents(path);
        QVERIFY(chattr(QStringLiteral("-i"), path));
        QVERIFY2(why.contains(path), qPrintable(why));
        QCOMPARE(held, QByteArray("[General]\nstation=AA00aa\n"));
    }

private:
    QTemporaryDir m_home;
};

QTEST_GUILESS_MAIN(SettingsFileTest)
#include "tst_settingsfile.moc"
