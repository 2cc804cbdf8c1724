// SPDX-License-Identifier: GPL-3.0-or-later
#include "trackingpanel.h"

#include "elementsetages.h"
#include "elementsetsdialog.h"
#include "targetpicker.h"

#include "session/rotatorsession.h"
#include "sky/observation.h"
#include "sky/sunmoon.h"
#include "sky/elementsetsources.h"
#include "sky/utctime.h"
#include "station/station.h"
#include "tracking/rotatorreach.h"
#include "tracking/skytrack.h"

#include <QFormLayout>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <cmath>

namespace slew::ui {

using tracking::TrackTarget;

namespace {

constexpr double kLookAheadDays = 1.0;
constexpr double kLookBackDays = 1.0 / 24.0; // an hour: any LEO pass under way rose within it
constexpr double kDopplerReferenceHz = 435e6;

QString hms(double seconds)
{
    const qint64 s = qint64(std::max(0.0, seconds));
    return QStringLiteral("%1:%2:%3").arg(s / 3600).arg((s / 60) % 60, 2, 10, QLatin1Char('0')).arg(s % 60, 2, 10, QLatin1Char('0'));
}

QString badge(const tracking::PassPlan &plan)
{
    if (!plan.isValid())
        return QObject::tr("no plan: %1").arg(plan.refusal);
    QStringList parts;
    if (plan.overTheTop)
        parts << QObject::tr("over the top");
    else if (plan.flipped)
        parts << QObject::tr("flip");
    if (plan.usesOverlap)
        parts << QObject::tr("overlap");
    if (plan.unwinds > 0)
        parts << QObject::tr("unwind");
    if (!plan.followable())
        parts << QObject::tr("lags %1°").arg(plan.predictedWorstDeg, 0, 'f', 1);
    return parts.isEmpty() ? QObject::tr("plain") : parts.join(QStringLiteral(", "));
}

} // namespace

TrackingPanel::TrackingPanel(station::Station *station, QWidget *parent)
    : QWidget(parent), m_station(station), m_session(station->session()), m_sets(station->elementSets()),
      m_clock(station->clock()), m_runner(station->passRunner())
{
    setObjectName(QStringLiteral("trackingPanel"));
    m_stationLine = new QLabel;
    m_stationLine->setObjectName(QStringLiteral("trackingStation"));
    m_setAges = new ElementSetAges(m_sets);
    m_picker = new TargetPicker(m_sets);
    m_passes = new QTableWidget(0, 6);
    m_passes->setObjectName(QStringLiteral("passes"));
    m_passes->setHorizontalHeaderLabels({tr("AOS (UTC)"), tr("AOS az"), tr("Max el"), tr("LOS (UTC)"), tr("LOS az"), tr("Plan")});
    m_passes->horizontalHeader()->setStretchLastSection(true);
    m_passes->verticalHeader()->hide();
    m_passes->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_passes->setSelectionMode(QAbstractItemView::SingleSelection);
    m_passes->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_countdown = new QLabel;
    m_countdown->setObjectName(QStringLiteral("countdown"));
    QFont big = m_countdown->font();
    big.setPointSizeF(big.pointSizeF() * 1.3);
    big.setBold(true);
    m_countdown->setFont(big);
    m_live = new QLabel;
    m_live->setObjectName(QStringLiteral("trackingLive"));
    m_live->setWordWrap(true);
    m_track = new QPushButton(tr("Track"));
    m_track->setObjectName(QStringLiteral("track"));
    m_stopTracking = new QPushButton(tr("Stop tracking"));
    m_stopTracking->setObjectName(QStringLiteral("stopTracking"));
    m_stopTracking->setEnabled(false);

    auto *top = new QFormLayout;
    top->addRow(tr("Station"), m_stationLine);
    top->addRow(tr("Element sets"), m_setAges);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_countdown, 1);
    buttons->addWidget(m_track);
    buttons->addWidget(m_stopTracking);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_picker, 1);
    layout->addWidget(m_passes, 2);
    layout->addLayout(buttons);
    layout->addWidget(m_live);

    connect(m_picker, &TargetPicker::chosenChanged, this, &TrackingPanel::showPasses);
    connect(m_passes, &QTableWidget::itemSelectionChanged, this, &TrackingPanel::onPassChosen);
    connect(m_track, &QPushButton::clicked, this, &TrackingPanel::startTracking);
    connect(m_stopTracking, &QPushButton::clicked, this, [this] { m_station->untrack(tr("stopped from the Tracking tab")); });
    connect(m_sets, &sky::ElementSetSources::setsChanged, this, &TrackingPanel::showSetAges);
    connect(m_session, &session::RotatorSession::profileChanged, this, &TrackingPanel::showPasses);
    connect(m_runner, &tracking::PassRunner::logLine, this, &TrackingPanel::message);
    connect(&m_runner->tracker(), &tracking::Tracker::stateChanged, this, [this] {
        m_stopTracking->setEnabled(m_runner->isRunning());
        m_track->setEnabled(!m_runner->isRunning());
    });
    connect(&m_tick, &QTimer::timeout, this, &TrackingPanel::refreshLive);
    m_tick.start(1000);
    connect(m_station, &station::Station::placeChanged, this, &TrackingPanel::showStation);
    // A clock started again or sent back to real time: the day's passes are
    // another day's. (A running tracker plans again by itself: PassRunner.)
    connect(m_clock, &tracking::StationClock::changed, this, &TrackingPanel::showPasses);
    showStation();
}

