#pragma once
// Every alarm, refusal, failure and connection change with its time, newest
// at the bottom. Bounded: the oldest lines go once kMaxLines is reached.

#include "station/alarmmonitor.h"

#include <QPlainTextEdit>

namespace slew::ui {

class EventLog : public QPlainTextEdit {
    Q_OBJECT
public:
    static constexpr int kMaxLines = 5000;

    explicit EventLog(QWidget *parent = nullptr);

public slots:
    void addEvent(const QDateTime &when, slew::station::AlarmMonitor::Severity severity, const QString &text);
};

} // namespace slew::ui
