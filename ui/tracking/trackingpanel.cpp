// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/trackingpanel.h"

#include "tracking/elementsetages.h"
#include "tracking/passplanbadge.h"
#include "tracking/targetpicker.h"
#include "tracking/trackingline.h"

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
    m_rehearse = new QPushButton(tr("Rehearse this pass"));
    m_rehearse->setObjectName(QStringLiteral("rehearsePass"));
    m_rehearse->setToolTip(tr("Start the station clock two minutes before the selected pass's AOS "
                              "(Sky → Time controller), to practise it on the simulator or the rotator."));
    m_rehearse->setEnabled(false);

    auto *top = new QFormLayout;
    top->addRow(tr("Station"), m_stationLine);
    top->addRow(tr("Element sets"), m_setAges);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_countdown, 1);
    buttons->addWidget(m_rehearse);
    buttons->addWidget(m_track);
    buttons->addWidget(m_stopTracking);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_picker, 1);
    layout->addWidget(m_passes, 2);
    layout->addLayout(buttons);
    layout->addWidget(m_live);

    connect(m_picker, &TargetPicker::chosenChanged, this, &TrackingPanel::showPasses);
    connect(m_picker, &TargetPicker::favouritesChanged, this, &TrackingPanel::favouritesChanged);
    connect(m_passes, &QTableWidget::itemSelectionChanged, this, &TrackingPanel::onPassChosen);
    connect(m_track, &QPushButton::clicked, this, &TrackingPanel::startTracking);
    connect(m_passes, &QTableWidget::itemSelectionChanged, this,
            [this] { m_rehearse->setEnabled(!m_passes->selectedItems().isEmpty()); });
    connect(m_rehearse, &QPushButton::clicked, this, [this] {
        const QList<QTableWidgetItem *> chosen = m_passes->selectedItems();
        if (!chosen.isEmpty() && chosen.first()->row() < m_planned.size())
            emit rehearsePassRequested(m_planned[chosen.first()->row()].pass.aos.julian);
    });
    connect(m_stopTracking, &QPushButton::clicked, this, [this] { m_station->untrack(tr("stopped from the Tracking tab")); });
    connect(m_sets, &sky::ElementSetSources::setsChanged, this, &TrackingPanel::showSetAges);
    connect(m_sets, &sky::ElementSetSources::setsChanged, this, &TrackingPanel::showButtons);
    connect(m_session, &session::RotatorSession::profileChanged, this, &TrackingPanel::showPasses);
    connect(m_runner, &tracking::PassRunner::logLine, this, &TrackingPanel::message);
    connect(&m_runner->tracker(), &tracking::Tracker::stateChanged, this, &TrackingPanel::showButtons);
    connect(m_runner, &tracking::PassRunner::logLine, this, &TrackingPanel::showButtons); // started, stopped
    connect(m_picker, &TargetPicker::chosenChanged, this, &TrackingPanel::showButtons);
    connect(m_session, &session::RotatorSession::stateChanged, this, &TrackingPanel::showButtons);
    connect(&m_tick, &QTimer::timeout, this, &TrackingPanel::refreshLive);
    m_tick.start(1000);
    connect(m_station, &station::Station::placeChanged, this, &TrackingPanel::showStation);
    connect(m_station, &station::Station::placeChanged, this, &TrackingPanel::showButtons);
    // A clock started again or sent back to real time: the day's passes are
    // another day's. (A running tracker plans again by itself: PassRunner.)
    connect(m_clock, &tracking::StationClock::changed, this, &TrackingPanel::showPasses);
    showStation();
    showButtons();
}

void TrackingPanel::showButtons()
{
    // Each button says what it acts on, and a greyed one says why.
    const auto shortName = [](const QString &name) { return name.size() > 24 ? name.left(23) + QChar(0x2026) : name; };
    if (m_runner->isRunning()) {
        const QString name = m_runner->target().name();
        m_track->setText(tr("Track"));
        m_track->setEnabled(false);
        m_track->setToolTip(tr("Slew is tracking %1: Stop tracking first").arg(name));
        m_stopTracking->setText(tr("Stop tracking %1").arg(shortName(name)));
        m_stopTracking->setEnabled(true);
        m_stopTracking->setToolTip(tr("Stop tracking %1; the antenna stays where it is").arg(name));
        return;
    }
    m_stopTracking->setText(tr("Stop tracking"));
    m_stopTracking->setEnabled(false);
    m_stopTracking->setToolTip(tr("Nothing is being tracked"));
    const std::optional<sky::FavouriteTarget> chosen = m_picker->chosen();
    const std::optional<TrackTarget> target = chosenTarget();
    const QString name = target ? target->name() : chosen ? chosen->name : QString();
    m_track->setEnabled(true); // a click on what cannot start says why, as the tooltip does
    m_track->setText(name.isEmpty() ? tr("Track") : tr("Track %1").arg(shortName(name)));
    QStringList missing;
    if (!target)
        missing << (chosen ? tr("%1 is not in the loaded element sets").arg(name) : tr("pick a target above"));
    else if (target->kind == TrackTarget::Kind::Satellite) {
        const QString old = sky::elementsTooOld(target->elements, m_clock->nowJulian(),
                                                m_station->elementAgeLimitDays(), tr("now"));
        if (!old.isEmpty())
            missing << tr("refresh the element sets, or raise the limit under Sky → Element sets… (%1)").arg(old);
    }
    if (!m_station->place())
        missing << tr("set the station (Sky → Station…)");
    if (!m_session->isConnected())
        missing << tr("connect a rotator");
    m_track->setToolTip(missing.isEmpty() ? tr("Track every pass of %1 from the next one").arg(name)
                                          : tr("To track: %1").arg(missing.join(QStringLiteral("; "))));
}

void TrackingPanel::showStation()
{
    const std::optional<sky::Site> place = m_station->place();
    m_stationLine->setText(place ? sky::describeSite(*place) : tr("not set: Sky → Station…"));
    m_stationLine->setToolTip(place && place->horizon ? tr("Horizon mask: %1").arg(place->horizon->describe())
                                                      : QString());
    showPasses();
}

void TrackingPanel::showSetAges()
{
    m_setAges->refresh(m_clock->nowJulian(), m_station->elementAgeLimitDays());
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
    const std::optional<sky::Site> place = m_station->place();
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
                                QStringLiteral("%1°").arg(p.los.azimuthDeg, 0, 'f', 0), passPlanBadge(one.plan)};
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
    if (const QString refused = m_station->track(*target, 0.0).reason(); !refused.isEmpty()) {
        emit message(refused);
        return;
    }
    showButtons();
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
        m_countdown->setText(tr("AOS in %1").arg(TrackingLine::countdown((next->aos.julian - now) * sky::kSecondsPerDay)));
    } else {
        m_countdown->setText(tr("up now: LOS in %1").arg(TrackingLine::countdown((next->los.julian - now) * sky::kSecondsPerDay)));
    }

    const std::optional<sky::Site> place = m_station->place();
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
