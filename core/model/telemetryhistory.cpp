#include "telemetryhistory.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slew::model {

namespace {

constexpr qint64 kRebaseAt = 2'000'000'000;   // ms offset (~23 days) that triggers a rebase
constexpr qint64 kRebaseKeep = 1'000'000'000; // ms of history that keeps positive offsets after it

// Grows a ring buffer's storage one element at a time up to `capacity`,
// doubling the reservation but never past the capacity, so a full ring
// holds exactly `capacity` elements.
template <typename T>
void putAt(std::vector<T> &v, std::size_t slot, const T &value, std::size_t capacity)
{
    if (slot < v.size()) {
        v[slot] = value;
        return;
    }
    if (v.size() == v.capacity())
        v.reserve(std::min(capacity, std::max<std::size_t>(1024, v.capacity() * 2)));
    v.push_back(value);
}

// The min/max of one plot column, with the times they occurred.
struct ColumnExtremes {
    qint64 column = -1;
    qint32 minTime = 0, maxTime = 0;
    float min = 0.0f, max = 0.0f;

    void start(qint64 c, qint32 tMin, float vMin, qint32 tMax, float vMax)
    {
        column = c;
        minTime = tMin;
        min = vMin;
        maxTime = tMax;
        max = vMax;
    }
    void merge(qint32 tMin, float vMin, qint32 tMax, float vMax)
    {
        if (vMin < min) {
            min = vMin;
            minTime = tMin;
        }
        if (vMax > max) {
            max = vMax;
            maxTime = tMax;
        }
    }
    void flush(QList<QPointF> &out, qint64 base) const
    {
        if (column < 0)
            return;
        const QPointF a(double(base + minTime), double(min));
        const QPointF b(double(base + maxTime), double(max));
        if (minTime == maxTime && min == max) {
            out.append(a);
        } else if (minTime <= maxTime) {
            out.append(a);
            out.append(b);
        } else {
            out.append(b);
            out.append(a);
        }
    }
};

} // namespace

TelemetryHistory::TelemetryHistory(qsizetype capacityPerSeries)
    : m_capacity(std::max<qsizetype>(kBlock, capacityPerSeries)), m_blockCapacity(m_capacity / kBlock + 2)
{
}

int TelemetryHistory::addSeries(const QString &name)
{
    Series s;
    s.name = name;
    m_series.push_back(std::move(s));
    return int(m_series.size()) - 1;
}

QString TelemetryHistory::seriesName(int id) const
{
    return id >= 0 && id < seriesCount() ? m_series[size_t(id)].name : QString();
}

int TelemetryHistory::seriesId(const QString &name) const
{
    for (int i = 0; i < seriesCount(); ++i) {
        if (m_series[size_t(i)].name == name)
            return i;
    }
    return -1;
}

qint32 TelemetryHistory::relative(qint64 ms) const
{
    const qint64 r = ms - m_baseMs.value_or(ms);
    return qint32(std::clamp<qint64>(r, std::numeric_limits<qint32>::min(), std::numeric_limits<qint32>::max()));
}

void TelemetryHistory::rebase(qint64 newBaseMs)
{
    // Only after weeks of running: shift every stored offset so new samples
    // fit in 32 bits again. Samples older than the representable range pin
    // to its start, which only sparse series (status changes) can reach.
    const qint64 shift = newBaseMs - *m_baseMs;
    auto moved = [shift](qint32 t) {
        return qint32(std::max<qint64>(std::numeric_limits<qint32>::min(), qint64(t) - shift));
    };
    for (Series &s : m_series) {
        for (qint32 &t : s.times)
            t = moved(t);
        for (Block &b : s.blocks) {
            b.minTime = moved(b.minTime);
            b.maxTime = moved(b.maxTime);
        }
    }
    m_baseMs = newBaseMs;
}

