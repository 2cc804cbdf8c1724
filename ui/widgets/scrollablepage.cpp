// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/scrollablepage.h"

#include <QEvent>
#include <QLayout>

#include <algorithm>

namespace slew::ui {

ScrollablePage::ScrollablePage(QWidget *page, QWidget *parent) : QScrollArea(parent)
{
    setObjectName(page->objectName() + QStringLiteral("Scroll"));
    setFrameShape(QFrame::NoFrame);
    setWidgetResizable(false); // fit() sizes the page
    setWidget(page);
    page->installEventFilter(this); // its least size changes with its content
    fit();
}

bool ScrollablePage::viewportEvent(QEvent *event)
{
    if (event->type() == QEvent::Resize)
        fit();
    return QScrollArea::viewportEvent(event);
}

bool ScrollablePage::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == widget() && event->type() == QEvent::LayoutRequest)
        fit();
    return QScrollArea::eventFilter(watched, event);
}

void ScrollablePage::fit()
{
    QWidget *page = widget();
    if (!page)
        return;
    const QSize least = page->minimumSizeHint().expandedTo(page->minimumSize());
    QSize size = viewport()->size().expandedTo(least);
    // A page of wrapping labels needs more height when narrower.
    if (const QLayout *layout = page->layout(); layout && layout->hasHeightForWidth())
        size.setHeight(std::max(size.height(), layout->totalMinimumHeightForWidth(size.width())));
    if (page->size() != size)
        page->resize(size);
}

int ScrollablePage::pageLeastWidth() const
{
    const QWidget *page = widget();
    return page ? page->minimumSizeHint().expandedTo(page->minimumSize()).width() : 0;
}

ScrollablePage *scrollablePage(QWidget *page)
{
    return new ScrollablePage(page);
}

} // namespace slew::ui
