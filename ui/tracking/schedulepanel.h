// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Schedule page: several targets followed by priority, pass after pass,
// without anyone choosing at each AOS, for a station in this process and
// one on a broker alike (through its face, face/stationface.h).
//
//   - The targets, in priority order, the first highest: drag one to
//     reorder; add by name, part of a name or catalogue number (the
//     station finds it among its element sets, as its track command does),
//     sun, moon, azel:AZ,EL or radec:RA,DEC; kept for the next start (one
//     list for this station, one for each station on a broker).
//   - The next 24 hours on a time line (scheduletimeline.h), a lane a
//     target, and below it every pass with its decision: taken, or dropped
//     and why. Before it runs, the plan is the station's preview, asked
//     again as the targets, the station's place, element sets or clock
//     change; while it runs, it is the station's own plan, with the pass
//     being followed outlined.
//   - Run schedule / Stop schedule. A change to the targets while it runs
//     plans again at once (a pass in progress is kept).
//
// The station names each target: an added one joins the list when the
// station's preview has found it (at once here; a round trip from afar),
// and is refused with the station's words when it finds none.

#include "face/schedulepreview.h"
#include "face/stationschedule.h"

#include <QTimer>
#include <QWidget>

class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QTableWidget;

namespace slew::face {
class Outcome;
class StationFace;
}

namespace slew::ui {

class ScheduleTimeline;

class SchedulePanel : public QWidget {
    Q_OBJECT
public:
    // The face must outlive the panel. Restores the kept targets.
    explicit SchedulePanel(face::StationFace *face, QWidget *parent = nullptr);

    // Adds a target as the Add field does. False, with the refusal shown,
    // when the text is refused before the station is asked (empty, listed
    // already); otherwise the station's answer comes as targetAdded or
    // targetRefused.
    bool addTarget(const QString &text);
    // The targets as listed, each as the station is asked for it: a
    // satellite by its catalogue number, any other as written.
    QStringList targetSpecs() const;

    ScheduleTimeline *timeline() const { return m_timeline; }
    // The plan shown: the station's while it runs, else the preview.
    const schedule::Schedule &shownSchedule() const { return m_shown; }
    bool isPreviewing() const { return m_previewing; }
    // The line above the time line ("Preview: …", "Running: … Now: …").
    QString stateText() const;

signals:
    void message(const QString &text); // for the event log
    void previewShown();                // a preview plan is on show (for tests)
    void targetAdded(const QString &spec);
    void targetRefused(const QString &why);

private:
    void onTargetsChanged();
    void askPreview();
    void onPreviewed(const QString &id, const face::SchedulePreview &preview);
    void onAnswered(const QString &id, const face::Outcome &outcome);
    // Lists the added targets the preview found; false when one was
    // refused as listed already (the preview planned it twice).
    bool takeAdded(const face::SchedulePreview &preview);
    void refuse(const QString &why);
    void show(const schedule::Schedule &plan);
    void showRunning(const face::StationSchedule &running);
    void showSchedule();
    void runOrStop();
    bool isRunning() const;
    void keepTargets();
    void restoreTargets();
    double nowJulian() const;
    QString settingsKey() const;

    face::StationFace *m_face;
    QListWidget *m_list;
    QLineEdit *m_add;
    QLabel *m_refusal;
    QPushButton *m_run;
    QLabel *m_state;
    ScheduleTimeline *m_timeline;
    QTableWidget *m_table;
    schedule::Schedule m_shown;
    bool m_previewing = false;
    bool m_wasRunning = false;
    // The preview awaited, and the texts added but not yet named by it.
    QString m_previewId;
    QStringList m_adding;
    QString m_runId; // a run or stop awaited from afar
    QTimer m_now;    // the time line's now line
};

} // namespace slew::ui