void TelemetryHistory::append(int id, qint64 timeMs, double value)
{
    if (id < 0 || id >= seriesCount() || !std::isfinite(value))
        return;
    if (!m_baseMs)
        m_baseMs = timeMs;
    else if (timeMs - *m_baseMs > kRebaseAt)
        rebase(timeMs - kRebaseKeep);
    Series &s = m_series[size_t(id)];
    qint32 t = relative(timeMs);
    if (s.count > 0)
        t = std::max(t, s.times[slot(s.total - 1)]);
    const float v = float(value);
    const qint64 index = s.total;
    putAt(s.times, slot(index), t, size_t(m_capacity));
    putAt(s.values, slot(index), v, size_t(m_capacity));

    const qint64 block = index / kBlock;
    if (index % kBlock == 0) {
        putAt(s.blocks, blockSlot(block), Block{t, t, v, v}, size_t(m_blockCapacity));
    } else {
        Block &b = s.blocks[blockSlot(block)];
        if (v < b.min) {
            b.min = v;
            b.minTime = t;
        }
        if (v > b.max) {
            b.max = v;
            b.maxTime = t;
        }
    }
    ++s.total;
    s.count = std::min<qsizetype>(s.count + 1, m_capacity);
}

qsizetype TelemetryHistory::sampleCount(int id) const
{
    return id >= 0 && id < seriesCount() ? m_series[size_t(id)].count : 0;
}

std::optional<QPointF> TelemetryHistory::lastSample(int id) const
{
    if (sampleCount(id) == 0)
        return std::nullopt;
    const Series &s = m_series[size_t(id)];
    const std::size_t i = slot(s.total - 1);
    return QPointF(double(*m_baseMs + s.times[i]), double(s.values[i]));
}

std::optional<QPointF> TelemetryHistory::sampleBefore(int id, qint64 ms) const
{
    if (sampleCount(id) == 0)
        return std::nullopt;
    const Series &s = m_series[size_t(id)];
    const qint64 at = lowerBound(s, relative(ms)) - 1;
    if (at < s.oldest())
        return std::nullopt;
    return QPointF(double(*m_baseMs + s.times[slot(at)]), double(s.values[slot(at)]));
}

std::optional<qint64> TelemetryHistory::firstTimeMs() const
{
    std::optional<qint64> first;
    for (const Series &s : m_series) {
        if (s.count == 0)
            continue;
        const qint64 t = *m_baseMs + s.times[slot(s.oldest())];
        first = first ? std::min(*first, t) : t;
    }
    return first;
}

