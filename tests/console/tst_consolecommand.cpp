// SPDX-License-Identifier: GPL-3.0-or-later
// slewctl's command words, parsed and refused: a table.

#include "console/consolecommand.h"

#include <QTest>

using slew::console::ConsoleCommand;
using Kind = ConsoleCommand::Kind;

class ConsoleCommandTest : public QObject {
    Q_OBJECT
private slots:
    void accepts_data();
    void accepts();
    void refuses_data();
    void refuses();
    void splitsPromptLines();
};

void ConsoleCommandTest::accepts_data()
{
    QTest::addColumn<QStringList>("words");
    QTest::addColumn<int>("kind");
    QTest::addColumn<double>("az");
    QTest::addColumn<double>("el");
    QTest::addColumn<bool>("wait");
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("reg");
    QTest::addColumn<double>("interval");
    QTest::newRow("get") << QStringList{"get"} << int(Kind::Get) << 0.0 << 0.0 << false << "" << 0 << 1.0;
    QTest::newRow("GET") << QStringList{"GET"} << int(Kind::Get) << 0.0 << 0.0 << false << "" << 0 << 1.0;
    QTest::newRow("goto") << QStringList{"goto", "180", "30.5"} << int(Kind::Goto) << 180.0 << 30.5 << false << "" << 0 << 1.0;
    QTest::newRow("goto negative") << QStringList{"goto", "-5", "-1"} << int(Kind::Goto) << -5.0 << -1.0 << false << "" << 0 << 1.0;
    QTest::newRow("goto wait") << QStringList{"goto", "10", "20", "--wait"} << int(Kind::Goto) << 10.0 << 20.0 << true << "" << 0 << 1.0;
    QTest::newRow("wait first") << QStringList{"goto", "--wait", "10", "20"} << int(Kind::Goto) << 10.0 << 20.0 << true << "" << 0 << 1.0;
    QTest::newRow("stop") << QStringList{"stop"} << int(Kind::Stop) << 0.0 << 0.0 << false << "" << 0 << 1.0;
    QTest::newRow("park wait") << QStringList{"park", "--wait"} << int(Kind::Park) << 0.0 << 0.0 << true << "" << 0 << 1.0;
    QTest::newRow("home") << QStringList{"home"} << int(Kind::Home) << 0.0 << 0.0 << false << "" << 0 << 1.0;
    QTest::newRow("watch") << QStringList{"watch"} << int(Kind::Watch) << 0.0 << 0.0 << false << "" << 0 << 1.0;
    QTest::newRow("watch interval") << QStringList{"watch", "--interval", "0.5"} << int(Kind::Watch) << 0.0 << 0.0 << false << "" << 0 << 0.5;
    QTest::newRow("watch interval=") << QStringList{"watch", "--interval=2"} << int(Kind::Watch) << 0.0 << 0.0 << false << "" << 0 << 2.0;
    QTest::newRow("watch bare") << QStringList{"watch", "0.25"} << int(Kind::Watch) << 0.0 << 0.0 << false << "" << 0 << 0.25;
    QTest::newRow("raw") << QStringList{"raw", "AZ EL"} << int(Kind::Raw) << 0.0 << 0.0 << false << "AZ EL" << 0 << 1.0;
    QTest::newRow("raw words") << QStringList{"raw", "AZ", "EL"} << int(Kind::Raw) << 0.0 << 0.0 << false << "AZ EL" << 0 << 1.0;
    QTest::newRow("config get") << QStringList{"config", "get", "1"} << int(Kind::ConfigGet) << 0.0 << 0.0 << false << "" << 1 << 1.0;
    QTest::newRow("config get CR") << QStringList{"config", "get", "CR13"} << int(Kind::ConfigGet) << 0.0 << 0.0 << false << "" << 13 << 1.0;
    QTest::newRow("config set") << QStringList{"config", "set", "cw4", "0.8"} << int(Kind::ConfigSet) << 0.0 << 0.0 << false << "0.8" << 4 << 1.0;
    QTest::newRow("quit") << QStringList{"quit"} << int(Kind::Quit) << 0.0 << 0.0 << false << "" << 0 << 1.0;
    QTest::newRow("exit") << QStringList{"exit"} << int(Kind::Quit) << 0.0 << 0.0 << false << "" << 0 << 1.0;
}

void ConsoleCommandTest::accepts()
{
    QFETCH(QStringList, words);
    QString error;
    const auto c = slew::console::parseConsoleCommand(words, &error);
    QVERIFY2(c, qPrintable(error));
    QTEST(int(c->kind), "kind");
    QTEST(c->azimuth, "az");
    QTEST(c->elevation, "el");
    QTEST(c->wait, "wait");
    QTEST(c->text, "text");
    QTEST(c->reg, "reg");
    QTEST(c->intervalSeconds, "interval");
}

void ConsoleCommandTest::refuses_data()
{
    QTest::addColumn<QStringList>("words");
    QTest::addColumn<QString>("message");
    QTest::newRow("nothing") << QStringList{} << "no command";
    QTest::newRow("unknown") << QStringList{"fly"} << "unknown command 'fly'";
    QTest::newRow("goto one number") << QStringList{"goto", "10"} << "usage: goto AZ EL";
    QTest::newRow("goto words") << QStringList{"goto", "north", "up"} << "not two numbers";
    QTest::newRow("goto nan") << QStringList{"goto", "nan", "10"} << "not two numbers";
    QTest::newRow("goto inf") << QStringList{"goto", "10", "inf"} << "not two numbers";
    QTest::newRow("get extra") << QStringList{"get", "now"} << "usage: get";
    QTest::newRow("stop wait") << QStringList{"stop", "--wait"} << "--wait goes with goto";
    QTest::newRow("watch zero") << QStringList{"watch", "--interval", "0"} << "0.05 to 3600";
    QTest::newRow("watch word") << QStringList{"watch", "--interval", "soon"} << "not 'soon'";
    QTest::newRow("raw empty") << QStringList{"raw"} << "usage: raw";
    QTest::newRow("config nothing") << QStringList{"config"} << "usage: config get REG";
    QTest::newRow("config register 0") << QStringList{"config", "get", "0"} << "register must be 1 to 13";
    QTest::newRow("config register 14") << QStringList{"config", "set", "14", "1"} << "register must be 1 to 13";
    QTest::newRow("config set no value") << QStringList{"config", "set", "1"} << "usage: config set REG VALUE";
}

void ConsoleCommandTest::refuses()
{
    QFETCH(QStringList, words);
    QFETCH(QString, message);
    QString error;
    QVERIFY(!slew::console::parseConsoleCommand(words, &error));
    QVERIFY2(error.contains(message), qPrintable(error));
}

void ConsoleCommandTest::splitsPromptLines()
{
    using slew::console::splitConsoleLine;
    QCOMPARE(splitConsoleLine("  goto 10   20 "), (QStringList{"goto", "10", "20"}));
    QCOMPARE(splitConsoleLine("raw 'AZ EL'"), (QStringList{"raw", "AZ EL"}));
    QCOMPARE(splitConsoleLine("raw \"AZ10.0 EL5.0\""), (QStringList{"raw", "AZ10.0 EL5.0"}));
    QCOMPARE(splitConsoleLine("raw ''"), (QStringList{"raw", ""}));
    QCOMPARE(splitConsoleLine(""), QStringList{});
}

QTEST_GUILESS_MAIN(ConsoleCommandTest)
#include "tst_consolecommand.moc"
