// SPDX-License-Identifier: GPL-3.0-or-later
// The command lines described once (app/cli): the config file reader, the
// precedence of the command line over the file, and the manual page made
// from the same descriptions as --help.

#include "cli/configfile.h"
#include "cli/manpage.h"
#include "cli/sharedoptions.h"
#include "cli/slewcommandline.h"
#include "sky/utctime.h"

#include <QCommandLineParser>
#include <QDir>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

using namespace slew::cli;

namespace {

struct SlewRun {
    int exitCode = -1;
    QString standardError;
};

// Runs the slew program to its end, waiting on its finished signal.
SlewRun runSlew(const QStringList &arguments, const QString &home = {})
{
    QProcess slew;
    if (!home.isEmpty()) {
        // The window's settings in a home of the test's own.
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("HOME"), home);
        env.insert(QStringLiteral("XDG_CONFIG_HOME"), home);
        env.insert(QStringLiteral("XDG_CACHE_HOME"), home);
        slew.setProcessEnvironment(env);
    }
    QSignalSpy finished(&slew, &QProcess::finished);
    slew.start(QString::fromLocal8Bit(qgetenv("SLEW_BIN")), arguments);
    if (!finished.wait(60000))
        slew.kill();
    return {slew.exitCode(), QString::fromUtf8(slew.readAllStandardError())};
}

} // namespace

class CommandLineTest : public QObject {
    Q_OBJECT
private slots:
    void configFileBecomesOptions();
    void configFileRefusesWhatItCannotMean_data();
    void configFileRefusesWhatItCannotMean();
    void commandLineWinsOverTheFile();
    void missingOrHugeFileIsRefused();
    void configFileTextIsEscapedInMessages();
    void valueRefusalsNameTheFileAndLine();
    void manualListsEveryOptionOfEveryMode();
    void windowReadsTheRehearsalClockAsTheServiceDoes();
    void windowStartsInRehearsal();
    void manualEscapesRoff();
};

void CommandLineTest::configFileBecomesOptions()
{
    QString error;
    const auto args = parseConfigText(QStringLiteral("# a comment\n"
                                                     "\n"
                                                     "connect = tcp://192.0.2.10:4533\n"
                                                     "  dialect=gs232b  \n"
                                                     "profile =\n"
                                                     "rotctld-listen = 127.0.0.1:4533 # not a comment: part of it\n"),
                                      QStringLiteral("t.conf"), slewHeadlessMode(), &error);
    QVERIFY2(args, qPrintable(error));
    QCOMPARE(args->arguments, (QStringList{"--connect=tcp://192.0.2.10:4533", "--dialect=gs232b",
                                           "--rotctld-listen=127.0.0.1:4533 # not a comment: part of it"}));
    // Each value knows its line, for the messages about it later.
    QCOMPARE(args->label("connect"), QString("t.conf:3: connect"));
    // A switch is set by true (or yes), and left out by false.
    const auto switches = parseConfigText(QStringLiteral("radio-restore = true\ntransponder-invert = no\n"),
                                          QStringLiteral("s.conf"), slewHeadlessMode(), &error);
    QVERIFY2(switches, qPrintable(error));
    QCOMPARE(switches->arguments, QStringList{"--radio-restore"});
    QCOMPARE(args->label("rotctld-listen"), QString("t.conf:6: rotctld-listen"));
    QCOMPARE(args->label("profile"), QString("--profile")); // empty: not set by the file
}

