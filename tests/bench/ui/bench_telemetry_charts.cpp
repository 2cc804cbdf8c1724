// How long the telemetry charts take to redraw a 24-hour window of 10 Hz
// samples (864,000 a series, in all twelve series) and how much memory the
// history holds. Prints the figures; the targets are under 30 ms a redraw
// and under 100 MB.
//
//   build-ui/tests/bench/ui/bench_telemetry_charts

#include "model/telemetryhistory.h"
#include "telemetry/telemetrycharts.h"
#include "telemetry/telemetryrecorder.h"

#include <QApplication>
#include <QDateTime>
#include <QElapsedTimer>
#include <QFile>
#include <QLineSeries>
#include <QPixmap>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using slew::model::TelemetryHistory;
using slew::ui::TelemetryRecorder;

namespace {

double residentMegabytes()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').front().toDouble() / 1024.0;
    }
    return -1;
}

struct Stats {
    double median, worst;
};

template <typename F>
Stats timeRuns(int runs, F &&work)
{
    std::vector<double> ms;
    for (int i = 0; i < runs; ++i) {
        QElapsedTimer t;
        t.start();
        work();
        ms.push_back(double(t.nsecsElapsed()) / 1e6);
    }
    std::sort(ms.begin(), ms.end());
    return {ms[ms.size() / 2], ms.back()};
}

} // namespace

int main(int argc, char *argv[])
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);

    constexpr int kSamples = 24 * 3600 * 10;
    const double rssBefore = residentMegabytes();
    TelemetryHistory history;
    for (int s = 0; s < TelemetryRecorder::SeriesCount; ++s)
        history.addSeries(TelemetryRecorder::seriesLabel(TelemetryRecorder::Series(s)));
    const qint64 end = QDateTime::currentMSecsSinceEpoch();
    const qint64 start = end - qint64(kSamples) * 100;

    QElapsedTimer fill;
    fill.start();
    for (int i = 0; i < kSamples; ++i) {
        const qint64 t = start + qint64(i) * 100;
        const double phase = i / 3000.0;
        for (int s = 0; s < TelemetryRecorder::SeriesCount; ++s)
            history.append(s, t, 90 + 80 * std::sin(phase + s) + (i % 977 == 0 ? 25 : 0));
    }
    const double fillMs = double(fill.elapsed());
    const double rssAfter = residentMegabytes();

    const int columns = 1000;
    const Stats decimate = timeRuns(20, [&] {
        std::size_t points = 0;
        for (int s = 0; s < TelemetryRecorder::SeriesCount; ++s)
            points += std::size_t(history.decimated(s, start, end, columns).size());
        if (points == 0)
            std::abort();
    });

    slew::ui::TelemetryCharts charts(&history);
    charts.resize(1000, 900);
    charts.setPaused(false);
    charts.setWindowMs(24LL * 3600 * 1000);
    charts.show();
    QApplication::processEvents();
    const Stats redraw = timeRuns(10, [&] { charts.redraw(); });
    const Stats redrawAndPaint = timeRuns(10, [&] {
        charts.redraw();
        const QPixmap frame = charts.grab();
        if (frame.isNull())
            std::abort();
    });
    qsizetype plotted = 0;
    for (int s = 0; s < TelemetryRecorder::SeriesCount; ++s) {
        if (const QXYSeries *line = charts.series(TelemetryRecorder::Series(s)))
            plotted += line->count(); // the status registers are lanes, not lines
    }

    std::printf("telemetry history: %d series x %d samples (24 h at 10 Hz) = %lld samples\n",
                int(TelemetryRecorder::SeriesCount), kSamples, (long long)(kSamples) * TelemetryRecorder::SeriesCount);
    std::printf("  fill:                          %.0f ms\n", fillMs);
    std::printf("  history memory (ring buffers): %.1f MB\n", double(history.memoryBytes()) / (1024.0 * 1024.0));
    std::printf("  process RSS growth:            %.1f MB (before %.1f, after %.1f)\n", rssAfter - rssBefore, rssBefore,
                rssAfter);
    std::printf("  decimate all series to %d columns: median %.2f ms, worst %.2f ms\n", columns, decimate.median,
                decimate.worst);
    std::printf("  chart redraw (decimate + replace, 5 charts, %lld points): median %.2f ms, worst %.2f ms\n",
                (long long)plotted, redraw.median, redraw.worst);
    std::printf("  chart redraw + paint to pixmap (1000x900):            median %.2f ms, worst %.2f ms\n",
                redrawAndPaint.median, redrawAndPaint.worst);
    const bool ok = redraw.worst < 30.0 && rssAfter - rssBefore < 100.0;
    std::printf("  targets (redraw < 30 ms, memory < 100 MB): %s\n", ok ? "met" : "NOT met");
    return 0;
}
