// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/schedulepanel.h"

#include "operatortheme.h"
#include "tracking/scheduletimeline.h"

#include "face/stationface.h"
#include "face/trackingnow.h"
#include "schedule/scheduletext.h"
#include "sky/utctime.h"

#include <QDateTime>
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

namespace slew::ui {

using face::Outcome;
using schedule::ScheduledPass;

namespace {

constexpr int kSpecRole = Qt::UserRole;
constexpr double kPreviewHours = 24.0;
constexpr int kLongestName = 100; // as a track command takes it

} // namespace

SchedulePanel::SchedulePanel(face::StationFace *face, QWidget *parent) : QWidget(parent), m_face(face)
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
    m_add->setMaxLength(kLongestName);
    m_add->setToolTip(tr("A satellite of the station's element sets (by name, part of it or catalogue number), "
                         "sun, moon, azel:AZ,EL (a fixed direction) or radec:RA,DEC (a radio source)"));
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
    m_run = new QPushButton(tr("Run schedule"));
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

    connect(m_face, &face::StationFace::scheduleChanged, this, &SchedulePanel::showSchedule);
    connect(m_face, &face::StationFace::schedulePreviewed, this, &SchedulePanel::onPreviewed);
    connect(m_face, &face::StationFace::answered, this, &SchedulePanel::onAnswered);
    // What the preview and the targets' names depend on.
    connect(m_face, &face::StationFace::skyChanged, this, &SchedulePanel::askPreview);
    connect(&m_now, &QTimer::timeout, this, [this] { m_timeline->setNow(nowJulian()); });
    m_now.start(5000);

    restoreTargets();
    showSchedule();
    if (!isRunning())
        askPreview();
}

double SchedulePanel::nowJulian() const
{
    return face::julianOfUnixMs(m_face->stationClockMs().value_or(QDateTime::currentMSecsSinceEpoch()));
}

QString SchedulePanel::settingsKey() const
{
    // A station on a broker has a list of its own, by its name.
    return m_face->isLocal() ? QStringLiteral("schedule/targets")
                             : QStringLiteral("schedule/remote/%1/targets").arg(m_face->title());
}

bool SchedulePanel::isRunning() const
{
    const std::optional<face::StationSchedule> s = m_face->schedule();
    return s && s->running;
}

QString SchedulePanel::stateText() const
{
    return m_state->text();
}

void SchedulePanel::refuse(const QString &why)
{
    m_refusal->setText(why);
    m_refusal->show();
    emit targetRefused(why);
}

bool SchedulePanel::addTarget(const QString &text)
{
    QString what = text.trimmed();
    if (what.compare(QLatin1String("sun"), Qt::CaseInsensitive) == 0
        || what.compare(QLatin1String("moon"), Qt::CaseInsensitive) == 0)
        what = what.toLower();
    QString error;
    if (what.isEmpty())
        error = tr("Name a target: a satellite, sun, moon, azel:AZ,EL or radec:RA,DEC");
    else if (what.size() > kLongestName)
        error = tr("A target's name is at most %1 characters").arg(kLongestName);
    else if (targetSpecs().contains(what, Qt::CaseInsensitive) || m_adding.contains(what, Qt::CaseInsensitive))
        error = tr("%1 is in the list already: a target has one priority").arg(what);
    if (!error.isEmpty()) {
        refuse(error);
        return false;
    }
    m_refusal->hide();
    m_adding << what;
    m_add->clear();
    askPreview();
    return true;
}

QStringList SchedulePanel::targetSpecs() const
{
    QStringList specs;
    for (int i = 0; i < m_list->count(); ++i)
        specs << m_list->item(i)->data(kSpecRole).toString();
    return specs;
}

