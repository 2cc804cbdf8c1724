// SPDX-License-Identifier: GPL-3.0-or-later
// slewctl URI [COMMAND]: one command to a rotator, or a prompt. Argument
// parsing and wiring only; the commands are carried out by core/console and
// the options are described in cli/.

#include "cli/optionnames.h"
#include "cli/slewcommandline.h"
#include "console/consolecommand.h"
#include "console/consolerunner.h"
#include "console/radiocommand.h"
#include "console/radiorunner.h"
#include "radio/radiolinks.h"
#include "linkschemes.h"
#include "model/rotatorprofile.h"
#include "protocol/dialect.h"
#include "session/connectionplan.h"
#include "session/rotatorsession.h"
#include "transport/linkfactory.h"
#include "cli/terminationsignalwatcher.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QSocketNotifier>

#include <cstdio>
#include <unistd.h>

using slew::console::ConsoleCommand;
using slew::console::ConsoleRunner;
using slew::console::ExitCode;

namespace opt = slew::cli::opt;

namespace {

int badArgument(const QString &message)
{
    std::fprintf(stderr, "slewctl: %s\n", qPrintable(message));
    return int(ExitCode::BadArgument);
}

void say(std::FILE *to, const QString &line)
{
    std::fprintf(to, "%s\n", qPrintable(line));
    std::fflush(to);
}

// Opens the link; a URI that names no link Slew knows, or one that cannot be
// made at all, is refused at once with the window's words, not after the
// connect timeout as "no answer". Empty when the link is on its way.
QString connectOrSayWhy(slew::session::RotatorSession &session, const QString &uri)
{
    QString why;
    const auto watch = QObject::connect(&session, &slew::session::RotatorSession::stateChanged, &session,
                                        [&why](slew::session::RotatorSession::State state, const QString &detail) {
                                            if (state == slew::session::RotatorSession::State::Disconnected)
                                                why = detail;
                                        });
    session.connectTo(uri);
    QObject::disconnect(watch);
    if (session.state() != slew::session::RotatorSession::State::Disconnected)
        return {};
    return why.isEmpty() ? QStringLiteral("cannot open %1").arg(uri) : why;
}

// Lines from standard input, read as they come, never blocking the loop.
class InputLines : public QObject {
    Q_OBJECT
public:
    explicit InputLines(QObject *parent = nullptr)
        : QObject(parent), m_notifier(STDIN_FILENO, QSocketNotifier::Read)
    {
        connect(&m_notifier, &QSocketNotifier::activated, this, &InputLines::readSome);
    }

signals:
    void line(const QString &text);
    void ended();

private:
    void readSome()
    {
        char chunk[4096];
        const ssize_t n = ::read(STDIN_FILENO, chunk, sizeof chunk);
        if (n <= 0) {
            m_notifier.setEnabled(false);
            if (!m_buffer.isEmpty())
                emit line(QString::fromUtf8(std::exchange(m_buffer, {})));
            emit ended();
            return;
        }
        m_buffer.append(chunk, n);
        for (qsizetype end; (end = m_buffer.indexOf('\n')) >= 0;) {
            const QByteArray text = m_buffer.left(end);
            m_buffer.remove(0, end + 1);
            emit line(QString::fromUtf8(text));
        }
        if (m_buffer.size() > kLongestLine) // not a command: drop it whole
            m_buffer.clear();
    }

