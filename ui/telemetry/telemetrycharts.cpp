// SPDX-License-Identifier: GPL-3.0-or-later
#include "telemetry/telemetrycharts.h"

#include "widgets/filechooser.h"

#include "telemetry/statuslaneview.h"
#include "telemetry/telemetrycsv.h"
#include "tracking/rehearsalmarker.h"
#include "widgets/chartaxisticks.h"
#include "widgets/plotareaaligner.h"

#include "tracking/stationclock.h"

#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDateTime>
#include <QDateTimeAxis>
#include <QGraphicsLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineSeries>
#include <QMetaEnum>
#include <QPushButton>
#include <QSaveFile>
#include <QSettings>
#include <QScatterSeries>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <optional>

namespace slew::ui {

using Series = TelemetryRecorder::Series;

namespace {

constexpr qint64 kMinute = 60 * 1000;
constexpr qint64 kMinWindow = kMinute;
constexpr qint64 kMaxWindow = 24 * 60 * kMinute;
constexpr char kWindowKey[] = "telemetry/windowMs";

// The window the operator chose last time, if it is one the list offers.
std::optional<qint64> keptWindowMs()
{
    bool ok = false;
    const qint64 ms = QSettings().value(QLatin1String(kWindowKey)).toLongLong(&ok);
    if (!ok || ms < kMinWindow || ms > kMaxWindow)
        return std::nullopt;
    return ms;
}

// A chart's height holds its plot and its time labels; the heading above
// is extra. Six of them (and the controls) fit a 720-pixel-high window even
// with the alarm banner shown above the tabs (tst_windowlayout).
constexpr int kChartMinimumHeight = 48;

QFont smallFont(QFont font)
{
    font.setPointSizeF(font.pointSizeF() * 0.85);
    return font;
}

bool isCommanded(Series s)
{
    return s == Series::AzCommanded || s == Series::ElCommanded;
}

} // namespace

TelemetryCharts::TelemetryCharts(const model::TelemetryHistory *history, QWidget *parent)
    : QWidget(parent), m_history(history), m_aligner(new PlotAreaAligner(this))
{
    setObjectName(QStringLiteral("telemetryCharts"));
    m_window = new QComboBox;
    m_window->setObjectName(QStringLiteral("chartWindow"));
    for (auto [label, minutes] : {std::pair{tr("1 min"), 1}, {tr("5 min"), 5}, {tr("15 min"), 15}, {tr("1 h"), 60},
                                  {tr("6 h"), 360}, {tr("24 h"), 1440}})
        m_window->addItem(label, qint64(minutes) * kMinute);
    m_window->setCurrentIndex(0);
    m_pause = new QPushButton(tr("Pause"));
    m_pause->setObjectName(QStringLiteral("chartPause"));
    m_pause->setCheckable(true);
    m_export = new QPushButton(tr("Export CSV…"));
    m_export->setObjectName(QStringLiteral("chartExport"));
    m_message = new QLabel;
    m_message->setObjectName(QStringLiteral("chartMessage"));
    for (QPushButton *b : {m_pause, m_export}) {
        b->setAutoDefault(false);
        b->setFocusPolicy(Qt::NoFocus);
    }
    m_rehearsal = new QLabel;
    m_rehearsal->setObjectName(QStringLiteral("chartRehearsal"));
    m_rehearsal->setStyleSheet(RehearsalMarker::markStyle());
    m_rehearsal->setToolTip(tr("The charts' times are the station clock's, a rehearsal's own time, not the real time."));
    m_rehearsal->setWordWrap(true);
    m_rehearsal->hide();

    auto *controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("Window")));
    controls->addWidget(m_window);
    controls->addWidget(m_pause);
    controls->addWidget(m_export);
    controls->addWidget(m_message, 1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(2);
    layout->addLayout(controls);
    // A line of its own: beside the controls it widened the page past
    // what 1280x720 gives the tabs.
    layout->addWidget(m_rehearsal);

    const QColor az(0x4c, 0xd9, 0x64), el(0x3c, 0xb4, 0xf2), azCmd(0xf2, 0xc0, 0x3c), elCmd(0xc0, 0x7c, 0xf2);
    addPanel(QStringLiteral("AzEl"), tr("Az/El"), QStringLiteral("°"),
             {{Series::AzActual, az}, {Series::ElActual, el}, {Series::AzCommanded, azCmd}, {Series::ElCommanded, elCmd}});
    addPanel(QStringLiteral("Speed"), tr("Speed"), QStringLiteral("°/s"), {{Series::AzVelocity, az}, {Series::ElVelocity, el}});
    addPanel(QStringLiteral("Load"), tr("Load"), QString(), {{Series::AzLoad, az}, {Series::ElLoad, el}});
    addPanel(QStringLiteral("Temp"), tr("Temperature"), QStringLiteral("°C"),
             {{Series::Temperature, QColor(0xf2, 0x9a, 0x3c)}});
    addStatusPanel();
    Panel &pointing = addPanel(QStringLiteral("Pointing"), tr("Pointing error"), QStringLiteral("°"),
                               {{Series::PointingError, QColor(0xf2, 0x6b, 0x9a)}}, Drawn::Dots);
    pointing.hiddenUntilRecorded = true;
    pointing.box->hide();
    // Under the pointing error, on the same time axis: the antenna and the
    // radio during one pass, one above the other.
    Panel &doppler = addPanel(QStringLiteral("Doppler"), tr("Doppler error"), QStringLiteral("Hz"),
                              {{Series::ReceiveDopplerError, QColor(0x4c, 0xd9, 0xc8)},
                               {Series::TransmitDopplerError, QColor(0xf2, 0xc0, 0x3c)}},
                              Drawn::Dots);
    doppler.hiddenUntilRecorded = true;
    doppler.box->hide();
    for (Panel &p : m_panels) {
        layout->addWidget(p.box, 1);
        m_aligner->add(p.chart, p.view);
    }

    connect(m_window, &QComboBox::currentIndexChanged, this,
            [this] { setWindowMs(m_window->currentData().toLongLong()); });
    // The operator's choice (activated: a choice made by hand, not by code)
    // is kept for the next start.
    connect(m_window, &QComboBox::activated, this,
            [this] { QSettings().setValue(QLatin1String(kWindowKey), m_window->currentData().toLongLong()); });
    if (const std::optional<qint64> kept = keptWindowMs())
        m_windowMs = *kept;
    connect(m_pause, &QPushButton::toggled, this, &TelemetryCharts::setPaused);
    connect(m_export, &QPushButton::clicked, this, &TelemetryCharts::chooseExportFile);
    connect(&m_timer, &QTimer::timeout, this, &TelemetryCharts::redraw);
    setWindowMs(m_windowMs);
}