void TrackingPanel::showStation()
{
    const std::optional<sky::Station> place = m_station->place();
    m_stationLine->setText(place ? sky::describeStation(*place) : tr("not set: Sky → Station…"));
    m_stationLine->setToolTip(place && place->horizon ? tr("Horizon mask: %1").arg(place->horizon->describe())
                                                      : QString());
    showPasses();
}

void TrackingPanel::showSetAges()
{
    m_setAges->refresh(m_clock->nowJulian(), ElementSetsDialog::savedAgeLimitDays());
}

bool TrackingPanel::selectTarget(const QString &name)
{
    return m_picker->selectTarget(name);
}

std::optional<TrackTarget> TrackingPanel::chosenTarget() const
{
    const std::optional<sky::FavouriteTarget> chosen = m_picker->chosen();
    if (!chosen || m_picker->chosenIsMissing())
        return std::nullopt;
    TrackTarget target;
    switch (chosen->kind) {
    case sky::FavouriteTarget::Kind::Sun: target.kind = TrackTarget::Kind::Sun; return target;
    case sky::FavouriteTarget::Kind::Moon: target.kind = TrackTarget::Kind::Moon; return target;
    case sky::FavouriteTarget::Kind::Direction: return TrackTarget::parseFixedOrCelestial(chosen->name, nullptr);
    case sky::FavouriteTarget::Kind::Satellite: break;
    }
    for (const sky::ElementSet &t : m_sets->sets()) {
        if (t.catalogueNumber == chosen->catalogueNumber) {
            target.elements = t;
            return target;
        }
    }
    return std::nullopt;
}

tracking::RotatorReach TrackingPanel::reach() const
{
    return tracking::reachOf(*m_session);
}

void TrackingPanel::showPasses()
{
    m_passes->setRowCount(0);
    m_planned.clear();
    m_sky.reset();
    m_planning = false;
    const int generation = ++m_generation; // a forecast still running is for another choice
    const auto target = chosenTarget();
    const std::optional<sky::Station> place = m_station->place();
    if (!target || !place) {
        emit passOverlayChanged(std::nullopt);
        refreshLive();
        emit passesShown();
        return;
    }
    const double now = m_clock->nowJulian();
    const sky::PassWindow window{now, now + kLookAheadDays, 0.0};
    m_sky.emplace(*target);
    // Off the window's thread: a day of the moon's passes takes a good part
    // of a second to sample and plan, and the operator may be typing.
    m_planning = true;
    auto *watcher = new QFutureWatcher<QList<tracking::PlannedPass>>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, generation] {
        watcher->deleteLater();
        if (generation != m_generation)
            return;
        m_planning = false;
        fillPasses(watcher->result());
    });
    // A pass under way shows where it rose, not "now".
    watcher->setFuture(QtConcurrent::run([sky = *m_sky, station = *place, window, reach = reach()] {
        return tracking::forecastPasses(sky, station, window, reach, kLookBackDays);
    }));
    refreshLive();
}

void TrackingPanel::fillPasses(const QList<tracking::PlannedPass> &planned)
{
    m_planned = planned;
    for (const tracking::PlannedPass &one : m_planned) {
        const sky::Pass &p = one.pass;
        const int row = m_passes->rowCount();
        m_passes->insertRow(row);
        // A pass under way: its true AOS, marked, as `slew --passes` marks
        // it; one that rose before the look-back says so.
        QString aos = sky::utcFromJulian(p.aos.julian).toString(QStringLiteral("MM-dd HH:mm:ss"));
        if (p.aosClipped)
            aos = tr("before %1").arg(aos);
        if (one.underWay())
            aos += tr(" (under way)");
        const QStringList cells{aos,
                                QStringLiteral("%1°").arg(p.aos.azimuthDeg, 0, 'f', 0),
                                QStringLiteral("%1°").arg(p.maxElevationDeg(), 0, 'f', 1),
                                sky::utcFromJulian(p.los.julian).toString(QStringLiteral("MM-dd HH:mm:ss")),
                                QStringLiteral("%1°").arg(p.los.azimuthDeg, 0, 'f', 0), badge(one.plan)};
        for (int c = 0; c < cells.size(); ++c) {
            auto *item = new QTableWidgetItem(cells[c]);
            item->setToolTip(one.plan.describe());
            m_passes->setItem(row, c, item);
        }
    }
    m_passes->resizeColumnsToContents();
    if (!m_planned.isEmpty())
        m_passes->selectRow(0);
    else
        emit passOverlayChanged(std::nullopt);
    refreshLive();
    emit passesShown();
}

