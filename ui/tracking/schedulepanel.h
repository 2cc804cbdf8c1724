// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Schedule tab: several targets followed by priority, pass after pass,
// without anyone choosing at each AOS (core/station/schedulerunner.h).
//
//   - The targets, in priority order, the first highest: drag one to
//     reorder; add by name or catalogue number (from the loaded element
//     sets), sun, moon, azel:AZ,EL or radec:RA,DEC; kept for the next start.
//   - The next 24 hours on a time line (scheduletimeline.h), a lane a
//     target, and below it every pass with its decision: taken, or dropped
//     and why. Before it runs, the plan is a preview, made again as the
//     targets, the station, the element sets or the clock change; while it
//     runs, it is the station's own plan, with the pass being followed
//     outlined.
//   - Run schedule / Stop schedule. A change to the targets while it runs
//     plans again at once (a pass in progress is kept).

#include "schedule/schedule.h"
#include "tracking/tracktarget.h"

#include <QTimer>
#include <QWidget>

class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QTableWidget;

namespace slew::station {
class Station;
}

namespace slew::ui {

class ScheduleTimeline;

class SchedulePanel : public QWidget {
    Q_OBJECT
public:
    // The station must outlive the panel. Restores the kept targets.
    explicit SchedulePanel(station::Station *station, QWidget *parent = nullptr);

    // Adds a target as the Add field does: false, with the refusal shown,
    // when the text names none.
    bool addTarget(const QString &text);
    // The targets as listed, resolved against the loaded element sets (a
    // satellite they do not hold is left out, and said).
    QList<tracking::TrackTarget> targets(QStringList *missing = nullptr) const;
    QStringList targetSpecs() const;

    ScheduleTimeline *timeline() const { return m_timeline; }
    // The plan shown: the station's while it runs, else the preview.
    const schedule::Schedule &shownSchedule() const { return m_shown; }
    bool isPreviewing() const { return m_previewing; }

signals:
    void message(const QString &text); // for the event log
    void previewShown();                // a preview plan is on show (for tests)

private:
    void onTargetsChanged();
    void preview();
    void show(const schedule::Schedule &plan);
    void showRunning();
    void runOrStop();
    void keepTargets();
    void restoreTargets();
    QString describeSpec(const QString &spec) const;

    station::Station *m_station;
    QListWidget *m_list;
    QLineEdit *m_add;
    QLabel *m_refusal;
    QPushButton *m_run;
    QLabel *m_state;
    ScheduleTimeline *m_timeline;
    QTableWidget *m_table;
    schedule::Schedule m_shown;
    bool m_previewing = false;
    int m_generation = 0;
    QTimer m_now; // the time line's now line
};

} // namespace slew::ui
