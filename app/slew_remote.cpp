// SPDX-License-Identifier: GPL-3.0-or-later
#include "slew_remote.h"

#include "slew_identity.h"
#include "cli/sharedoptions.h"
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
#include <cstring>

namespace {

int fail(const QString &message)
{
    std::fprintf(stderr, "slew: %s\n", qPrintable(message));
    return 2;
}

} // namespace

bool wantsRemote(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--remote") == 0 || std::strncmp(argv[i], "--remote=", 9) == 0)
            return true;
    }
    return false;
}

int runRemote(int argc, char **argv)
{
    // A screenshot, --help and --version need no display.
    for (int i = 1; i < argc; ++i) {
        const bool noDisplay = std::strncmp(argv[i], "--screenshot", 12) == 0 || std::strcmp(argv[i], "--help") == 0
                               || std::strcmp(argv[i], "--version") == 0;
        if (noDisplay && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    QApplication app(argc, argv);
    setUpSlewApplication();
    slew::ui::applyOperatorTheme(app);
    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewRemoteMode());
    parser.process(app.arguments());

    QString error;
    const auto address = slew::remote::parseBrokerAddress(parser.value(QStringLiteral("remote")), &error);
    if (!address)
        return fail(QStringLiteral("--remote: %1").arg(error));
    const auto password = slew::remote::brokerPassword(parser.value(QStringLiteral("mqtt-password-file")), &error);
    if (!password)
        return fail(QStringLiteral("--mqtt-password-file: %1").arg(error));
    int settleMs = 3000;
    if (parser.isSet(QStringLiteral("settle-ms"))) {
        bool ok = false;
        settleMs = parser.value(QStringLiteral("settle-ms")).toInt(&ok);
        if (!ok || settleMs < 0 || settleMs > 3600000)
            return fail(QStringLiteral("--settle-ms wants a number of milliseconds up to an hour"));
    }
    checkSettingsFile();
    QMainWindow *window = slew::ui::openRemoteWindow(*address, *password, &error);
    if (!window)
        return fail(QStringLiteral("--remote: %1").arg(error));
    if (parser.isSet(QStringLiteral("screenshot")))
        slew::ui::scheduleWindowSnapshot(window, parser.value(QStringLiteral("screenshot")), settleMs);
    return app.exec();
}
