#pragma once
// What every face of the slew program (window, --headless, --tune) sets up
// first: its name and version for QSettings and --version, and the link
// kinds that live outside core/transport (sim:, rotctld://).

#include "linkschemes.h"
#include "model/settingsfile.h"
#include "sky/satellitenames.h"

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

// Every face that finds satellites by name runs this at start: what was
// wrong in the operator's own satellite names (sky/satellitenames.h) is
// said on stderr, and returned for the window to show as well; the good
// lines are used.
inline QStringList checkSatelliteNames()
{
    const QStringList &problems = slew::sky::satelliteNameProblems();
    for (const QString &problem : problems)
        std::fprintf(stderr, "slew: %s\n", qPrintable(problem));
    return problems;
}