void SchedulePanel::onTargetsChanged()
{
    keepTargets();
    if (!isRunning()) {
        askPreview();
        return;
    }
    // Run again with the new list and the running schedule's own numbers:
    // the station plans again and keeps the pass in progress.
    const QStringList specs = targetSpecs();
    if (specs.isEmpty())
        return;
    const schedule::ScheduleSettings now = m_face->schedule().value_or(face::StationSchedule{}).schedule.settings;
    face::ScheduleRequest request;
    if (now.startJulian > 0) {
        request.hours = now.hours;
        request.minElevationDeg = now.minElevationDeg;
        request.guardSeconds = now.guardSeconds;
    }
    const Outcome sent = m_face->runSchedule(specs, request);
    if (sent.isRefused())
        emit message(tr("schedule: %1").arg(sent.reason()));
    m_runId = sent.id();
}

void SchedulePanel::keepTargets()
{
    QSettings().setValue(settingsKey(), targetSpecs());
}

void SchedulePanel::restoreTargets()
{
    for (QString spec : QSettings().value(settingsKey()).toStringList()) {
        if (spec.startsWith(QLatin1String("norad:")))
            spec = spec.mid(6); // as kept before the station named its targets
        auto *item = new QListWidgetItem(spec);
        item->setData(kSpecRole, spec);
        m_list->addItem(item);
    }
}

void SchedulePanel::askPreview()
{
    const QStringList asked = targetSpecs() + m_adding;
    const bool running = isRunning();
    if (!running)
        m_run->setText(tr("Run schedule"));
    if (asked.isEmpty()) {
        m_previewId.clear();
        m_previewing = false;
        show(schedule::Schedule{});
        m_state->setText(tr("Add targets: the first is followed first where passes overlap."));
        return;
    }
    // While a schedule runs only an added target is asked after: its plan
    // is the station's own.
    if (running && m_adding.isEmpty())
        return;
    face::ScheduleRequest request;
    request.hours = kPreviewHours;
    const Outcome asking = m_face->previewSchedule(asked, request);
    if (asking.isRefused()) {
        m_previewId.clear();
        onAnswered(QString(), asking);
        return;
    }
    m_previewId = asking.id();
    if (!running)
        m_state->setText(tr("Planning the next %1 hours…").arg(kPreviewHours, 0, 'f', 0));
}

void SchedulePanel::onAnswered(const QString &id, const Outcome &outcome)
{
    if (!m_runId.isEmpty() && id == m_runId) {
        m_runId.clear();
        if (outcome.isRefused())
            emit message(tr("schedule: %1").arg(outcome.reason()));
        return;
    }
    if (id != m_previewId || !outcome.isRefused())
        return;
    m_previewId.clear();
    // With no preview the targets added are listed as written; the station
    // names them when it can preview again.
    for (const QString &text : std::exchange(m_adding, {})) {
        auto *item = new QListWidgetItem(text);
        item->setData(kSpecRole, text);
        m_list->addItem(item);
        emit targetAdded(text);
    }
    keepTargets();
    if (!isRunning()) {
        m_previewing = false;
        show(schedule::Schedule{});
        m_state->setText(tr("No preview: %1.").arg(outcome.reason()));
    }
}

void SchedulePanel::onPreviewed(const QString &id, const face::SchedulePreview &preview)
{
    if (id != m_previewId)
        return; // asked before the list changed
    m_previewId.clear();
    QStringList notFound;
    for (int i = 0; i < m_list->count() && i < preview.targets.size(); ++i) {
        const face::NamedTarget &t = preview.targets.at(i);
        QListWidgetItem *item = m_list->item(i);
        item->setText(t.isFound() ? t.name : tr("%1 (not found)").arg(t.asked));
        item->setToolTip(t.problem);
        if (!t.isFound())
            notFound << t.asked;
    }
    bool added = false;
    if (!m_adding.isEmpty()) {
        const int before = m_list->count();
        if (!takeAdded(preview)) {
            onTargetsChanged(); // a duplicate was planned too: ask again
            return;
        }
        added = m_list->count() > before;
        keepTargets();
    }
    if (isRunning()) {
        if (added)
            onTargetsChanged(); // run with the new list
        return;
    }
    if (!preview.notPlanned.isEmpty()) {
        m_previewing = false;
        show(schedule::Schedule{});
        m_state->setText(tr("No preview: %1.").arg(preview.notPlanned));
        return;
    }
    m_previewing = true;
    show(preview.schedule);
    QString text = tr("Preview: %1.").arg(schedule::describeScheduleSummary(m_shown));
    if (!notFound.isEmpty())
        text += tr(" Not found by the station: %1.").arg(notFound.join(QStringLiteral(", ")));
    m_state->setText(text);
    emit previewShown();
}

