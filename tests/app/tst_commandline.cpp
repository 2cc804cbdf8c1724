// SPDX-License-Identifier: GPL-3.0-or-later
// The command lines described once (app/cli): the config file reader, the
// precedence of the command line over the file, and the manual page made
// from the same descriptions as --help.

#include "cli/configfile.h"
#include "cli/manpage.h"
#include "cli/slewcommandline.h"

#include <QCommandLineParser>
#include <QTemporaryDir>
#include <QTest>

using namespace slew::cli;

class CommandLineTest : public QObject {
    Q_OBJECT
private slots:
    void configFileBecomesOptions();
    void configFileRefusesWhatItCannotMean_data();
    void configFileRefusesWhatItCannotMean();
    void commandLineWinsOverTheFile();
    void missingOrHugeFileIsRefused();
    void manualListsEveryOptionOfEveryMode();
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
    QCOMPARE(*args, (QStringList{"--connect=tcp://192.0.2.10:4533", "--dialect=gs232b",
                                 "--rotctld-listen=127.0.0.1:4533 # not a comment: part of it"}));
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
    QVERIFY2(parser.parse(*args), qPrintable(parser.errorText()));
    QCOMPARE(parser.value("connect"), QString("tcp://192.0.2.1:1"));
    QCOMPARE(parser.value("rotctld-listen"), QString("127.0.0.1:4533"));

    // Without --config the arguments are untouched.
    const QStringList plain{"slew", "--headless", "--connect", "sim:"};
    QCOMPARE(*withConfigFile(plain, slewHeadlessMode(), &error), plain);
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
    QVERIFY2(error.contains("too big"), qPrintable(error));
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
