// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A titled box around one widget, with the tight margins the operator
// window's control column needs to fit a 720-pixel screen; the remote
// window's column uses the same.

#include <QGroupBox>
#include <QString>

namespace slew::ui {

QGroupBox *titledGroup(const QString &title, QWidget *content);

} // namespace slew::ui
