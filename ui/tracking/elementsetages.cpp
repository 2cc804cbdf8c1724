// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/elementsetages.h"

#include "sky/elementsetsources.h"

#include <QLabel>
#include <QUrlQuery>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace slew::ui {

namespace {

// What an operator calls a source: a file's name, or a CelesTrak-style
// group ("celestrak.org amateur"); the whole URL is in the tooltip.
QString sourceName(const QUrl &url)
{
    if (url.isLocalFile())
        return url.fileName();
    const QString group = QUrlQuery(url).queryItemValue(QStringLiteral("GROUP"));
    const QString what = group.isEmpty() ? url.fileName() : group;
    return what.isEmpty() ? url.host() : QStringLiteral("%1 %2").arg(url.host(), what);
}

} // namespace

QString describeAgeDays(double days)
{
    if (days < 1.0 / 24.0)
        return QObject::tr("%1 min").arg(std::max(0.0, days * 24.0 * 60.0), 0, 'f', 0);
    return days < 1.0 ? QObject::tr("%1 h").arg(days * 24.0, 0, 'f', 1) : QObject::tr("%1 days").arg(days, 0, 'f', 1);
}

QString describeAgeSince(const QDateTime &then)
{
    if (!then.isValid())
        return QObject::tr("no copy");
    return describeAgeDays(then.secsTo(QDateTime::currentDateTimeUtc()) / 86400.0);
}

ElementSetAges::ElementSetAges(const sky::ElementSetSources *sources, QWidget *parent)
    : QWidget(parent), m_sources(sources), m_layout(new QVBoxLayout(this))
{
    setObjectName(QStringLiteral("elementSetAges"));
    m_layout->setContentsMargins(0, 0, 0, 0);
    m_layout->setSpacing(0);
}

bool ElementSetAges::isStale(const QLabel *line)
{
    return line->property("stale").toBool();
}

void ElementSetAges::refresh(double julianNow, double limitDays)
{
    const QList<sky::ElementSetSourceStatus> status = m_sources->status();
    const qsizetype wanted = std::max<qsizetype>(1, status.size());
    while (m_lines.size() < wanted) {
        auto *line = new QLabel;
        line->setObjectName(QStringLiteral("elementSetAge%1").arg(m_lines.size()));
        line->setTextInteractionFlags(Qt::TextSelectableByMouse);
        line->setWordWrap(true); // a long file name must not push the tab wider
        m_layout->addWidget(line);
        m_lines.append(line);
    }
    while (m_lines.size() > wanted)
        delete m_lines.takeLast();

    if (status.isEmpty()) {
        m_lines[0]->setText(tr("none loaded: add a source in Sky → Element sets…"));
        m_lines[0]->setToolTip(QString());
        m_lines[0]->setProperty("stale", false);
        m_lines[0]->setStyleSheet(QString());
        return;
    }
    for (qsizetype i = 0; i < status.size(); ++i) {
        const sky::ElementSetSourceStatus &s = status[i];
        const auto newest = sky::newestEpochJulian(m_sources->setsFrom(i));
        QString text = tr("%1: %n set(s)", nullptr, s.setCount).arg(sourceName(s.url));
        // Predicting before the epoch (rehearsing the past) drifts as well.
        const double age = newest ? std::abs(julianNow - *newest) : 0.0;
        const bool stale = newest && age > limitDays;
        if (newest)
            text += tr(", newest elements %1 old").arg(describeAgeDays(age));
        else if (!s.error.isEmpty())
            text += QStringLiteral(" (%1)").arg(s.error);
        if (s.cachedAt.isValid())
            text += tr(", downloaded %1 ago").arg(describeAgeSince(s.cachedAt));
        if (stale)
            text = tr("⚠ %1: older than %2 days, not tracked; refresh in Sky → Element sets…")
                       .arg(text)
                       .arg(limitDays, 0, 'g', 4);
        QLabel *line = m_lines[i];
        line->setText(text);
        line->setToolTip(s.url.toString());
        line->setProperty("stale", stale);
        line->setStyleSheet(stale ? QStringLiteral("color:#f2a03c; font-weight:bold;") : QString());
    }
}

} // namespace slew::ui
