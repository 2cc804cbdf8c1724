#include "eventlog.h"

#include "sky/utctime.h"
#include "tracking/stationclock.h"

#include <QScrollBar>
#include <QTextCursor>

namespace slew::ui {

EventLog::EventLog(QWidget *parent) : QPlainTextEdit(parent)
{
    setObjectName(QStringLiteral("eventLog"));
    setReadOnly(true);
    setMaximumBlockCount(kMaxLines);
    // A long line wraps, a long word in it too (a URI, a controller's
    // reply): all of every line in view, its time first.
    setLineWrapMode(QPlainTextEdit::WidgetWidth);
    setWordWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    QFont f(QStringLiteral("monospace"));
    f.setStyleHint(QFont::Monospace);
    setFont(f);
}

void EventLog::addEvent(station::AlarmMonitor::Severity severity, const QString &text)
{
    if (m_clock && m_clock->isRehearsal()) {
        addEvent(sky::utcFromJulian(m_clock->nowJulian()).toLocalTime(), severity, tr("[rehearsal] %1").arg(text));
        return;
    }
    addEvent(QDateTime::currentDateTime(), severity, text);
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
    // the new line. The cursor goes to the start of the last line, so the
    // view stays at the bottom with the times.
    QTextCursor cursor = textCursor();
    cursor.movePosition(QTextCursor::End);
    cursor.movePosition(QTextCursor::StartOfBlock);
    setTextCursor(cursor);
    horizontalScrollBar()->setValue(0);
}

} // namespace slew::ui
