// SPDX-License-Identifier: GPL-3.0-or-later
#include "windowstate.h"

#include <QEvent>
#include <QMainWindow>
#include <QSettings>
#include <QSplitter>
#include <QTabWidget>

namespace slew::ui {

namespace {

constexpr char kGeometryKey[] = "window/geometry";
constexpr char kSplitterKey[] = "window/splitter";
constexpr char kTabKey[] = "window/tab";

// The control column's width on a first start: the jog pad and the go-to
// fields at ease, the rest shared between the plot and the tabs.
constexpr int kControlColumnWidth = 320;

} // namespace

QSize WindowState::openingSize(QSize available)
{
    return QSize(1440, 900).boundedTo(available);
}

QRect WindowState::onScreen(QRect kept, QRect available)
{
    if (available.isEmpty())
        return kept;
    kept.setSize(kept.size().boundedTo(available.size()));
    if (kept.right() > available.right())
        kept.moveRight(available.right());
    if (kept.bottom() > available.bottom())
        kept.moveBottom(available.bottom());
    if (kept.left() < available.left())
        kept.moveLeft(available.left());
    if (kept.top() < available.top())
        kept.moveTop(available.top());
    return kept;
}

WindowState::WindowState(QMainWindow *window, QSplitter *splitter, QTabWidget *tabs, QRect available)
    : QObject(window), m_window(window), m_splitter(splitter), m_tabs(tabs)
{
    const QSettings settings;
    // restoreGeometry only brings back a window that would be wholly off
    // the screen; one that stands partly out is moved in here.
    if (window->restoreGeometry(settings.value(QLatin1String(kGeometryKey)).toByteArray())) {
        if (const QRect kept = onScreen(window->geometry(), available); kept != window->geometry())
            window->setGeometry(kept);
    } else {
        window->resize(openingSize(available.size()));
    }
    if (!splitter->restoreState(settings.value(QLatin1String(kSplitterKey)).toByteArray())) {
        // The plot square where it can be, the tabs taking the rest.
        const int width = window->width();
        const int rest = std::max(0, width - kControlColumnWidth);
        splitter->setSizes({rest * 5 / 11, kControlColumnWidth, rest * 6 / 11});
    }
    bool ok = false;
    const int tab = settings.value(QLatin1String(kTabKey)).toInt(&ok);
    if (ok && tab >= 0 && tab < tabs->count())
        tabs->setCurrentIndex(tab);
    m_restoring = false;

    connect(splitter, &QSplitter::splitterMoved, this, &WindowState::keep);
    connect(tabs, &QTabWidget::currentChanged, this, &WindowState::keep);
    // Size and place change through the window's own events.
    window->installEventFilter(this);
}

bool WindowState::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_window && (event->type() == QEvent::Resize || event->type() == QEvent::Move)
        && m_window->isVisible())
        keep();
    return QObject::eventFilter(watched, event);
}

void WindowState::keep()
{
    if (m_restoring)
        return;
    QSettings settings;
    settings.setValue(QLatin1String(kGeometryKey), m_window->saveGeometry());
    settings.setValue(QLatin1String(kSplitterKey), m_splitter->saveState());
    settings.setValue(QLatin1String(kTabKey), m_tabs->currentIndex());
}

} // namespace slew::ui
