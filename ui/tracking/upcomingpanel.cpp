// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/upcomingpanel.h"

#include "tracking/passplanbadge.h"
#include "tracking/trackingline.h"

#include "session/rotatorsession.h"
#include "sky/elementsetsources.h"
#include "sky/favouritetargets.h"
#include "sky/utctime.h"
#include "station/station.h"
#include "tracking/rotatorreach.h"
#include "tracking/stationclock.h"

#include <QFutureWatcher>
#include <QHeaderView>
#include <QLabel>
#include <QSettings>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <vector>

namespace slew::ui {

namespace {

constexpr double kLookAheadDays = 1.0;
constexpr double kLookBackDays = 1.0 / 24.0; // a pass under way shows where it rose, as in One target
constexpr int kMostRows = 60;

enum Column { TargetColumn, AosColumn, InColumn, MaxElColumn, LosColumn, RotatorColumn, ColumnCount };

QString clockText(double julian)
{
    return sky::utcFromJulian(julian).toString(QStringLiteral("MM-dd HH:mm:ss"));
}

} // namespace

UpcomingPanel::UpcomingPanel(station::Station *station, QWidget *parent) : QWidget(parent), m_station(station)
{
    setObjectName(QStringLiteral("upcomingPanel"));
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("upcomingStatus"));
    m_status->setWordWrap(true);
    m_table = new QTableWidget(0, ColumnCount);
    m_table->setObjectName(QStringLiteral("upcomingPasses"));
    m_table->setHorizontalHeaderLabels(
        {tr("Target"), tr("AOS (UTC)"), tr("In"), tr("Max el"), tr("LOS (UTC)"), tr("This rotator")});
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->hide();
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_status);
    layout->addWidget(m_table, 1);

    connect(m_table, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
        if (row >= 0 && row < m_rows.size())
            emit targetChosen(m_rows.at(row).search);
    });
    connect(station->elementSets(), &sky::ElementSetSources::setsChanged, this, &UpcomingPanel::refresh);
    connect(station, &station::Station::placeChanged, this, &UpcomingPanel::refresh);
    connect(station->clock(), &tracking::StationClock::changed, this, &UpcomingPanel::refresh);
    connect(station->session(), &session::RotatorSession::profileChanged, this, &UpcomingPanel::refresh);
    connect(&m_tick, &QTimer::timeout, this, &UpcomingPanel::tick);
    m_tick.start(1000);
    refresh();
}

void UpcomingPanel::refresh()
{
    const int generation = ++m_generation;
    const std::optional<sky::Site> place = m_station->place();
    sky::FavouriteTargets favourites;
    favourites.load(QSettings());
    // The favourites as targets: a satellite from the loaded sets (one no
    // set holds is counted, and said), the sun, the moon. A fixed direction
    // has no passes to list.
    struct Favourite {
        QString name, search;
        tracking::TargetSky sky;
    };
    std::vector<Favourite> targets;
    int missing = 0;
    const QList<sky::ElementSet> sets = m_station->elementSets()->sets();
    for (const sky::FavouriteTarget &f : favourites.list()) {
        tracking::TrackTarget target;
        QString search;
        switch (f.kind) {
        case sky::FavouriteTarget::Kind::Sun:
            target.kind = tracking::TrackTarget::Kind::Sun;
            search = QStringLiteral("sun");
            break;
        case sky::FavouriteTarget::Kind::Moon:
            target.kind = tracking::TrackTarget::Kind::Moon;
            search = QStringLiteral("moon");
            break;
        case sky::FavouriteTarget::Kind::Direction: continue;
        case sky::FavouriteTarget::Kind::Satellite: {
            const auto set = std::find_if(sets.cbegin(), sets.cend(),
                                          [&f](const sky::ElementSet &s) { return s.catalogueNumber == f.catalogueNumber; });
            if (set == sets.cend()) {
                ++missing;
                continue;
            }
            target.elements = *set;
            search = QString::number(set->catalogueNumber);
            break;
        }
        }
        targets.push_back({target.name(), search, tracking::TargetSky(target)});
    }
    const QString missingNote =
        missing > 0 ? tr(" %n favourite(s) not in the loaded element sets.", nullptr, missing) : QString();
    if (!place || targets.empty()) {
        m_planning = false;
        fill({});
        m_status->setText((!place ? tr("Set the station (Sky → Station…) to see the passes.")
                                  : tr("Star satellites, the sun or the moon in One target (☆) to list their next "
                                       "passes here."))
                          + missingNote);
        return;
    }
    m_planning = true;
    m_status->setText(tr("Planning the next passes of %n favourite(s)…", nullptr, int(targets.size())) + missingNote);
    const double now = m_station->clock()->nowJulian();
    const sky::PassWindow window{now, now + kLookAheadDays, 0.0};
    // Off the window's thread: the moon's day takes a good part of a second.
    auto *watcher = new QFutureWatcher<QList<Row>>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, generation, missingNote, count = targets.size()] {
        watcher->deleteLater();
        if (generation != m_generation)
            return;
        m_planning = false;
        m_status->setText(tr("The next passes of %n favourite(s), in the coming day.", nullptr, int(count)) + missingNote);
        fill(watcher->result());
    });
    watcher->setFuture(QtConcurrent::run([targets, station = *place, window, reach = tracking::reachOf(*m_station->session())] {
        QList<Row> rows;
        for (const Favourite &f : targets)
            for (const tracking::PlannedPass &p : tracking::forecastPasses(f.sky, station, window, reach, kLookBackDays))
                rows.append({f.name, f.search, p});
        std::stable_sort(rows.begin(), rows.end(),
                         [](const Row &a, const Row &b) { return a.planned.pass.aos.julian < b.planned.pass.aos.julian; });
        if (rows.size() > kMostRows)
            rows.resize(kMostRows);
        return rows;
    }));
}