void TelemetryCharts::setElevationShown(bool shown)
{
    for (Panel &panel : m_panels) {
        for (const Plotted &p : panel.plotted) {
            if (p.line && TelemetryRecorder::isElevation(p.id))
                p.line->setVisible(shown);
        }
        updateLegend(panel);
    }
    const auto &lanes = m_lanes->lanes();
    for (int i = 0; i < int(lanes.size()); ++i) {
        if (TelemetryRecorder::isElevation(Series(lanes[size_t(i)].series)))
            m_lanes->setLaneShown(i, shown);
    }
}

void TelemetryCharts::setReportsShown(bool inputs, bool statusRegisters)
{
    for (Panel &panel : m_panels) {
        if (panel.key == QLatin1String("Speed") || panel.key == QLatin1String("Load") || panel.key == QLatin1String("Temp"))
            panel.offered = inputs;
        else if (panel.key == QLatin1String("Status"))
            panel.offered = statusRegisters;
        else
            continue;
        panel.box->setVisible(panel.offered);
    }
}

QChart *TelemetryCharts::makeChart(QDateTimeAxis **time) const
{
    auto *chart = new QChart;
    chart->setTheme(QChart::ChartThemeDark);
    chart->setBackgroundRoundness(0);
    chart->setMargins(QMargins(2, 2, 2, 2));
    // The heading above the chart carries the legend; and the frame a
    // chart's layout keeps by default is height a short chart cannot spare.
    chart->legend()->hide();
    chart->layout()->setContentsMargins(0, 0, 0, 0);
    *time = new QDateTimeAxis;
    (*time)->setFormat(QStringLiteral("HH:mm:ss"));
    (*time)->setLabelsFont(smallFont(font()));
    (*time)->setTickCount(6);
    chart->addAxis(*time, Qt::AlignBottom);
    return chart;
}

