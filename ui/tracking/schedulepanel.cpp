// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/schedulepanel.h"

#include "operatortheme.h"
#include "tracking/scheduletimeline.h"

#include "schedule/scheduletext.h"
#include "session/rotatorsession.h"
#include "sky/elementsetformat.h"
#include "sky/elementsetsources.h"
#include "sky/utctime.h"
#include "station/schedulerunner.h"
#include "station/station.h"
#include "tracking/rotatorreach.h"
#include "tracking/stationclock.h"

#include <QFutureWatcher>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

namespace slew::ui {

using schedule::ScheduledPass;
using tracking::TrackTarget;

namespace {

constexpr char kTargetsKey[] = "schedule/targets";
constexpr int kSpecRole = Qt::UserRole;
constexpr double kPreviewHours = 24.0;

} // namespace

SchedulePanel::SchedulePanel(station::Station *station, QWidget *parent) : QWidget(parent), m_station(station)
{
    setObjectName(QStringLiteral("schedulePanel"));
    m_list = new QListWidget;
    m_list->setObjectName(QStringLiteral("scheduleTargets"));
    m_list->setDragDropMode(QAbstractItemView::InternalMove);
    m_list->setDefaultDropAction(Qt::MoveAction);
    m_list->setToolTip(tr("The first is the highest priority: drag to reorder"));
    m_list->setMinimumHeight(60);
    m_add = new QLineEdit;
    m_add->setObjectName(QStringLiteral("scheduleAdd"));
    m_add->setPlaceholderText(tr("satellite, sun, moon, azel:…"));
    // What it takes, readable however narrow the window: the page scrolls instead.
    m_add->setMinimumWidth(m_add->fontMetrics().horizontalAdvance(m_add->placeholderText()) + 24);
    m_add->setToolTip(tr("A satellite of the loaded element sets (by name or catalogue number), sun, moon, "
                         "azel:AZ,EL (a fixed direction) or radec:RA,DEC (a radio source)"));
    auto *add = new QPushButton(tr("Add"));
    add->setObjectName(QStringLiteral("scheduleAddButton"));
    add->setAutoDefault(false);
    auto *remove = new QPushButton(tr("Remove"));
    remove->setObjectName(QStringLiteral("scheduleRemove"));
    remove->setAutoDefault(false);
    m_refusal = new QLabel;
    m_refusal->setObjectName(QStringLiteral("scheduleRefusal"));
    m_refusal->setWordWrap(true);
    m_refusal->setStyleSheet(refusedText());
    m_refusal->hide();
    m_run = new QPushButton;
    m_run->setObjectName(QStringLiteral("scheduleRun"));
    m_run->setAutoDefault(false);
    m_state = new QLabel;
    m_state->setObjectName(QStringLiteral("scheduleState"));
    m_state->setWordWrap(true);
    m_timeline = new ScheduleTimeline;
    m_table = new QTableWidget(0, 4);
    m_table->setObjectName(QStringLiteral("schedulePasses"));
    m_table->setHorizontalHeaderLabels({tr("UTC"), tr("Target"), tr("Max el"), tr("Decision")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setWordWrap(false);

    auto *targets = new QGroupBox(tr("Targets by priority"));
    targets->setObjectName(QStringLiteral("scheduleTargetsGroup"));
    auto *targetsLayout = new QHBoxLayout(targets);
    targetsLayout->setContentsMargins(6, 2, 6, 4);
    targetsLayout->addWidget(m_list, 1);
    auto *side = new QVBoxLayout;
    side->addWidget(m_add);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(add);
    buttons->addWidget(remove);
    side->addLayout(buttons);
    side->addWidget(m_refusal);
    side->addStretch(1);
    side->addWidget(m_run);
    targetsLayout->addLayout(side, 1);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    layout->addWidget(targets);
    layout->addWidget(m_state);
    layout->addWidget(m_timeline);
    layout->addWidget(m_table, 1);

    connect(add, &QPushButton::clicked, this, [this] { addTarget(m_add->text()); });
    connect(m_add, &QLineEdit::returnPressed, this, [this] { addTarget(m_add->text()); });
    connect(remove, &QPushButton::clicked, this, [this] {
        delete m_list->currentItem();
        onTargetsChanged();
    });
    // A drag within the list moves rows: the order is the priority.
    connect(m_list->model(), &QAbstractItemModel::rowsMoved, this, &SchedulePanel::onTargetsChanged);
    connect(m_run, &QPushButton::clicked, this, &SchedulePanel::runOrStop);

    station::ScheduleRunner *runner = m_station->scheduleRunner();
    connect(runner, &station::ScheduleRunner::runningChanged, this, [this] {
        if (m_station->scheduleRunner()->isRunning())
            showRunning();
        else
            preview();
    });
    connect(runner, &station::ScheduleRunner::scheduleChanged, this, &SchedulePanel::showRunning);
    connect(runner, &station::ScheduleRunner::currentChanged, this, &SchedulePanel::showRunning);
    connect(runner, &station::ScheduleRunner::logLine, this, &SchedulePanel::message);
    // What the preview depends on.
    connect(m_station, &station::Station::placeChanged, this, &SchedulePanel::preview);
    connect(m_station->elementSets(), &sky::ElementSetSources::setsChanged, this, &SchedulePanel::preview);
    // The list names satellites by the loaded sets: at start they come after
    // the list is restored, and a reload may rename one.
    connect(m_station->elementSets(), &sky::ElementSetSources::setsChanged, this, [this] {
        for (int i = 0; i < m_list->count(); ++i)
            m_list->item(i)->setText(describeSpec(m_list->item(i)->data(kSpecRole).toString()));
    });
    connect(m_station->clock(), &tracking::StationClock::changed, this, &SchedulePanel::preview);
    connect(&m_now, &QTimer::timeout, this, [this] { m_timeline->setNow(m_station->clock()->nowJulian()); });
    m_now.start(5000);

    restoreTargets();
    showRunning();
    preview();
}

QString SchedulePanel::describeSpec(const QString &spec) const
{
    if (spec.startsWith(QLatin1String("norad:"))) {
        const int norad = spec.mid(6).toInt();
        for (const sky::ElementSet &t : m_station->elementSets()->sets())
            if (t.catalogueNumber == norad)
                return t.displayName();
        return tr("NORAD %1 (not in the loaded element sets)").arg(norad);
    }
    if (spec == QLatin1String("sun"))
        return tr("Sun");
    if (spec == QLatin1String("moon"))
        return tr("Moon");
    return spec;
}

bool SchedulePanel::addTarget(const QString &text)
{
    const QString what = text.trimmed();
    QString spec;
    QString error;
    if (what.isEmpty()) {
        error = tr("Name a target: a satellite, sun, moon, azel:AZ,EL or radec:RA,DEC");
    } else if (what.compare(QLatin1String("sun"), Qt::CaseInsensitive) == 0) {
        spec = QStringLiteral("sun");
    } else if (what.compare(QLatin1String("moon"), Qt::CaseInsensitive) == 0) {
        spec = QStringLiteral("moon");
    } else if (const auto fixed = TrackTarget::parseFixedOrCelestial(what, &error)) {
        spec = what;
    } else if (error.isEmpty()) {
        const QList<sky::ElementSet> sets = m_station->elementSets()->sets(); // the search's answer points into it
        const sky::ElementSet *tle = sky::findOneSatellite(sets, what, &error);
        if (tle)
            spec = QStringLiteral("norad:%1").arg(tle->catalogueNumber);
    }
    if (!spec.isEmpty() && targetSpecs().contains(spec))
        error = tr("%1 is in the list already: a target has one priority").arg(describeSpec(spec));
    if (!error.isEmpty()) {
        m_refusal->setText(error);
        m_refusal->show();
        return false;
    }
    m_refusal->hide();
    auto *item = new QListWidgetItem(describeSpec(spec));
    item->setData(kSpecRole, spec);
    m_list->addItem(item);
    m_add->clear();
    onTargetsChanged();
    return true;
}

QStringList SchedulePanel::targetSpecs() const
{
    QStringList specs;
    for (int i = 0; i < m_list->count(); ++i)
        specs << m_list->item(i)->data(kSpecRole).toString();
    return specs;
}

QList<TrackTarget> SchedulePanel::targets(QStringList *missing) const
{
    QList<TrackTarget> out;
    for (const QString &spec : targetSpecs()) {
        TrackTarget t;
        if (spec == QLatin1String("sun")) {
            t.kind = TrackTarget::Kind::Sun;
        } else if (spec == QLatin1String("moon")) {
            t.kind = TrackTarget::Kind::Moon;
        } else if (spec.startsWith(QLatin1String("norad:"))) {
            const int norad = spec.mid(6).toInt();
            bool found = false;
            for (const sky::ElementSet &tle : m_station->elementSets()->sets()) {
                if (tle.catalogueNumber == norad) {
                    t.elements = tle;
                    found = true;
                    break;
                }
            }
            if (!found) {
                if (missing)
                    *missing << describeSpec(spec);
                continue;
            }
        } else if (const auto fixed = TrackTarget::parseFixedOrCelestial(spec, nullptr)) {
            t = *fixed;
        } else {
            continue;
        }
        out.append(t);
    }
    return out;
}

void SchedulePanel::onTargetsChanged()
{
    keepTargets();
    station::ScheduleRunner *runner = m_station->scheduleRunner();
    if (runner->isRunning()) {
        QStringList missing;
        const QList<TrackTarget> list = targets(&missing);
        if (!list.isEmpty())
            runner->setTargets(list);
        return;
    }
    preview();
}

void SchedulePanel::keepTargets()
{
    QSettings().setValue(QLatin1String(kTargetsKey), targetSpecs());
}

void SchedulePanel::restoreTargets()
{
    for (const QString &spec : QSettings().value(QLatin1String(kTargetsKey)).toStringList()) {
        auto *item = new QListWidgetItem(describeSpec(spec));
        item->setData(kSpecRole, spec);
        m_list->addItem(item);
    }
}

void SchedulePanel::preview()
{
    m_run->setText(tr("Run schedule"));
    if (m_station->scheduleRunner()->isRunning())
        return;
    QStringList missing;
    const QList<TrackTarget> list = targets(&missing);
    const std::optional<sky::Site> place = m_station->place();
    if (list.isEmpty() || !place) {
        m_previewing = false;
        show(schedule::Schedule{});
        m_state->setText(!place ? tr("The schedule needs the station: Sky → Station…")
                                : tr("Add targets: the first is followed first where passes overlap."));
        return;
    }
    schedule::ScheduleSettings settings;
    settings.startJulian = m_station->clock()->nowJulian();
    settings.hours = kPreviewHours;
    const session::RotatorSession *session = m_station->session();
    if (session->hasPosition())
        settings.antennaAt = schedule::AntennaPoint{session->azimuth(), session->elevation()};
    const tracking::RotatorReach reach = tracking::reachOf(*session);
    const int generation = ++m_generation;
    m_state->setText(tr("Planning the next %1 hours…").arg(kPreviewHours, 0, 'f', 0));
    auto *watcher = new QFutureWatcher<schedule::Schedule>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, generation, missing] {
        watcher->deleteLater();
        if (generation != m_generation || m_station->scheduleRunner()->isRunning())
            return;
        m_previewing = true;
        show(watcher->result());
        QString text = tr("Preview: %1.").arg(schedule::describeScheduleSummary(m_shown));
        if (!missing.isEmpty())
            text += tr(" Not in the loaded element sets: %1.").arg(missing.join(QStringLiteral(", ")));
        m_state->setText(text);
        emit previewShown();
    });
    watcher->setFuture(QtConcurrent::run([list, place = *place, reach, settings] {
        return schedule::planSchedule(list, place, reach, settings);
    }));
}

void SchedulePanel::showRunning()
{
    station::ScheduleRunner *runner = m_station->scheduleRunner();
    if (!runner->isRunning())
        return;
    ++m_generation; // a preview still being made is of no use now
    m_previewing = false;
    m_run->setText(tr("Stop schedule"));
    show(runner->schedule());
    m_timeline->setCurrent(runner->current());
    QString text;
    if (runner->isPlanning() && runner->schedule().passes.isEmpty())
        text = tr("Running: planning…");
    else
        text = tr("Running: %1.").arg(schedule::describeScheduleSummary(runner->schedule()));
    if (const std::optional<ScheduledPass> &now = runner->current())
        text += tr(" Now: %1 until %2 UTC.")
                    .arg(now->target, sky::utcFromJulian(now->endJulian).toString(QStringLiteral("HH:mm:ss")));
    m_state->setText(text);
}

void SchedulePanel::show(const schedule::Schedule &plan)
{
    m_shown = plan;
    m_timeline->setSchedule(plan);
    m_timeline->setNow(m_station->clock()->nowJulian());
    if (!m_station->scheduleRunner()->isRunning())
        m_timeline->setCurrent(std::nullopt);
    m_table->setRowCount(0);
    for (const ScheduledPass &p : plan.passes) {
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        const QDateTime start = sky::utcFromJulian(p.startJulian);
        const QDateTime end = sky::utcFromJulian(p.endJulian);
        auto cell = [&](int column, const QString &text) {
            auto *item = new QTableWidgetItem(text);
            item->setToolTip(schedule::describeScheduledPass(p));
            if (!p.taken)
                item->setForeground(QColor(0x9a, 0x9f, 0xa8));
            m_table->setItem(row, column, item);
        };
        cell(0, QStringLiteral("%1–%2").arg(start.toString(QStringLiteral("dd HH:mm")),
                                            end.toString(QStringLiteral("HH:mm"))));
        cell(1, QStringLiteral("%1 [%2]").arg(p.target).arg(p.priority + 1));
        cell(2, QStringLiteral("%1°").arg(p.pass.maxElevationDeg(), 0, 'f', 0));
        cell(3, p.taken ? (p.why.isEmpty() ? tr("taken") : tr("taken: %1").arg(p.why)) : tr("dropped: %1").arg(p.why));
    }
}

void SchedulePanel::runOrStop()
{
    station::ScheduleRunner *runner = m_station->scheduleRunner();
    if (runner->isRunning()) {
        m_station->untrack(tr("stopped from the Schedule tab"));
        return;
    }
    QStringList missing;
    const QList<TrackTarget> list = targets(&missing);
    if (list.isEmpty()) {
        emit message(tr("schedule: no target to follow"));
        return;
    }
    if (!m_station->session()->isConnected()) {
        emit message(tr("schedule: it needs a rotator: connect first"));
        return;
    }
    if (const QString refused = m_station->runSchedule(list, station::ScheduleOptions{}).reason(); !refused.isEmpty())
        emit message(tr("schedule: %1").arg(refused));
}

} // namespace slew::ui