void CommandLineTest::configFileRefusesWhatItCannotMean_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    QTest::newRow("no equals") << "connect sim:" << "t.conf:1: expected `name = value`";
    QTest::newRow("unknown name") << "\n\nlisten = 1.2.3.4:5" << "t.conf:3: unknown setting 'listen'";
    QTest::newRow("a switch") << "headless = 1" << "t.conf:1: unknown setting 'headless'";
    QTest::newRow("the file itself") << "config = /etc/passwd" << "unknown setting 'config'";
    QTest::newRow("empty name") << "= sim:" << "unknown setting ''";
    QTest::newRow("a name twice") << "connect = sim:\n# the real one\nconnect = tcp://192.0.2.1:1"
                                  << "t.conf:3: 'connect' is set again; it was set on line 1 already";
    QTest::newRow("twice, once empty") << "profile =\nprofile = a.json" << "t.conf:2: 'profile' is set again";
    QTest::newRow("a switch that is not") << "radio-restore = maybe"
                                          << "t.conf:1: radio-restore is a switch: true or false, not 'maybe'";
}

void CommandLineTest::configFileRefusesWhatItCannotMean()
{
    QFETCH(QString, text);
    QFETCH(QString, message);
    QString error;
    QVERIFY(!parseConfigText(text, QStringLiteral("t.conf"), slewHeadlessMode(), &error));
    QVERIFY2(error.startsWith(message) || error.contains(message), qPrintable(error));
    // Every refusal says what may be set instead.
    if (error.contains(u"unknown setting"))
        QVERIFY2(error.contains(u"connect, dialect, profile, rotctld-listen, rotctld-allow, rotctld-max-clients"), qPrintable(error));
}

void CommandLineTest::configFileTextIsEscapedInMessages()
{
    // ESC and BEL from a file must not reach a terminal or the journal raw.
    for (const char *text : {"\x1b[2J\x07" "bad = 1", "connect sim:\x1b]0;owned\x07"}) {
        QString error;
        QVERIFY(!parseConfigText(QString::fromLatin1(text), QStringLiteral("t.conf"), slewHeadlessMode(), &error));
        QVERIFY2(!error.contains(QChar(0x1b)) && !error.contains(QChar(0x07)), qPrintable(error));
        QVERIFY2(error.contains("\\x1b"), qPrintable(error));
    }
}

void CommandLineTest::valueRefusalsNameTheFileAndLine()
{
    // The value is read after the file (a port is checked by the service):
    // its refusal still names the file and the line.
    QTemporaryDir dir;
    const QString path = dir.filePath("station.conf");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("connect = sim:\n\nrotctld-listen = 127.0.0.1:70000\n");
    file.close();
    const SlewRun fromFile = runSlew({"--headless", "--config", path});
    QCOMPARE(fromFile.exitCode, 2);
    QVERIFY2(fromFile.standardError.contains(path + ":3: rotctld-listen 127.0.0.1:70000: "),
             qPrintable(fromFile.standardError));
    QVERIFY2(fromFile.standardError.contains("65535"), qPrintable(fromFile.standardError));

    // The same value on the command line is named as the option.
    const SlewRun fromOption = runSlew({"--headless", "--rotctld-listen", "127.0.0.1:70000"});
    QCOMPARE(fromOption.exitCode, 2);
    QVERIFY2(fromOption.standardError.contains("--rotctld-listen 127.0.0.1:70000: "),
             qPrintable(fromOption.standardError));
}

void CommandLineTest::commandLineWinsOverTheFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("station.conf");
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("connect = sim:?az_max=450\nrotctld-listen = 127.0.0.1:4533\n");
    file.close();

    QString error;
    const auto args = withConfigFile({"slew", "--headless", "--config", path, "--connect", "tcp://192.0.2.1:1"},
                                     slewHeadlessMode(), &error);
    QVERIFY2(args, qPrintable(error));
    QCommandLineParser parser;
    describeTo(parser, slewHeadlessMode());
    QVERIFY2(parser.parse(args->arguments), qPrintable(parser.errorText()));
    QCOMPARE(parser.value("connect"), QString("tcp://192.0.2.1:1"));
    QCOMPARE(parser.value("rotctld-listen"), QString("127.0.0.1:4533"));
    // The command line's value is not the file's: messages name the option.
    QCOMPARE(args->label("connect"), QString("--connect"));
    QCOMPARE(args->label("rotctld-listen"), path + ":2: rotctld-listen");

    // Without --config the arguments are untouched.
    const QStringList plain{"slew", "--headless", "--connect", "sim:"};
    QCOMPARE(withConfigFile(plain, slewHeadlessMode(), &error)->arguments, plain);
}