bool SchedulePanel::takeAdded(const face::SchedulePreview &preview)
{
    const QStringList adding = std::exchange(m_adding, {});
    const qsizetype first = preview.targets.size() - adding.size();
    bool asPlanned = true;
    for (qsizetype i = 0; i < adding.size() && first >= 0; ++i) {
        const face::NamedTarget &t = preview.targets.at(first + i);
        if (!t.isFound()) {
            refuse(t.problem); // found nothing, so planned nothing
            continue;
        }
        if (targetSpecs().contains(t.spec(), Qt::CaseInsensitive)) {
            refuse(tr("%1 is in the list already: a target has one priority").arg(t.name));
            asPlanned = false;
            continue;
        }
        auto *item = new QListWidgetItem(t.name);
        item->setData(kSpecRole, t.spec());
        m_list->addItem(item);
        emit targetAdded(t.spec());
    }
    return asPlanned;
}

void SchedulePanel::showSchedule()
{
    const std::optional<face::StationSchedule> s = m_face->schedule();
    if (s && s->running) {
        m_wasRunning = true;
        showRunning(*s);
    } else if (m_wasRunning) {
        m_wasRunning = false;
        askPreview();
    }
}

void SchedulePanel::showRunning(const face::StationSchedule &running)
{
    m_previewing = false;
    m_run->setText(tr("Stop schedule"));
    show(running.schedule);
    std::optional<ScheduledPass> now;
    if (running.current && *running.current < running.schedule.passes.size())
        now = running.schedule.passes.at(*running.current);
    m_timeline->setCurrent(now);
    QString text;
    if (!running.planned)
        text = tr("Running: planning…");
    else
        text = tr("Running: %1.").arg(schedule::describeScheduleSummary(running.schedule));
    if (now)
        text += tr(" Now: %1 until %2 UTC.")
                    .arg(now->target, sky::utcFromJulian(now->endJulian).toString(QStringLiteral("HH:mm:ss")));
    // Started elsewhere (the service's --track, another window): said, as
    // an edit here runs this list instead.
    QStringList listed;
    for (int i = 0; i < m_list->count(); ++i)
        listed << m_list->item(i)->text();
    if (running.planned && listed != running.schedule.targets)
        text += tr(" By priority: %1 (a change to the list here runs it instead).")
                    .arg(running.schedule.targets.join(QStringLiteral(", ")));
    m_state->setText(text);
}

void SchedulePanel::show(const schedule::Schedule &plan)
{
    m_shown = plan;
    m_timeline->setSchedule(plan);
    m_timeline->setNow(nowJulian());
    if (!isRunning())
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
    if (isRunning()) {
        const Outcome stopped = m_face->stopSchedule();
        if (stopped.isRefused())
            emit message(tr("schedule: %1").arg(stopped.reason()));
        m_runId = stopped.id();
        return;
    }
    const QStringList specs = targetSpecs();
    if (specs.isEmpty()) {
        emit message(tr("schedule: no target to follow"));
        return;
    }
    const std::optional<face::StationState> state = m_face->state();
    if (!state || state->link != u"connected") {
        emit message(tr("schedule: it needs a rotator: connect first"));
        return;
    }
    const Outcome sent = m_face->runSchedule(specs, face::ScheduleRequest{});
    if (sent.isRefused())
        emit message(tr("schedule: %1").arg(sent.reason()));
    m_runId = sent.id();
}

} // namespace slew::ui
