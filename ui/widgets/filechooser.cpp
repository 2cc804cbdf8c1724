// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/filechooser.h"

#include <QFileDialog>

namespace slew::ui {

void chooseFile(QWidget *parent, FileChoice choice, const QString &title, const QString &suggestedName,
                const QString &filter, std::function<void(const QString &path)> chosen)
{
    auto *dialog = new QFileDialog(parent, title, QString(), filter);
    dialog->setObjectName(QStringLiteral("fileChooser"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowModality(Qt::NonModal);
    if (choice == FileChoice::Save) {
        dialog->setAcceptMode(QFileDialog::AcceptSave);
        dialog->setFileMode(QFileDialog::AnyFile);
        dialog->selectFile(suggestedName);
    } else {
        dialog->setAcceptMode(QFileDialog::AcceptOpen);
        dialog->setFileMode(QFileDialog::ExistingFile);
    }
    QObject::connect(dialog, &QFileDialog::fileSelected, dialog,
                     [chosen = std::move(chosen)](const QString &path) {
                         if (!path.isEmpty())
                             chosen(path);
                     });
    dialog->show();
}

} // namespace slew::ui