void CommandLineTest::missingOrHugeFileIsRefused()
{
    QString error;
    QVERIFY(!withConfigFile({"slew", "--headless", "--config=/nonexistent/slew.conf"}, slewHeadlessMode(), &error));
    QVERIFY2(error.startsWith("config file /nonexistent/slew.conf:"), qPrintable(error));

    QTemporaryDir dir;
    QFile big(dir.filePath("big.conf"));
    QVERIFY(big.open(QIODevice::WriteOnly));
    big.write(QByteArray(100 * 1024, '#'));
    big.close();
    QVERIFY(!readConfigFile(big.fileName(), slewHeadlessMode(), &error));
    QVERIFY2(error.contains("over the 64 KiB limit"), qPrintable(error));

    // A device reads as 0 bytes to QFile::size(), and then for ever: refused
    // before a byte is read.
    QVERIFY(!readConfigFile("/dev/zero", slewHeadlessMode(), &error));
    QVERIFY2(error.contains("/dev/zero is a character device"), qPrintable(error));
    // A FIFO with no writer would block open() for ever.
    const QString fifo = dir.filePath("fifo.conf");
    QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
    QVERIFY(!readConfigFile(fifo, slewHeadlessMode(), &error));
    QVERIFY2(error.contains("FIFO"), qPrintable(error));
}

void CommandLineTest::manualListsEveryOptionOfEveryMode()
{
    for (const ProgramDescription *program : {&slewProgram(), &slewSimProgram()}) {
        const QString page = renderManPage(*program, QStringLiteral("9.9"));
        QVERIFY(page.startsWith(u".\\\""));
        QVERIFY(page.contains(QStringLiteral(".TH %1 1").arg(program->name.toUpper().replace(u'-', "\\-"))));
        for (const ProgramMode &mode : program->modes) {
            QVERIFY(!mode.options.isEmpty());
            for (const ProgramOption &option : mode.options) {
                const QString roffName = QStringLiteral("\\fB\\-\\-%1\\fR").arg(QString(option.longName()).replace(u'-', "\\-"));
                QVERIFY2(page.contains(roffName), qPrintable(program->name + ": " + option.longName()));
            }
        }
    }
    // The simulator's own options appear, both spellings.
    const QString sim = renderManPage(slewSimProgram(), QStringLiteral("9.9"));
    QVERIFY(sim.contains(u"\\fB\\-\\-az\\-max\\fR"));
    QVERIFY(sim.contains(u"\\fB\\-\\-az_max\\fR"));

    // Every dialect family, the keys and the files a user meets.
    const QString slew = renderManPage(slewProgram(), QStringLiteral("9.9"));
    for (const char *words : {"Micro\\-2g", "Rot2Prog", "GS\\-232A/B", ".SH \"KEYBOARD\"", "Esc", "slew.conf",
                              "slew.conf.broken", "element\\-sets/", "rotator.json"})
        QVERIFY2(slew.contains(QLatin1String(words)), words);
    // The page is plain ASCII: groff warns on anything else.
    for (const QChar c : slew)
        QVERIFY2(c.unicode() < 128, qPrintable(QStringLiteral("non-ASCII %1 in the page").arg(c)));
}

