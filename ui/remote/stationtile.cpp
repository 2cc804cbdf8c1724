// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/stationtile.h"

#include "operatortheme.h"
#include "remote/remotebanner.h"
#include "rotor/polarplotwidget.h"

#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace slew::ui {

StationTile::StationTile(const QString &name, QWidget *parent) : QFrame(parent), m_name(name)
{
    setObjectName(QStringLiteral("stationTile_%1").arg(name));
    setFrameShape(QFrame::StyledPanel);
    m_title = new QLabel(name);
    m_title->setTextFormat(Qt::PlainText);
    QFont f = m_title->font();
    f.setBold(true);
    f.setPointSizeF(f.pointSizeF() * 1.1);
    m_title->setFont(f);
    m_plot = new PolarPlotWidget;
    m_plot->setMinimumSize(150, 150);
    m_plot->setLegendShown(false);
    setFixedSize(kWidth, kHeight);
    m_plot->setAttribute(Qt::WA_TransparentForMouseEvents); // a view; the station's own window takes targets
    m_status = new QLabel;
    m_status->setTextFormat(Qt::PlainText);
    m_status->setWordWrap(true);
    m_alarms = new QLabel;
    m_alarms->setTextFormat(Qt::PlainText);
    m_alarms->setWordWrap(true);
    m_alarms->setStyleSheet(warningText());
    m_alarms->setVisible(false);
    m_open = new QPushButton(tr("Open"));
    m_open->setObjectName(QStringLiteral("openStation_%1").arg(name));
    connect(m_open, &QPushButton::clicked, this, [this] { emit openRequested(m_name); });
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(2);
    layout->addWidget(m_title);
    layout->addWidget(m_plot, 1);
    layout->addWidget(m_status);
    layout->addWidget(m_alarms);
    layout->addWidget(m_open);
}

QString StationTile::statusText() const
{
    return m_status->text();
}

void StationTile::show(bool live, bool online, const std::optional<face::StationState> &state, qint64 ageMs)
{
    QString status;
    // The plot is drawn again only when what it shows has changed: the
    // network window asks every tile every second, for the ages.
    const bool stale = !state || state->stale || !live;
    if (state && (state->unixMs != m_shownMs || stale != m_shownStale)) {
        m_shownMs = state->unixMs;
        m_shownStale = stale;
        m_plot->setLimits(state->limits);
        m_plot->setPark(state->park);
        if (state->position)
            m_plot->setActual(state->position->x(), state->position->y(), stale);
        if (state->target)
            m_plot->setTarget(state->target->x(), state->target->y());
        else
            m_plot->clearTarget();
    }
    if (state) {
        if (state->position)
            status = tr("az %1° el %2°").arg(state->position->x(), 0, 'f', 1).arg(state->position->y(), 0, 'f', 1);
        status += state->moving ? tr(", moving") : tr(", at rest");
        if (state->tracking != u"off")
            status += tr(" · tracking %1 (%2)").arg(state->trackingTarget, state->tracking);
        if (state->link != u"connected")
            status += tr(" · rotator %1").arg(state->link);
        m_alarms->setText(state->alarms.join(QStringLiteral(" · ")));
        m_alarms->setVisible(!state->alarms.isEmpty());
    }
    if (!online)
        status = tr("OFFLINE · ") + status;
    status += tr(" · %1").arg(RemoteBanner::ageText(ageMs));
    m_status->setText(status);
    m_title->setEnabled(live);
    m_status->setEnabled(live);
    setStyleSheet(live ? QString() : QStringLiteral("#%1{background:#2b2e33;}").arg(objectName()));
}

} // namespace slew::ui
