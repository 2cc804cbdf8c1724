// SPDX-License-Identifier: GPL-3.0-or-later
#include "wizard/pagebody.h"

#include <QScrollArea>
#include <QVBoxLayout>
#include <QWizardPage>

namespace slew::ui {

QWidget *makePageBody(QWizardPage *page)
{
    auto *scroll = new QScrollArea(page);
    scroll->setObjectName(QStringLiteral("pageScroll"));
    scroll->setFrameShape(QFrame::NoFrame);
    // The body takes the viewport's size while it is big enough, and keeps
    // its layout's minimum (scrolling) when it is not.
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    auto *body = new QWidget;
    body->setObjectName(QStringLiteral("pageBody"));
    scroll->setWidget(body);
    auto *outer = new QVBoxLayout(page);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->addWidget(scroll);
    return body;
}

} // namespace slew::ui