void CommandLineTest::windowReadsTheRehearsalClockAsTheServiceDoes()
{
    // The window and the station service take the clock, the profile and the
    // travel alike, and refuse alike.
    for (const ProgramMode *mode : {&slewWindowMode(), &slewHeadlessMode()}) {
        for (const char *option : {"clock-start", "clock-rate", "profile", "limits"})
            QVERIFY2(mode->find(QString::fromLatin1(option)), option);
    }
    const auto read = [](const QStringList &arguments, QString *error) {
        QCommandLineParser parser;
        describeTo(parser, slewWindowMode());
        if (!parser.parse(QStringList{"slew"} + arguments)) {
            *error = parser.errorText();
            return std::optional<StationClockOptions>();
        }
        return readStationClockOptions(parser, commandLineLabel, error);
    };
    QString error;
    auto clock = read({"--clock-start", "2026-11-25T12:00:00Z", "--clock-rate", "5"}, &error);
    QVERIFY2(clock, qPrintable(error));
    QVERIFY(clock->startJulian);
    QCOMPARE(*clock->startJulian, *slew::sky::julianFromIso("2026-11-25T12:00:00Z"));
    QCOMPARE(clock->rate, 5.0);
    clock = read({}, &error);
    QVERIFY2(clock, qPrintable(error));
    QVERIFY(!clock->startJulian);
    QCOMPARE(clock->rate, 1.0);

    QVERIFY(!read({"--clock-rate", "5"}, &error));
    QCOMPARE(error, QString("--clock-rate: needs --clock-start"));
    QVERIFY(!read({"--clock-start", "2026-11-25T12:00:00Z", "--clock-rate", "nan"}, &error));
    QVERIFY2(error.startsWith("--clock-rate: ") && error.endsWith(" (1 to 20)"), qPrintable(error));
    QVERIFY(!read({"--clock-start", "2026-11-25T12:00:00Z", "--clock-rate", "21"}, &error));
    QVERIFY2(error.startsWith("--clock-rate: ") && error.endsWith(" (1 to 20)"), qPrintable(error));
    QVERIFY(!read({"--clock-start", "yesterday"}, &error));
    QCOMPARE(error, QString("--clock-start yesterday: expected an ISO 8601 time, as 2024-06-20T12:00:00Z"));
}

void CommandLineTest::windowStartsInRehearsal()
{
    QTemporaryDir home;
    // A rate alone is refused, in the station service's words, before any window.
    const SlewRun rateAlone = runSlew({"--clock-rate", "5"}, home.path());
    QCOMPARE(rateAlone.exitCode, 2);
    QVERIFY2(rateAlone.standardError.contains("slew: --clock-rate: needs --clock-start"),
             qPrintable(rateAlone.standardError));
    const SlewRun badTravel = runSlew({"--limits", "0:500,0:90"}, home.path());
    QCOMPARE(badTravel.exitCode, 2);
    QVERIFY2(badTravel.standardError.contains("slew: --limits 0:500,0:90: "), qPrintable(badTravel.standardError));

    // With a start the window opens in rehearsal (here drawn to a file, with no display).
    const QString picture = QDir(home.path()).filePath("rehearsal.png");
    const SlewRun rehearsal = runSlew({"--connect", "sim:", "--clock-start", "2026-11-25T12:00:00Z", "--clock-rate", "5",
                                       "--limits", "0:450,0:180", "--screenshot", picture, "--settle-ms", "0"},
                                      home.path());
    QVERIFY2(rehearsal.exitCode == 0, qPrintable(rehearsal.standardError));
    QVERIFY(QFile::exists(picture));
}

void CommandLineTest::manualEscapesRoff()
{
    ProgramDescription p;
    p.name = QStringLiteral("x");
    p.summary = QStringLiteral("a \\ backslash");
    p.description = QStringLiteral(".starts with a dot\n'and a quote");
    p.modes = {ProgramMode{QStringLiteral("Options"), QStringLiteral("x"), QString(),
                           {ProgramOption{{QStringLiteral("a-b")}, QString(), QStringLiteral("text"), false}}}};
    const QString page = renderManPage(p, QStringLiteral("1"));
    QVERIFY(page.contains(u"x \\- a \\e backslash"));
    QVERIFY(page.contains(u"\n\\&.starts with a dot\n\\&'and a quote"));
    QVERIFY(page.contains(u"\\fB\\-\\-a\\-b\\fR"));
}

QTEST_GUILESS_MAIN(CommandLineTest)
#include "tst_commandline.moc"