TelemetryCharts::Panel TelemetryCharts::makePanel(const QString &key, const QString &title, const QString &unit,
                                                  QChartView *view)
{
    Panel p;
    p.key = key;
    p.view = view;
    p.chart = view->chart();
    p.time = qobject_cast<QDateTimeAxis *>(p.chart->axes(Qt::Horizontal).value(0));
    view->setObjectName(QStringLiteral("chart%1View").arg(key));
    view->setRenderHint(QPainter::Antialiasing);
    view->setFrameShape(QFrame::NoFrame);
    view->setMinimumHeight(kChartMinimumHeight);

    QFont titleFont = smallFont(font());
    titleFont.setBold(true);
    p.title = new QLabel(unit.isEmpty() ? title : QStringLiteral("%1 (%2)").arg(title, unit));
    p.title->setObjectName(QStringLiteral("chart%1Title").arg(key));
    p.title->setFont(titleFont);
    p.legend = new QLabel;
    p.legend->setObjectName(QStringLiteral("chart%1Legend").arg(key));
    p.legend->setFont(smallFont(font()));
    p.legend->setTextFormat(Qt::RichText);
    p.legend->setWordWrap(true); // a narrow tab takes a second line, not a cut
    auto *heading = new QHBoxLayout;
    heading->setContentsMargins(4, 0, 4, 0);
    heading->setSpacing(12);
    heading->addWidget(p.title);
    heading->addWidget(p.legend, 1);

    p.box = new QWidget;
    p.box->setObjectName(QStringLiteral("chart%1").arg(key));
    auto *column = new QVBoxLayout(p.box);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);
    column->addLayout(heading);
    column->addWidget(view, 1);
    return p;
}

TelemetryCharts::Panel &TelemetryCharts::addPanel(const QString &key, const QString &title, const QString &unit,
                                                  std::initializer_list<std::pair<Series, QColor>> series, Drawn drawn)
{
    QDateTimeAxis *time = nullptr;
    QChart *chart = makeChart(&time);
    auto *value = new QValueAxis;
    value->setLabelsFont(smallFont(font()));
    // Whole-number labels: they have to fit a chart only a hundred pixels high.
    value->setLabelFormat(QStringLiteral("%.0f"));
    chart->addAxis(value, Qt::AlignLeft);
    const QMetaEnum names = QMetaEnum::fromType<Series>();
    Panel p = makePanel(key, title, unit, new QChartView(chart));
    p.value = value;
    for (const auto &[id, colour] : series) {
        QXYSeries *line = nullptr;
        if (drawn == Drawn::Dots) {
            auto *dots = new QScatterSeries;
            dots->setMarkerSize(4);
            dots->setColor(colour);
            dots->setBorderColor(colour);
            line = dots;
        } else {
            line = new QLineSeries;
            QPen pen(colour, 1.5);
            if (isCommanded(id))
                pen.setStyle(Qt::DashLine);
            line->setPen(pen);
        }
        line->setObjectName(QStringLiteral("series%1").arg(QLatin1String(names.valueToKey(id))));
        line->setName(TelemetryRecorder::seriesLabel(id));
        chart->addSeries(line);
        line->attachAxis(time);
        line->attachAxis(value);
        p.plotted.push_back({id, line, colour, drawn});
    }
    m_panels.push_back(p);
    updateLegend(m_panels.back());
    return m_panels.back();
}

