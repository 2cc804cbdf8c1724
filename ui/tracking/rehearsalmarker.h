// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The window's mark of a rehearsal: while the station clock is not real
// time, an orange line in the status bar ("REHEARSAL: station clock
// 2026-11-25 14:03:10 UTC ×5", every second; ", paused" while the clock
// holds) and the window's title starts
// with REHEARSAL, so no one takes a rehearsed pass for the real sky, even
// with the Time controller closed. In real time both are gone.

#include <QLabel>
#include <QTimer>

class QMainWindow;

namespace slew::tracking {
class StationClock;
}

namespace slew::ui {

class RehearsalMarker : public QLabel {
    Q_OBJECT
public:
    // Takes its place at the foot of `window`, whose title it marks too.
    // The clock must outlive it.
    RehearsalMarker(const tracking::StationClock *clock, QMainWindow *window);

    // "2026-11-25 14:03:10 UTC"
    static QString clockText(double julian);
    // "×5", "×2.5"
    static QString rateText(double rate);
    // How a rehearsal is marked wherever the window says it: orange.
    static QString markStyle();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void refresh();
    void markTitle();

    const tracking::StationClock *m_clock;
    QMainWindow *m_titled;
    QString m_titlePrefix; // what this put before the window's own title
    bool m_retitling = false;
    QTimer m_tick;
};

} // namespace slew::ui
