#pragma once
// What every face of the slew program (window, --headless, --tune) sets up
// first: its name and version for QSettings and --version, and the link
// kinds that live outside core/transport (sim:, rotctld://).

#include "linkschemes.h"
#include "model/settingsfile.h"

#include <QCoreApplication>

#include <cstdio>

inline void setUpSlewApplication()
{
    QCoreApplication::setOrganizationName(QStringLiteral("Slew"));
    QCoreApplication::setApplicationName(QStringLiteral("slew"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SLEW_VERSION));
    slew::registerLinkSchemes();
}

// Every face that uses QSettings runs this before it reads them: a settings
// file that cannot be read is moved aside (model/settingsfile.h) and stderr
// says so. The line is returned for the window to show as well.
inline QString checkSettingsFile()
{
    const QString message = slew::model::setAsideUnreadableSettings().message;
    if (!message.isEmpty())
        std::fprintf(stderr, "slew: %s\n", qPrintable(message));
    return message;
}
