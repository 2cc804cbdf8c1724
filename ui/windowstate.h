// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How the operator left the window: its size and place, how the splitter
// divides it, which tab is in front. Kept in the settings as the presets are,
// written as soon as the operator changes one, so a crash keeps it too, and
// put back at the next start.

#include <QObject>
#include <QRect>
#include <QSize>

class QMainWindow;
class QSplitter;
class QTabWidget;

namespace slew::ui {

class WindowState : public QObject {
    Q_OBJECT
public:
    // Restores what was kept, or lays the window out for a first start on a
    // screen whose room is `available`; from then on keeps every change.
    WindowState(QMainWindow *window, QSplitter *splitter, QTabWidget *tabs, QRect available);

    // The first start's size: 1440x900, or the screen's room when smaller.
    static QSize openingSize(QSize available);
    // A kept place and size brought wholly onto the screen's room: no
    // bigger than it, moved in where it stood out (a window kept on a
    // larger or second screen).
    static QRect onScreen(QRect kept, QRect available);

private:
    void keep();
    bool eventFilter(QObject *watched, QEvent *event) override;

    QMainWindow *m_window;
    QSplitter *m_splitter;
    QTabWidget *m_tabs;
    bool m_restoring = true;
};

} // namespace slew::ui
