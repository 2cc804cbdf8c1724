#pragma once
// Live charts of the recorded telemetry: position actual vs commanded, speed
// (IP7/IP8), load (IP5/IP6), temperature (IP0), the status and error
// registers (GS, GE) as lanes of named states, and the pointing error while
// Slew tracks, and under it the radio's Doppler error on each path, as dots:
// a line would join one pass to the next across the hours between them.
// Those two panels appear once there is something to show, so a window that
// never tracks keeps its room.
// Each chart is headed by a line with its name, unit and legend, read
// across: a title turned on its side beside the axis has only the chart's
// height, a hundred pixels or less, and was cut to "Spe…". The plot areas
// share one left edge, so one moment stands at one x in every chart.
// The window runs from one minute to 24 hours; each redraw asks the history
// for at most two points per pixel column, so a day of 10 Hz samples costs
// no more to draw than a minute. Pausing freezes the view, not the record.
// Following the station clock (followClock), the time axis is that clock's:
// during a rehearsal the rehearsal's own time, and a line above the charts
// says so, as the status bar does.

#include "telemetry/telemetryrecorder.h"

#include <QTimer>
#include <QWidget>

#include <vector>

class QComboBox;
class QLabel;
class QXYSeries;
class QPushButton;
class QChart;
class QChartView;
class QDateTimeAxis;
class QValueAxis;

namespace slew::tracking {
class StationClock;
}

namespace slew::ui {

class PlotAreaAligner;
class StatusLaneView;

class TelemetryCharts : public QWidget {
    Q_OBJECT
public:
    // The history's series are in TelemetryRecorder::Series order.
    explicit TelemetryCharts(const model::TelemetryHistory *history, QWidget *parent = nullptr);

    // The time axis ends at the time `clock` reads (it must outlive this),
    // as the recorder stamps it (TelemetryRecorder::followClock); with
    // none, at this machine's UTC.
    void followClock(const tracking::StationClock *clock);
    // "REHEARSAL: the times are the station clock's (×5)", shown only in a rehearsal.
    QLabel *rehearsalLine() const { return m_rehearsal; }

    qint64 windowMs() const { return m_windowMs; }
    void setWindowMs(qint64 ms); // clamped to 1 min .. 24 h
    bool isPaused() const { return m_paused; }
    // The line (or dots) drawing s; null for the status registers, which
    // are lanes (statusLanes()).
    QXYSeries *series(TelemetryRecorder::Series s) const;
    int redrawCount() const { return m_redraws; }

    // The GS/GE lanes.
    StatusLaneView *statusLanes() const { return m_lanes; }

    // Writes the current window as CSV (telemetrycsv.h: one row per time,
    // one column per series), atomically.
    bool exportCsv(const QString &path, QString *error) const;

    // An azimuth-only rotator: the elevation lines (and their legend
    // entries) and the GS el lane are hidden rather than drawn as a flat 0.
    void setElevationShown(bool shown);
    // What the controller reports beyond its position: the inputs (speed,
    // load, temperature: Easycomm III's IP) and the status and error
    // registers (GS, GE). Panels it cannot fill are hidden rather than left
    // empty (a SPID or GS-232 controller has none of them); the recorded
    // history is kept.
    void setReportsShown(bool inputs, bool statusRegisters);

public slots:
    void setPaused(bool paused);
    void redraw();

private:
    enum class Drawn { Lines, Dots };
    struct Plotted {
        TelemetryRecorder::Series id;
        QXYSeries *line; // null in the status lanes, which are painted, not plotted
        QColor colour;
        Drawn drawn;
    };
    struct Panel {
        QString key;      // names the widgets: chart<key> (the box), chart<key>Title, chart<key>Legend, chart<key>View
        QWidget *box;     // heading and chart: what is shown or hidden
        QLabel *title;
        QLabel *legend;
        QChart *chart;
        QChartView *view;
        QDateTimeAxis *time;
        QValueAxis *value = nullptr; // none in the status lanes
        std::vector<Plotted> plotted;
        bool hiddenUntilRecorded = false;
        bool offered = true; // the controller reports what this panel draws
    };
    Panel &addPanel(const QString &key, const QString &title, const QString &unit,
                    std::initializer_list<std::pair<TelemetryRecorder::Series, QColor>> series,
                    Drawn drawn = Drawn::Lines);
    void addStatusPanel();
    Panel makePanel(const QString &key, const QString &title, const QString &unit, QChartView *view);
    QChart *makeChart(QDateTimeAxis **time) const;
    void updateLegend(Panel &panel);
    void redrawPanel(Panel &panel, qint64 from, qint64 to);
    void redrawLanes(Panel &panel, qint64 from, qint64 to);
    void chooseExportFile();
    void showRehearsal();

    const model::TelemetryHistory *m_history;
    std::vector<Panel> m_panels;
    StatusLaneView *m_lanes = nullptr;
    PlotAreaAligner *m_aligner;
    QComboBox *m_window;
    QPushButton *m_pause;
    QPushButton *m_export;
    QLabel *m_message;
    QLabel *m_rehearsal;
    const tracking::StationClock *m_clock = nullptr;
    QTimer m_timer;
    qint64 m_windowMs = 60 * 1000; // live by default: the last minute
    qint64 m_frozenAt = 0; // the view's right edge while paused
    bool m_paused = false;
    int m_redraws = 0;
};

} // namespace slew::ui
