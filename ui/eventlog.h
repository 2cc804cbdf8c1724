#pragma once
// Every alarm, refusal, failure and connection change with its time, newest
// at the bottom. Bounded: the oldest lines go once kMaxLines is reached.
// Stamped by the station's clock: during a rehearsal a line has the
// rehearsal's time, marked, as the pass it belongs to.

#include "station/alarmmonitor.h"

#include <QPlainTextEdit>

namespace slew::tracking {
class StationClock;
}

namespace slew::ui {

class EventLog : public QPlainTextEdit {
    Q_OBJECT
public:
    static constexpr int kMaxLines = 5000;

    explicit EventLog(QWidget *parent = nullptr);

    // The clock addEvent(severity, text) stamps lines with; none: the
    // computer's.
    void setClock(const tracking::StationClock *clock) { m_clock = clock; }

public slots:
    void addEvent(slew::station::AlarmMonitor::Severity severity, const QString &text);
    void addEvent(const QDateTime &when, slew::station::AlarmMonitor::Severity severity, const QString &text);

private:
    const tracking::StationClock *m_clock = nullptr;
};

} // namespace slew::ui