void TelemetryCharts::addStatusPanel()
{
    QDateTimeAxis *time = nullptr;
    QChart *chart = makeChart(&time);
    std::vector<StatusLaneView::Lane> lanes = {
        {TelemetryRecorder::seriesLabel(Series::AzStatus), StatusRegister::AxisStatus, Series::AzStatus},
        {TelemetryRecorder::seriesLabel(Series::ElStatus), StatusRegister::AxisStatus, Series::ElStatus},
        {TelemetryRecorder::seriesLabel(Series::ErrorFlags), StatusRegister::ErrorFlags, Series::ErrorFlags},
    };
    m_lanes = new StatusLaneView(chart, std::move(lanes));
    m_lanes->laneAxis()->setLabelsFont(smallFont(font()));
    Panel p = makePanel(QStringLiteral("Status"), tr("Status"), QString(), m_lanes);
    for (const StatusLaneView::Lane &lane : m_lanes->lanes())
        p.plotted.push_back({Series(lane.series), nullptr, QColor(), Drawn::Lines});
    const QString explained =
        tr("The controller's status register (GS) for each axis and its error register (GE), by the names of "
           "their bits. Point at a stretch for its times and raw value.");
    p.title->setToolTip(explained);
    p.legend->setToolTip(explained);
    m_panels.push_back(p);
    updateLegend(m_panels.back());
}

void TelemetryCharts::updateLegend(Panel &panel)
{
    // A swatch in each line's colour and style, then its name; &nbsp; keeps
    // the two together when the line wraps.
    QStringList entries;
    auto entry = [&entries](const QColor &colour, const QString &swatch, const QString &name) {
        entries << QStringLiteral("<span style=\"color:%1\">%2</span>&nbsp;%3")
                       .arg(colour.name(), swatch, name.toHtmlEscaped().replace(QLatin1Char(' '), QStringLiteral("&nbsp;")));
    };
    if (panel.view == m_lanes) {
        for (StatusTone tone : {StatusTone::Idle, StatusTone::Moving, StatusTone::Pointing, StatusTone::Error})
            entry(toneColour(tone), QStringLiteral("■"), toneName(tone));
    } else {
        for (const Plotted &p : panel.plotted) {
            if (!p.line->isVisible())
                continue;
            const QString swatch = p.drawn == Drawn::Dots ? QStringLiteral("●")
                : isCommanded(p.id)                      ? QStringLiteral("╍")
                                                         : QStringLiteral("━");
            entry(p.colour, swatch, p.line->name());
        }
    }
    panel.legend->setText(entries.join(QStringLiteral(" &nbsp; ")));
}

QXYSeries *TelemetryCharts::series(Series s) const
{
    for (const Panel &p : m_panels)
        for (const Plotted &pl : p.plotted)
            if (pl.id == s)
                return pl.line;
    return nullptr;
}

void TelemetryCharts::setWindowMs(qint64 ms)
{
    m_windowMs = std::clamp(ms, kMinWindow, kMaxWindow);
    const int index = m_window->findData(m_windowMs);
    if (index >= 0 && index != m_window->currentIndex())
        m_window->setCurrentIndex(index);
    // About one redraw per pixel's worth of time, within 4 Hz .. 0.2 Hz.
    m_timer.start(int(std::clamp<qint64>(m_windowMs / 600, 250, 5000)));
    const QString format = m_windowMs > 6 * 60 * kMinute ? QStringLiteral("HH:mm") : QStringLiteral("HH:mm:ss");
    // Long windows carry a point per pixel column in every series; smoothing
    // thousands of segments costs more than it shows.
    const bool smooth = m_windowMs <= 15 * kMinute;
    for (Panel &p : m_panels) {
        p.time->setFormat(format);
        p.view->setRenderHint(QPainter::Antialiasing, smooth);
    }
    redraw();
}

void TelemetryCharts::followClock(const tracking::StationClock *clock)
{
    m_clock = clock;
    if (clock) {
        connect(clock, &tracking::StationClock::changed, this, &TelemetryCharts::showRehearsal, Qt::UniqueConnection);
        connect(clock, &tracking::StationClock::pausedChanged, this, &TelemetryCharts::showRehearsal,
                Qt::UniqueConnection);
    }
    showRehearsal();
    redraw();
}

void TelemetryCharts::showRehearsal()
{
    const bool rehearsal = m_clock && m_clock->isRehearsal();
    if (rehearsal)
        m_rehearsal->setText(tr("REHEARSAL: the times are the station clock's (%1%2)")
                                 .arg(RehearsalMarker::rateText(m_clock->rate()),
                                      m_clock->isPaused() ? tr(", paused") : QString()));
    m_rehearsal->setVisible(rehearsal);
}