QList<sky::Pass> TrackingPanel::passes() const
{
    QList<sky::Pass> list;
    for (const tracking::PlannedPass &one : m_planned)
        list.append(one.pass);
    return list;
}

void TrackingPanel::onPassChosen()
{
    const QList<QTableWidgetItem *> chosen = m_passes->selectedItems();
    if (chosen.isEmpty() || chosen.first()->row() >= m_planned.size())
        return;
    const int row = chosen.first()->row();
    const QList<tracking::SkyPoint> &points = m_planned[row].points;
    const tracking::PassPlan &plan = m_planned[row].plan;
    PassOverlay overlay;
    for (const tracking::SkyPoint &p : points)
        overlay.sky.append(QPointF(p.azimuthDeg, p.elevationDeg));
    for (const tracking::PathPoint &p : plan.path)
        overlay.planned.append(QPointF(p.azimuth, p.elevation));
    overlay.azimuthTurnStart = reach().limits.azMin;
    overlay.azimuthTurnEnd = reach().limits.azMin + 360.0;
    overlay.flipped = plan.flipped;
    overlay.overTheTop = plan.overTheTop;
    overlay.unwinds = plan.unwinds;
    emit passOverlayChanged(overlay);
}

void TrackingPanel::startTracking()
{
    const auto target = chosenTarget();
    if (!target || !m_station->place()) {
        emit message(tr("tracking needs a target and the station (Sky → Station…)"));
        return;
    }
    if (!m_session->isConnected()) {
        emit message(tr("tracking needs a rotator: connect first"));
        return;
    }
    if (const QString refused = m_station->track(*target, 0.0); !refused.isEmpty()) {
        emit message(refused);
        return;
    }
    m_track->setEnabled(false);
    m_stopTracking->setEnabled(true);
}

void TrackingPanel::refreshLive()
{
    showSetAges(); // the elements age as the station's clock runs
    const double now = m_clock->nowJulian();
    const sky::Pass *next = nullptr;
    for (const tracking::PlannedPass &one : m_planned) {
        if (one.pass.los.julian > now) {
            next = &one.pass;
            break;
        }
    }
    if (m_picker->chosenIsMissing()) {
        m_countdown->setText(tr("not in the loaded element sets"));
    } else if (m_planning) {
        m_countdown->setText(tr("planning the passes…"));
    } else if (!next) {
        m_countdown->setText(m_planned.isEmpty() && chosenTarget() ? tr("no pass in the next day") : QString());
    } else if (next->aos.julian > now) {
        m_countdown->setText(tr("AOS in %1").arg(hms((next->aos.julian - now) * sky::kSecondsPerDay)));
    } else {
        m_countdown->setText(tr("up now: LOS in %1").arg(hms((next->los.julian - now) * sky::kSecondsPerDay)));
    }

    const std::optional<sky::Station> place = m_station->place();
    if (!m_sky || !place) {
        m_live->clear();
        return;
    }
    QString where;
    if (const std::optional<sky::LookAngles> look = m_sky->lookAt(*place, now)) {
        where = tr("az %1°, el %2°").arg(look->azimuthDeg, 0, 'f', 1).arg(look->elevationDeg, 0, 'f', 1);
        if (m_sky->target().kind == TrackTarget::Kind::Satellite)
            where += tr(", range %1 km, range-rate %2 km/s, Doppler %3 kHz at 435 MHz")
                         .arg(look->rangeKm, 0, 'f', 0)
                         .arg(look->rangeRateKmS, 0, 'f', 3)
                         .arg(sky::dopplerShiftHz(kDopplerReferenceHz, look->rangeRateKmS) / 1000.0, 0, 'f', 2);
        emit passTargetMoved(look->elevationDeg >= 0 ? std::optional<QPointF>(QPointF(look->azimuthDeg, look->elevationDeg))
                                                     : std::nullopt);
    }
    QString pointing;
    if (m_runner->tracker().state() == tracking::Tracker::State::Tracking && m_session->hasPosition()) {
        const tracking::SkyPoint t = m_runner->tracker().targetNow();
        pointing = tr("; pointing error %1°").arg(
            tracking::skyAngleDeg(m_session->azimuth(), m_session->elevation(), t.azimuthDeg, t.elevationDeg), 0, 'f', 2);
    }
    m_live->setText(where + pointing);
}

} // namespace slew::ui
