// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A file to open or to save, chosen in a dialog that blocks nothing: the
// static QFileDialog::get…FileName run their own event loop and are modal,
// so while one was up the window's Stop could not be clicked. This one is
// shown without modality and calls back with the file once one is chosen.

#include <QString>

#include <functional>

class QWidget;

namespace slew::ui {

enum class FileChoice { Open, Save };

void chooseFile(QWidget *parent, FileChoice choice, const QString &title, const QString &suggestedName,
                const QString &filter, std::function<void(const QString &path)> chosen);

} // namespace slew::ui
