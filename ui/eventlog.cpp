#include "eventlog.h"

namespace slew::ui {

EventLog::EventLog(QWidget *parent) : QPlainTextEdit(parent)
{
    setObjectName(QStringLiteral("eventLog"));
    setReadOnly(true);
    setMaximumBlockCount(kMaxLines);
    setLineWrapMode(QPlainTextEdit::NoWrap);
    QFont f(QStringLiteral("monospace"));
    f.setStyleHint(QFont::Monospace);
    setFont(f);
}

void EventLog::addEvent(const QDateTime &when, AlarmMonitor::Severity severity, const QString &text)
{
    const char *colour = severity == AlarmMonitor::Severity::Alarm     ? "#ff6b6b"
                         : severity == AlarmMonitor::Severity::Warning ? "#f2c03c"
                                                                       : "#b0bac6";
    const char *tag = severity == AlarmMonitor::Severity::Alarm     ? "ALARM"
                      : severity == AlarmMonitor::Severity::Warning ? "WARN "
                                                                    : "info ";
    appendHtml(QStringLiteral("<span style='color:#8a96a3'>%1</span> <span style='color:%2'>%3 %4</span>")
                   .arg(when.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")), QLatin1String(colour),
                        QLatin1String(tag), text.toHtmlEscaped()));
}

} // namespace slew::ui
