// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Keeps a column of charts on one left edge, so that one moment stands at
// one x in all of them. Qt Charts makes each value axis as wide as its own
// labels ("5" in one chart, "-180" or "GS el" in the next), which moves each
// plot area's left edge; the aligner gives every chart the difference to
// the widest as extra left margin. Charts whose widget is not visible are
// left out until it is shown. It aligns after the charts have laid out,
// never in the middle of their layout.

#include <QObject>

#include <vector>

class QChart;
class QWidget;

namespace slew::ui {

class PlotAreaAligner : public QObject {
    Q_OBJECT
public:
    explicit PlotAreaAligner(QObject *parent = nullptr);

    // `chart` is drawn in `shownBy` (its view, or a box holding it).
    void add(QChart *chart, QWidget *shownBy);
    // Lines the plot areas up now, and leaves each chart laid out.
    void align();
    // Aligns once the event loop is back, however often it is asked.
    void alignSoon();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    struct Entry {
        QChart *chart;
        QWidget *shownBy;
        int extra = 0; // left margin added to line this chart up
    };
    std::vector<Entry> m_entries;
    bool m_pending = false;
};

} // namespace slew::ui
