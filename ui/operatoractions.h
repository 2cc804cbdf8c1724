// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every move the operator starts from the window (go to, a click on the
// plot, a preset, park, home, stop, a jog), written to the Events log once
// when it starts and once when it ends, with how it ended: arrived, stopped
// short and how far off, stopped, or replaced by another target. When the
// move ends, the panels' "Going to…" lines are told to clear.

#include "station/alarmmonitor.h"
#include "session/movewatch.h"

#include <QObject>
#include <QPointF>
#include <QString>

#include <optional>

namespace slew::ui {

class OperatorActions : public QObject {
    Q_OBJECT
public:
    explicit OperatorActions(session::MoveWatch *watch, QObject *parent = nullptr);

public slots:
    // A move was sent to target (pointing frame; none for a park not read yet).
    void moveStarted(const QString &what, std::optional<QPointF> target);
    // An action without a move of its own to follow: Stop, a jog, homing.
    void action(const QString &text);
    void outcome(const QString &text, bool problem);

signals:
    void logged(station::AlarmMonitor::Severity severity, const QString &text);
    // The move the panels' lines describe has ended, however it ended.
    void moveEnded();

private:
    void onEnded(session::MoveWatch::Outcome outcome, QPointF at, double offDeg);

    session::MoveWatch *m_watch;
    QString m_what; // the move being followed, as it was logged
};

// "az 270.5°, el 12.0°": positions as the Events log writes them.
QString describePosition(QPointF azEl);

} // namespace slew::ui