void TelemetryCharts::setPaused(bool paused)
{
    m_paused = paused;
    m_frozenAt = TelemetryRecorder::nowMs(m_clock);
    m_pause->setChecked(paused);
    m_pause->setText(paused ? tr("Resume") : tr("Pause"));
    m_message->setText(paused ? tr("Paused: still recording") : QString());
    if (!paused)
        redraw();
}

void TelemetryCharts::redraw()
{
    if (m_paused)
        return;
    const qint64 to = TelemetryRecorder::nowMs(m_clock);
    const qint64 from = to - m_windowMs;
    for (Panel &p : m_panels) {
        if (!p.offered)
            continue;
        if (p.hiddenUntilRecorded && p.box->isHidden()) {
            const bool recorded = std::any_of(p.plotted.begin(), p.plotted.end(),
                                              [this](const Plotted &pl) { return m_history->sampleCount(pl.id) > 0; });
            if (!recorded)
                continue;
            p.box->show();
        }
        if (p.view == m_lanes)
            redrawLanes(p, from, to);
        else
            redrawPanel(p, from, to);
    }
    ++m_redraws;
}

void TelemetryCharts::redrawPanel(Panel &panel, qint64 from, qint64 to)
{
    const auto &history = *m_history;
    const int columns = std::max(100, int(panel.chart->plotArea().width()));
    double lo = INFINITY, hi = -INFINITY;
    QList<QList<QPointF>> lines;
    lines.reserve(panel.plotted.size());
    for (Plotted &pl : panel.plotted) {
        QList<QPointF> points = history.decimated(pl.id, from, to, columns);
        for (const QPointF &pt : points) {
            lo = std::min(lo, pt.y());
            hi = std::max(hi, pt.y());
        }
        lines.append(std::move(points));
    }
    // A range change lays out every line of the chart again. Emptying the
    // lines first, then setting the axes, then filling the lines lays each
    // one out once: this order is what keeps a 24-hour redraw fast.
    for (Plotted &pl : panel.plotted)
        pl.line->clear();
    // Whole-number steps as many as the height has room for: a flat line
    // (a rotator at rest) keeps readable labels, and no label repeats.
    const AxisTicks ticks = wholeNumberTicks(lo, hi, ticksForHeight(panel.chart->plotArea().height()));
    panel.value->setRange(ticks.min, ticks.max);
    panel.value->setTickType(QValueAxis::TicksDynamic);
    panel.value->setTickAnchor(ticks.firstTick);
    panel.value->setTickInterval(ticks.step);
    panel.time->setRange(QDateTime::fromMSecsSinceEpoch(from), QDateTime::fromMSecsSinceEpoch(to));
    for (qsizetype i = 0; i < lines.size(); ++i)
        panel.plotted[i].line->replace(lines[i]);
}

void TelemetryCharts::redrawLanes(Panel &panel, qint64 from, qint64 to)
{
    const int columns = std::max(100, int(panel.chart->plotArea().width()));
    std::vector<std::vector<StatusStretch>> stretches;
    for (const StatusLaneView::Lane &lane : m_lanes->lanes())
        stretches.push_back(statusStretches(*m_history, lane.series, from, to, columns));
    panel.time->setRange(QDateTime::fromMSecsSinceEpoch(from), QDateTime::fromMSecsSinceEpoch(to));
    m_lanes->setStretches(from, to, std::move(stretches));
}

bool TelemetryCharts::exportCsv(const QString &path, QString *error) const
{
    const qint64 to = m_paused ? m_frozenAt : TelemetryRecorder::nowMs(m_clock);
    const qint64 from = to - m_windowMs;
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error)
            *error = tr("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    // A write that fails makes commit() fail: one check covers both.
    writeTelemetryCsv(file, *m_history, telemetryCsvColumns(), from, to);
    if (!file.commit()) {
        if (error)
            *error = tr("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

void TelemetryCharts::chooseExportFile()
{
    chooseFile(this, FileChoice::Save, tr("Export telemetry"), QStringLiteral("telemetry.csv"), tr("CSV files (*.csv)"),
               [this](const QString &path) {
                   QString error;
                   m_message->setText(exportCsv(path, &error) ? tr("Exported to %1").arg(path) : error);
               });
}

} // namespace slew::ui
