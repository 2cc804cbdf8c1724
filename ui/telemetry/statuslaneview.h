// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The status chart of the telemetry tab: one lane per register (GS azimuth,
// GS elevation, GE), each a row of coloured stretches labelled with the
// names of the bits set in them ("moving, pointing", "motor error"), under
// the same time axis as the other charts. The lane names stand where the
// other charts have their value labels. Pointing at a stretch shows its
// time, names and raw value as a tooltip.

#include "telemetry/statuslanes.h"

#include <QChartView>

#include <vector>

class QCategoryAxis;

namespace slew::ui {

class StatusLaneView : public QChartView {
    Q_OBJECT
public:
    struct Lane {
        QString name;       // "GS az"
        StatusRegister reg;
        int series;         // the history's series it draws
        bool shown = true;
    };

    // The chart comes with its time axis; the view adds the lane axis.
    StatusLaneView(QChart *chart, std::vector<Lane> lanes, QWidget *parent = nullptr);

    const std::vector<Lane> &lanes() const { return m_lanes; }
    // A lane left out (elevation, on an azimuth-only rotator) gives its
    // room to the others.
    void setLaneShown(int lane, bool shown);
    // What the lanes hold in [fromMs, toMs], one list per lane in lanes() order.
    void setStretches(qint64 fromMs, qint64 toMs, std::vector<std::vector<StatusStretch>> perLane);
    const std::vector<StatusStretch> &stretches(int lane) const { return m_stretches[size_t(lane)]; }
    QCategoryAxis *laneAxis() const { return m_axis; }

    // What lies under `pos` (viewport coordinates), as the tooltip says it:
    // "GS az 12:01:03–12:01:10: moving, pointing (0x06)"; empty off the lanes.
    QString describeAt(QPoint pos) const;

protected:
    void drawForeground(QPainter *painter, const QRectF &rect) override;
    bool viewportEvent(QEvent *event) override;

private:
    std::vector<int> shownLanes() const; // top to bottom
    QRectF plotInScene() const;
    void rebuildAxis();

    std::vector<Lane> m_lanes;
    std::vector<std::vector<StatusStretch>> m_stretches;
    QCategoryAxis *m_axis;
    qint64 m_fromMs = 0;
    qint64 m_toMs = 1;
};

} // namespace slew::ui
