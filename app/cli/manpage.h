// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A program description (programoption.h) written as a manual page in roff,
// the format man(1) reads.

#include "programoption.h"

namespace slew::cli {

QString renderManPage(const ProgramDescription &program, const QString &version);

} // namespace slew::cli
