// SPDX-License-Identifier: GPL-3.0-or-later
#include "slew_remote.h"

#include "slew_identity.h"
#include "cli/sharedoptions.h"
#include "cli/argvoptions.h"
#include "cli/optionnames.h"
#include "cli/slewcommandline.h"
#include "operatortheme.h"
#include "remote/remoteopener.h"
#include "windowsnapshot.h"

#include "remote/brokeraddress.h"
#include "remote/brokerpassword.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QMainWindow>

#include <cstdio>

namespace opt = slew::cli::opt;

namespace {

int fail(const QString &message)
{
    std::fprintf(stderr, "slew: %s\n", qPrintable(message));
    return 2;
}

} // namespace

bool wantsRemote(int argc, char **argv)
{
    return slew::cli::argvHasOption(argc, argv, opt::remote);
}

int runRemote(int argc, char **argv)
{
    // A screenshot, --help and --version need no display.
    const bool noDisplay = slew::cli::argvHasOption(argc, argv, opt::screenshot)
                           || slew::cli::argvHasSwitch(argc, argv, opt::help)
                           || slew::cli::argvHasSwitch(argc, argv, opt::version);
    if (noDisplay && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    setUpSlewApplication();
    slew::ui::applyOperatorTheme(app);
    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewRemoteMode());
    parser.process(app.arguments());

    QString error;
    const auto address = slew::remote::parseBrokerAddress(parser.value(opt::remote), &error);
    if (!address)
        return fail(QStringLiteral("--remote: %1").arg(error));
    const auto password = slew::remote::brokerPassword(parser.value(opt::mqttPasswordFile), &error);
    if (!password)
        return fail(QStringLiteral("--mqtt-password-file: %1").arg(error));
    int settleMs = 3000;
    if (parser.isSet(opt::settleMs)) {
        bool ok = false;
        settleMs = parser.value(opt::settleMs).toInt(&ok);
        if (!ok || settleMs < 0 || settleMs > 3600000)
            return fail(QStringLiteral("--settle-ms wants a number of milliseconds up to an hour"));
    }
    checkSettingsFile();
    QMainWindow *window = slew::ui::openRemoteWindow(*address, *password, &error);
    if (!window)
        return fail(QStringLiteral("--remote: %1").arg(error));
    if (parser.isSet(opt::screenshot))
        slew::ui::scheduleWindowSnapshot(window, parser.value(opt::screenshot), settleMs);
    return app.exec();
}
