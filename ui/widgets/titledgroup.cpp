// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/titledgroup.h"

#include <QGroupBox>
#include <QVBoxLayout>

namespace slew::ui {

QGroupBox *titledGroup(const QString &title, QWidget *content)
{
    auto *box = new QGroupBox(title);
    auto *l = new QVBoxLayout(box);
    l->setContentsMargins(6, 2, 6, 4);
    l->addWidget(content);
    return box;
}

} // namespace slew::ui
