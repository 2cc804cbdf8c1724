// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/plotareaaligner.h"

#include <QChart>
#include <QEvent>
#include <QGraphicsLayout>
#include <QWidget>

#include <algorithm>
#include <cmath>

namespace slew::ui {

PlotAreaAligner::PlotAreaAligner(QObject *parent) : QObject(parent) {}

void PlotAreaAligner::add(QChart *chart, QWidget *shownBy)
{
    m_entries.push_back({chart, shownBy});
    // A new axis width (new labels, a new size) moves the plot area.
    connect(chart, &QChart::plotAreaChanged, this, &PlotAreaAligner::alignSoon);
    // A chart shown again may have missed changes made while it was hidden.
    shownBy->installEventFilter(this);
}

bool PlotAreaAligner::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Show || event->type() == QEvent::Hide)
        alignSoon();
    return QObject::eventFilter(watched, event);
}

void PlotAreaAligner::alignSoon()
{
    if (m_pending)
        return;
    m_pending = true;
    QMetaObject::invokeMethod(this, [this] { align(); }, Qt::QueuedConnection);
}

void PlotAreaAligner::align()
{
    m_pending = false;
    std::vector<Entry *> shown;
    for (Entry &e : m_entries) {
        if (e.shownBy->isVisible())
            shown.push_back(&e);
    }
    if (shown.empty())
        return;
    // Where each plot area would begin without the extra margin; the layout
    // is brought up to date first, so the plot areas are the current ones.
    std::vector<double> natural;
    for (Entry *e : shown) {
        e->chart->layout()->activate();
        natural.push_back(e->chart->plotArea().left() - e->extra);
    }
    const double edge = *std::max_element(natural.begin(), natural.end());
    for (std::size_t i = 0; i < shown.size(); ++i) {
        Entry &e = *shown[i];
        const int extra = int(std::lround(edge - natural[i]));
        if (extra == e.extra)
            continue;
        QMargins margins = e.chart->margins();
        margins.setLeft(margins.left() - e.extra + extra);
        e.extra = extra;
        e.chart->setMargins(margins);
        e.chart->layout()->activate();
    }
}

} // namespace slew::ui