void UpcomingPanel::fill(const QList<Row> &rows)
{
    m_rows = rows;
    m_table->setRowCount(0);
    for (const Row &r : m_rows) {
        const sky::Pass &p = r.planned.pass;
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        QString aos = clockText(p.aos.julian);
        if (p.aosClipped)
            aos = tr("before %1").arg(aos);
        const QStringList cells{r.target, aos, QString(), QStringLiteral("%1°").arg(p.maxElevationDeg(), 0, 'f', 1),
                                clockText(p.los.julian), passPlanBadge(r.planned.plan)};
        for (int c = 0; c < cells.size(); ++c)
            m_table->setItem(row, c, new QTableWidgetItem(cells.at(c)));
        if (!r.planned.plan.isValid())
            m_table->item(row, RotatorColumn)->setForeground(palette().color(QPalette::Disabled, QPalette::Text));
    }
    tick();
    m_table->resizeColumnsToContents();
    // The countdowns change every second: room for the longest of them.
    const bool anyUp = std::any_of(m_rows.cbegin(), m_rows.cend(), [this](const Row &r) {
        return r.planned.pass.aos.julian <= m_station->clock()->nowJulian();
    });
    const QString longest = QStringLiteral("00:00:00");
    const int countdownWidth =
        m_table->fontMetrics().horizontalAdvance(anyUp ? tr("up now, LOS in %1").arg(longest) : longest) + 16;
    m_table->setColumnWidth(InColumn, std::max(m_table->columnWidth(InColumn), countdownWidth));
    emit rowsShown();
}

void UpcomingPanel::tick()
{
    const double now = m_station->clock()->nowJulian();
    bool anyOver = false;
    for (int row = 0; row < m_rows.size(); ++row) {
        const sky::Pass &p = m_rows.at(row).planned.pass;
        const double toAos = (p.aos.julian - now) * sky::kSecondsPerDay;
        const double toLos = (p.los.julian - now) * sky::kSecondsPerDay;
        anyOver = anyOver || toLos < 0;
        const QString in = toAos > 0    ? TrackingLine::countdown(toAos)
                           : toLos > 0 ? tr("up now, LOS in %1").arg(TrackingLine::countdown(toLos))
                                       : tr("over");
        if (QTableWidgetItem *item = m_table->item(row, InColumn))
            item->setText(in);
    }
    if (anyOver && !m_planning)
        refresh(); // the list moves on: the day ahead is a day from now
}

} // namespace slew::ui
