#pragma once
// A bounded record of telemetry series (position, speed, load, temperature,
// status) for the live charts and CSV export.
//
// A chart never needs more than two points per pixel column: the lowest and
// the highest value in it. Every series therefore keeps, beside its raw
// samples, a min/max summary of each aligned block of kBlock samples, so that
// reducing a 24-hour window (864,000 samples at 10 Hz) to a few thousand
// points touches about one summary per block instead of every sample.
//
// Memory is bounded: each series holds at most `capacity` samples in a ring
// (time as a 32-bit offset in ms, value as a float: 8 bytes a sample) and
// grows to it only as samples arrive.

#include <QList>
#include <QPointF>
#include <QString>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace slew::model {

class TelemetryHistory {
public:
    static constexpr int kBlock = 64;                         // samples per min/max summary
    static constexpr qsizetype kDefaultCapacity = 24 * 3600 * 10; // 24 h at 10 Hz

    explicit TelemetryHistory(qsizetype capacityPerSeries = kDefaultCapacity);

    // Adds a series and returns its id (0, 1, 2, ... in order of adding).
    int addSeries(const QString &name);
    int seriesCount() const { return int(m_series.size()); }
    QString seriesName(int id) const;
    int seriesId(const QString &name) const; // -1 when there is none

    // Times must not go backwards within a series; an earlier time is taken
    // as the latest one, so a clock step never reorders the record.
    void append(int id, qint64 timeMs, double value);

    qsizetype sampleCount(int id) const;
    std::optional<QPointF> lastSample(int id) const; // x: ms since the epoch
    // The newest sample earlier than ms: what a register recorded only on
    // change held when a window opened there.
    std::optional<QPointF> sampleBefore(int id, qint64 ms) const;
    std::optional<qint64> firstTimeMs() const;      // oldest sample of any series

    // The samples in [fromMs, toMs] for a plot `columns` pixels wide: per
    // column the minimum and the maximum, in the order they occurred, so
    // spikes survive any zoom. When there are few samples they come back
    // unreduced. x is ms since the epoch.
    QList<QPointF> decimated(int id, qint64 fromMs, qint64 toMs, int columns) const;

    // Every retained sample in [fromMs, toMs], oldest first.
    void forEachSample(int id, qint64 fromMs, qint64 toMs, const std::function<void(qint64, double)> &visit) const;

    // The series side by side, as a table has them: one call per time at
    // which any of `ids` has a sample in [fromMs, toMs], oldest first, with
    // each series' value at that time in `ids` order (NaN where it has none
    // then). Where one series holds two samples at one time (a clock that
    // stepped back), the later one is the value.
    void forEachRow(const std::vector<int> &ids, qint64 fromMs, qint64 toMs,
                    const std::function<void(qint64, const std::vector<double> &)> &visit) const;

    // Bytes held by the samples and summaries (the ring buffers' capacity).
    std::size_t memoryBytes() const;
    void clear();

private:
    struct Block {
        qint32 minTime = 0;
        qint32 maxTime = 0;
        float min = 0.0f;
        float max = 0.0f;
    };
    struct Series {
        QString name;
        std::vector<qint32> times; // ms after m_baseMs
        std::vector<float> values;
        std::vector<Block> blocks;
        qint64 total = 0; // samples ever appended; a sample's absolute index is its position in that count
        qsizetype count = 0;
        qint64 oldest() const { return total - count; }
    };

    qint32 relative(qint64 ms) const;
    void rebase(qint64 newBaseMs);
    qint64 lowerBound(const Series &s, qint32 t) const; // first index with time >= t
    qint64 upperBound(const Series &s, qint32 t) const; // first index with time > t
    std::size_t slot(qint64 index) const { return std::size_t(index % m_capacity); }
    std::size_t blockSlot(qint64 block) const { return std::size_t(block % m_blockCapacity); }

    qsizetype m_capacity;
    qsizetype m_blockCapacity;
    std::vector<Series> m_series;
    std::optional<qint64> m_baseMs;
};

} // namespace slew::model
