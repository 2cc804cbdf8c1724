#include "alarmbanner.h"

#include <QHBoxLayout>
#include <QLabel>

namespace slew::ui {

AlarmBanner::AlarmBanner(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("alarmBanner"));
    setAttribute(Qt::WA_StyledBackground);
    m_text = new QLabel;
    m_text->setObjectName(QStringLiteral("alarmText"));
    m_text->setWordWrap(true);
    // Alarm text comes from controllers and, in a remote window, from the
    // broker: shown as it is, never read as rich text.
    m_text->setTextFormat(Qt::PlainText);
    auto *icon = new QLabel(QStringLiteral("⚠"));
    QFont f = icon->font();
    f.setPointSizeF(f.pointSizeF() * 1.5);
    icon->setFont(f);
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(10, 6, 10, 6);
    layout->addWidget(icon);
    layout->addWidget(m_text, 1);
    setVisible(false);
}

QString AlarmBanner::text() const
{
    return m_text->text();
}

void AlarmBanner::showAlarms(const QStringList &alarms, bool severe)
{
    m_severe = severe;
    setStyleSheet(QStringLiteral("#alarmBanner{background:%1;} QLabel{color:%2;font-weight:bold;}")
                      .arg(severe ? QStringLiteral("#b71c1c") : QStringLiteral("#e0a020"),
                           severe ? QStringLiteral("white") : QStringLiteral("#1a1a1a")));
    m_text->setText(alarms.join(QStringLiteral("   ·   ")));
    setVisible(!alarms.isEmpty());
}

} // namespace slew::ui