qint64 TelemetryHistory::lowerBound(const Series &s, qint32 t) const
{
    qint64 lo = s.oldest(), hi = s.total;
    while (lo < hi) {
        const qint64 mid = lo + (hi - lo) / 2;
        if (s.times[slot(mid)] < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

qint64 TelemetryHistory::upperBound(const Series &s, qint32 t) const
{
    qint64 lo = s.oldest(), hi = s.total;
    while (lo < hi) {
        const qint64 mid = lo + (hi - lo) / 2;
        if (s.times[slot(mid)] <= t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

QList<QPointF> TelemetryHistory::decimated(int id, qint64 fromMs, qint64 toMs, int columns) const
{
    QList<QPointF> out;
    if (sampleCount(id) == 0 || toMs < fromMs || columns < 1)
        return out;
    const Series &s = m_series[size_t(id)];
    const qint64 base = *m_baseMs;
    const qint32 from = relative(fromMs), to = relative(toMs);
    const qint64 lo = lowerBound(s, from), hi = upperBound(s, to);
    if (hi <= lo)
        return out;

    if (hi - lo <= 2 * qint64(columns)) {
        out.reserve(hi - lo);
        for (qint64 i = lo; i < hi; ++i)
            out.append(QPointF(double(base + s.times[slot(i)]), double(s.values[slot(i)])));
        return out;
    }

    const double width = std::max(1.0, double(qint64(to) - from + 1) / columns);
    const double perMs = 1.0 / width;
    auto columnOf = [&](qint32 t) { return std::min<qint64>(columns - 1, qint64(double(qint64(t) - from) * perMs)); };

    // Physical positions advance with the index instead of being recomputed
    // with a modulo for every sample: this loop runs for every block of every
    // series on every redraw.
    const std::size_t capacity = std::size_t(m_capacity), blockCapacity = std::size_t(m_blockCapacity);
    std::size_t p = slot(lo);
    std::size_t bp = blockSlot(lo / kBlock);
    auto step = [&](std::size_t &at, std::size_t by, std::size_t cap) {
        at += by;
        if (at >= cap)
            at -= cap;
    };

    out.reserve(2 * columns);
    ColumnExtremes col;
    qint64 i = lo;
    while (i < hi) {
        // A whole block inside one column counts as its summary; the block
        // ring holds a summary for every block whose samples are all retained.
        if (i % kBlock == 0 && i + kBlock <= hi) {
            std::size_t lastAt = p + kBlock - 1;
            if (lastAt >= capacity)
                lastAt -= capacity;
            const qint64 c = columnOf(s.times[p]);
            if (c == columnOf(s.times[lastAt])) {
                const Block &b = s.blocks[bp];
                if (c == col.column) {
                    col.merge(b.minTime, b.min, b.maxTime, b.max);
                } else {
                    col.flush(out, base);
                    col.start(c, b.minTime, b.min, b.maxTime, b.max);
                }
                i += kBlock;
                step(p, kBlock, capacity);
                step(bp, 1, blockCapacity);
                continue;
            }
        }
        const qint32 t = s.times[p];
        const float v = s.values[p];
        const qint64 c = columnOf(t);
        if (c == col.column) {
            col.merge(t, v, t, v);
        } else {
            col.flush(out, base);
            col.start(c, t, v, t, v);
        }
        ++i;
        step(p, 1, capacity);
        if (i % kBlock == 0)
            step(bp, 1, blockCapacity);
    }
    col.flush(out, base);
    return out;
}

void TelemetryHistory::forEachSample(int id, qint64 fromMs, qint64 toMs,
                                     const std::function<void(qint64, double)> &visit) const
{
    if (sampleCount(id) == 0 || toMs < fromMs)
        return;
    const Series &s = m_series[size_t(id)];
    const qint64 hi = upperBound(s, relative(toMs));
    for (qint64 i = lowerBound(s, relative(fromMs)); i < hi; ++i)
        visit(*m_baseMs + s.times[slot(i)], double(s.values[slot(i)]));
}

void TelemetryHistory::forEachRow(const std::vector<int> &ids, qint64 fromMs, qint64 toMs,
                                  const std::function<void(qint64, const std::vector<double> &)> &visit) const
{
    if (toMs < fromMs || !m_baseMs)
        return;
    // One cursor per series over its samples in the window; each row takes
    // the earliest time any cursor stands at, and moves those cursors on.
    struct Cursor {
        const Series *series = nullptr;
        qint64 at = 0, end = 0;
    };
    std::vector<Cursor> cursors(ids.size());
    for (std::size_t c = 0; c < ids.size(); ++c) {
        if (sampleCount(ids[c]) == 0)
            continue;
        const Series &s = m_series[size_t(ids[c])];
        cursors[c] = {&s, lowerBound(s, relative(fromMs)), upperBound(s, relative(toMs))};
    }
    std::vector<double> values(ids.size());
    for (;;) {
        std::optional<qint32> time;
        for (const Cursor &c : cursors) {
            if (c.at < c.end)
                time = std::min(time.value_or(c.series->times[slot(c.at)]), c.series->times[slot(c.at)]);
        }
        if (!time)
            return;
        for (std::size_t c = 0; c < cursors.size(); ++c) {
            Cursor &cur = cursors[c];
            values[c] = std::numeric_limits<double>::quiet_NaN();
            for (; cur.at < cur.end && cur.series->times[slot(cur.at)] == *time; ++cur.at)
                values[c] = double(cur.series->values[slot(cur.at)]);
        }
        visit(*m_baseMs + *time, values);
    }
}

std::size_t TelemetryHistory::memoryBytes() const
{
    std::size_t bytes = sizeof(*this);
    for (const Series &s : m_series) {
        bytes += sizeof(Series) + s.times.capacity() * sizeof(qint32) + s.values.capacity() * sizeof(float)
            + s.blocks.capacity() * sizeof(Block);
    }
    return bytes;
}

void TelemetryHistory::clear()
{
    for (Series &s : m_series) {
        s.times = {};
        s.values = {};
        s.blocks = {};
        s.total = 0;
        s.count = 0;
    }
    m_baseMs.reset();
}

} // namespace slew::model
