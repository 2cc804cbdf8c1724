// SPDX-License-Identifier: GPL-3.0-or-later
#include "programoption.h"

namespace slew::cli {

QCommandLineOption ProgramOption::toQt() const
{
    return valueName.isEmpty() ? QCommandLineOption(names, description)
                               : QCommandLineOption(names, description, valueName);
}

const ProgramOption *ProgramMode::find(QStringView longName) const
{
    for (const ProgramOption &option : options) {
        if (option.longName() == longName)
            return &option;
    }
    return nullptr;
}

} // namespace slew::cli
