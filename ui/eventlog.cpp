#include "eventlog.h"

#include <QScrollBar>
#include <QTextCursor>

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

void EventLog::addEvent(const QDateTime &when, station::AlarmMonitor::Severity severity, const QString &text)
{
    const char *colour = severity == station::AlarmMonitor::Severity::Alarm     ? "#ff6b6b"
                         : severity == station::AlarmMonitor::Severity::Warning ? "#f2c03c"
                                                                       : "#b0bac6";
    const char *tag = severity == station::AlarmMonitor::Severity::Alarm     ? "ALARM"
                      : severity == station::AlarmMonitor::Severity::Warning ? "WARN "
                                                                    : "info ";
    appendHtml(QStringLiteral("<span style='color:#8a96a3'>%1</span> <span style='color:%2'>%3 %4</span>")
                   .arg(when.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz")), QLatin1String(colour),
                        QLatin1String(tag), text.toHtmlEscaped()));
    // The view follows the text cursor, which appending leaves at the end of
    // the new line: a long one carried the view right (at once, or when the
    // tab was next shown) and hid every line's time. The cursor goes to the
    // start of the last line, so the view stays at the bottom with the times.
    QTextCursor cursor = textCursor();
    cursor.movePosition(QTextCursor::End);
    cursor.movePosition(QTextCursor::StartOfBlock);
    setTextCursor(cursor);
    horizontalScrollBar()->setValue(0);
}

} // namespace slew::ui
