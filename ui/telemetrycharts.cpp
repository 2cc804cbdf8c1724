// SPDX-License-Identifier: GPL-3.0-or-later
#include "telemetrycharts.h"

#include "chartaxisticks.h"
#include "telemetrycsv.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDateTime>
#include <QDateTimeAxis>
#include <QFileDialog>
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

// A status register holds its value until the next change: draw it so.
QList<QPointF> asSteps(const QList<QPointF> &points, qint64 to)
{
    QList<QPointF> out;
    out.reserve(points.size() * 2 + 1);
    for (qsizetype i = 0; i < points.size(); ++i) {
        if (i > 0)
            out.append(QPointF(points[i].x(), points[i - 1].y()));
        out.append(points[i]);
    }
    if (!points.isEmpty())
        out.append(QPointF(double(to), points.back().y()));
    return out;
}

} // namespace

TelemetryCharts::TelemetryCharts(const model::TelemetryHistory *history, QWidget *parent)
    : QWidget(parent), m_history(history)
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

    const QColor az(0x4c, 0xd9, 0x64), el(0x3c, 0xb4, 0xf2), azCmd(0xf2, 0xc0, 0x3c), elCmd(0xc0, 0x7c, 0xf2);
    addPanel(tr("Az/El"), QStringLiteral("°"),
             {{Series::AzActual, az}, {Series::ElActual, el}, {Series::AzCommanded, azCmd}, {Series::ElCommanded, elCmd}});
    addPanel(tr("Speed"), QStringLiteral("°/s"), {{Series::AzVelocity, az}, {Series::ElVelocity, el}});
    addPanel(tr("Load"), QString(), {{Series::AzLoad, az}, {Series::ElLoad, el}});
    addPanel(tr("Temp"), QStringLiteral("°C"), {{Series::Temperature, QColor(0xf2, 0x9a, 0x3c)}});
    addPanel(tr("Status"), QString(),
             {{Series::AzStatus, az}, {Series::ElStatus, el}, {Series::ErrorFlags, QColor(0xe5, 0x48, 0x48)}},
             Drawn::Steps);
    addPanel(tr("Pointing"), QStringLiteral("°"), {{Series::PointingError, QColor(0xf2, 0x6b, 0x9a)}}, Drawn::Dots);
    m_panels.back().hiddenUntilRecorded = true;
    m_panels.back().view->hide();
    for (Panel &p : m_panels)
        layout->addWidget(p.view, 1);

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
            if (TelemetryRecorder::isElevation(p.id))
                p.line->setVisible(shown);
        }
    }
}

void TelemetryCharts::setReportsShown(bool inputs, bool statusRegisters)
{
    for (Panel &panel : m_panels) {
        const QString name = panel.view->objectName();
        if (name == QLatin1String("chartSpeed") || name == QLatin1String("chartLoad") || name == QLatin1String("chartTemp"))
            panel.offered = inputs;
        else if (name == QLatin1String("chartStatus"))
            panel.offered = statusRegisters;
        else
            continue;
        panel.view->setVisible(panel.offered);
    }
}

void TelemetryCharts::addPanel(const QString &title, const QString &unit,
                               std::initializer_list<std::pair<Series, QColor>> series, Drawn drawn)
{
    Panel p;
    p.chart = new QChart;
    p.chart->setTheme(QChart::ChartThemeDark);
    p.chart->setBackgroundRoundness(0);
    p.chart->setMargins(QMargins(2, 2, 2, 2));
    p.chart->legend()->setAlignment(Qt::AlignTop); // every plot area then has the same width, so times line up
    QFont small = p.chart->legend()->font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    p.chart->legend()->setFont(small);
    p.time = new QDateTimeAxis;
    p.time->setFormat(QStringLiteral("HH:mm:ss"));
    p.time->setLabelsFont(small);
    p.time->setTickCount(6);
    p.value = new QValueAxis;
    p.value->setLabelsFont(small);
    // Whole-number labels and a title without brackets: both have to fit a
    // chart only a hundred pixels high.
    p.value->setLabelFormat(QStringLiteral("%.0f"));
    p.value->setTitleText(unit.isEmpty() ? title : QStringLiteral("%1 %2").arg(title, unit));
    QFont titleFont = small;
    titleFont.setBold(true);
    p.value->setTitleFont(titleFont);
    p.chart->addAxis(p.time, Qt::AlignBottom);
    p.chart->addAxis(p.value, Qt::AlignLeft);
    const QMetaEnum names = QMetaEnum::fromType<Series>();
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
            if (id == Series::AzCommanded || id == Series::ElCommanded)
                pen.setStyle(Qt::DashLine);
            line->setPen(pen);
        }
        line->setObjectName(QStringLiteral("series%1").arg(QLatin1String(names.valueToKey(id))));
        line->setName(TelemetryRecorder::seriesLabel(id));
        p.chart->addSeries(line);
        line->attachAxis(p.time);
        line->attachAxis(p.value);
        p.plotted.push_back({id, line, drawn == Drawn::Steps});
    }
    p.view = new QChartView(p.chart);
    p.view->setObjectName(QStringLiteral("chart%1").arg(QString(title).remove(QLatin1Char('/'))));
    p.view->setRenderHint(QPainter::Antialiasing);
    p.view->setMinimumHeight(110);
    m_panels.push_back(p);
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

void TelemetryCharts::setPaused(bool paused)
{
    m_paused = paused;
    m_frozenAt = QDateTime::currentMSecsSinceEpoch();
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
    const qint64 to = QDateTime::currentMSecsSinceEpoch();
    const qint64 from = to - m_windowMs;
    for (Panel &p : m_panels) {
        if (!p.offered)
            continue;
        if (p.hiddenUntilRecorded && p.view->isHidden()) {
            const bool recorded = std::any_of(p.plotted.begin(), p.plotted.end(),
                                              [this](const Plotted &pl) { return m_history->sampleCount(pl.id) > 0; });
            if (!recorded)
                continue;
            p.view->show();
        }
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
        if (pl.step) {
            // The value in force when the window opens is the last one before it.
            if (points.isEmpty() || points.front().x() > from) {
                std::optional<QPointF> before;
                history.forEachSample(pl.id, from - kMaxWindow, from, [&](qint64 t, double v) { before = QPointF(t, v); });
                if (before)
                    points.prepend(QPointF(double(from), before->y()));
            }
            points = asSteps(points, to);
        }
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

bool TelemetryCharts::exportCsv(const QString &path, QString *error) const
{
    const qint64 to = m_paused ? m_frozenAt : QDateTime::currentMSecsSinceEpoch();
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
    const QString path = QFileDialog::getSaveFileName(this, tr("Export telemetry"), QStringLiteral("telemetry.csv"),
                                                      tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    QString error;
    m_message->setText(exportCsv(path, &error) ? tr("Exported to %1").arg(path) : error);
}

} // namespace slew::ui