    static constexpr qsizetype kLongestLine = 4096;
    QSocketNotifier m_notifier;
    QByteArray m_buffer;
};

// `slewctl --radio URI [COMMAND]`: one command to a radio, then what it holds.
int runRadio(QCoreApplication &app, const QString &uri, const QStringList &words, bool json)
{
    QString error;
    const std::optional<slew::console::RadioCommand> command = slew::console::parseRadioCommand(words, &error);
    if (!command)
        return badArgument(error);
    std::unique_ptr<slew::radio::RadioLink> link = slew::radio::makeRadioLink(uri, &error);
    if (!link)
        return badArgument(error);
    slew::console::RadioRunner runner(link.get(), json);
    QObject::connect(&runner, &slew::console::RadioRunner::output, &app, [](const QString &l) { say(stdout, l); });
    QObject::connect(&runner, &slew::console::RadioRunner::problem, &app,
                     [json](const QString &l) { say(stderr, json ? l : QStringLiteral("slewctl: ") + l); });
    int exitCode = 0;
    QObject::connect(&runner, &slew::console::RadioRunner::finished, &app, [&](ExitCode code) {
        exitCode = int(code);
        app.quit();
    });
    slew::cli::TerminationSignalWatcher interrupts;
    QObject::connect(&interrupts, &slew::cli::TerminationSignalWatcher::terminationRequested, &app, [&] {
        exitCode = int(ExitCode::Failed);
        app.quit();
    });
    runner.run(*command);
    app.exec();
    return exitCode;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("slewctl"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SLEW_VERSION));
    slew::registerLinkSchemes();

    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewctlProgram(), slew::cli::slewctlMode());
    parser.addPositionalArgument(QStringLiteral("URI"), QStringLiteral("The rotator's link, e.g. sim: or serial:/dev/ttyUSB0"));
    parser.addPositionalArgument(QStringLiteral("command"), slew::console::consoleCommandSummary(), QStringLiteral("[COMMAND]"));
    // `goto 10 -5`: after the URI, everything belongs to the command.
    parser.setOptionsAfterPositionalArgumentsMode(QCommandLineParser::ParseAsPositionalArguments);
    if (!parser.parse(app.arguments()))
        return badArgument(parser.errorText());
    if (parser.isSet(opt::help))
        parser.showHelp(0);
    if (parser.isSet(opt::version))
        parser.showVersion();

    const QStringList positional = parser.positionalArguments();
    if (parser.isSet(opt::radio))
        return runRadio(app, parser.value(opt::radio), positional, parser.isSet(opt::json));
    if (positional.isEmpty())
        return badArgument(QStringLiteral("which rotator? e.g. slewctl sim: get"));
    slew::model::RotatorProfile profile;
    if (parser.isSet(opt::profile)) {
        QString error;
        const auto loaded = slew::model::RotatorProfile::load(parser.value(opt::profile), &error);
        if (!loaded)
            return badArgument(error);
        profile = *loaded;
    }
    if (parser.isSet(opt::dialect)) {
        const auto dialect = slew::protocol::dialectFromName(parser.value(opt::dialect));
        if (!dialect)
            return badArgument(QStringLiteral("unknown dialect '%1'").arg(parser.value(opt::dialect)));
        profile.dialect = *dialect;
    }
    profile.uri = positional.first();
    // What the URI names (`dialect=`, `firmware=`, a simulator's own, a
    // rotctld:// peer) where --dialect and --profile do not say otherwise.
    profile = slew::session::commandLineConnectionProfile(
        profile, parser.isSet(opt::dialect) || parser.isSet(opt::profile));
    int timeoutSeconds = 600;
    if (parser.isSet(opt::timeout)) {
        bool ok = false;
        timeoutSeconds = parser.value(opt::timeout).toInt(&ok);
        if (!ok || timeoutSeconds < 1 || timeoutSeconds > 86400)
            return badArgument(QStringLiteral("--timeout wants 1 to 86400 seconds"));
    }

    // One command from the command line, checked before anything connects.
    const QStringList words = positional.mid(1);
    std::optional<ConsoleCommand> once;
    if (!words.isEmpty()) {
        QString error;
        once = slew::console::parseConsoleCommand(words, &error);
        if (!once)
            return badArgument(error);
        if (once->kind == ConsoleCommand::Kind::Help) {
            std::fputs(qPrintable(slew::console::consoleCommandSummary()), stdout);
            return 0;
        }
    }

    slew::session::RotatorSession session;
    session.setProfile(profile);
    ConsoleRunner runner(&session, parser.isSet(opt::json));
    runner.setArrivalTimeout(timeoutSeconds * 1000);
    QObject::connect(&runner, &ConsoleRunner::output, &app, [](const QString &l) { say(stdout, l); });
    const bool json = parser.isSet(opt::json);
    QObject::connect(&runner, &ConsoleRunner::problem, &app,
                     [json](const QString &l) { say(stderr, json ? l : QStringLiteral("slewctl: ") + l); });

    int exitCode = 0;
    slew::cli::TerminationSignalWatcher interrupts;
    if (once) {
        QObject::connect(&runner, &ConsoleRunner::finished, &app, [&](ExitCode code) {
            exitCode = int(code);
            app.quit();
        });
        QObject::connect(&interrupts, &slew::cli::TerminationSignalWatcher::terminationRequested, &runner,
                         &ConsoleRunner::interrupt);
        if (const QString why = connectOrSayWhy(session, profile.uri); !why.isEmpty()) {
            say(stderr, json ? why : QStringLiteral("slewctl: ") + why);
            return int(ExitCode::LinkFailure);
        }
        runner.run(*once);
        app.exec();
        return exitCode;
    }

    // The prompt: commands one at a time; lines typed meanwhile wait.
    const bool terminal = ::isatty(STDIN_FILENO);
    InputLines input;
    QStringList waiting;
    bool inputEnded = false;
    auto prompt = [&] {
        if (terminal) {
            std::fputs("slewctl> ", stdout);
            std::fflush(stdout);
        }
    };
    std::function<void()> next = [&] {
        while (!runner.isRunning() && !waiting.isEmpty()) {
            const QStringList commandWords = slew::console::splitConsoleLine(waiting.takeFirst());
            if (commandWords.isEmpty()) {
                prompt();
                continue;
            }
            QString error;
            const auto command = slew::console::parseConsoleCommand(commandWords, &error);
            if (!command) {
                say(stderr, QStringLiteral("slewctl: ") + error);
                if (exitCode == 0)
                    exitCode = int(ExitCode::BadArgument);
                prompt();
            } else if (command->kind == ConsoleCommand::Kind::Quit) {
                app.quit();
                return;
            } else if (command->kind == ConsoleCommand::Kind::Help) {
                std::fputs(qPrintable(slew::console::consoleCommandSummary()), stdout);
                prompt();
            } else {
                runner.run(*command);
            }
        }
        if (inputEnded && waiting.isEmpty() && !runner.isRunning())
            app.quit();
    };
    // A script fed to the prompt fails with its first failure's code.
    QObject::connect(&runner, &ConsoleRunner::finished, &app, [&](ExitCode code) {
        if (exitCode == 0)
            exitCode = int(code);
        prompt();
        QMetaObject::invokeMethod(&app, next, Qt::QueuedConnection);
    });
    QObject::connect(&input, &InputLines::line, &app, [&](const QString &text) {
        waiting << text;
        next();
    });
    QObject::connect(&input, &InputLines::ended, &app, [&] {
        inputEnded = true;
        next();
    });
    // Ctrl-C ends what runs; at an idle prompt it leaves.
    QObject::connect(&interrupts, &slew::cli::TerminationSignalWatcher::terminationRequested, &app, [&] {
        if (runner.isRunning())
            runner.interrupt();
        else
            app.quit();
    });
    if (const QString why = connectOrSayWhy(session, profile.uri); !why.isEmpty()) {
        say(stderr, QStringLiteral("slewctl: ") + why);
        return int(ExitCode::LinkFailure);
    }
    prompt();
    app.exec();
    return exitCode;
}

#include "slewctl_main.moc"
