#pragma once
// What every face of the slew program (window, --headless, --tune) sets up
// first: its name and version for QSettings and --version, and the link
// kinds that live outside core/transport (sim:, rotctld://).

#include "linkschemes.h"

#include <QCoreApplication>

inline void setUpSlewApplication()
{
    QCoreApplication::setOrganizationName(QStringLiteral("Slew"));
    QCoreApplication::setApplicationName(QStringLiteral("slew"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SLEW_VERSION));
    slew::registerLinkSchemes();
}
