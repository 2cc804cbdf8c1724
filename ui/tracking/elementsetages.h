// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Tracking tab's line per element-set source: its name, how many sets it
// holds, how old its newest elements are, and when the copy was downloaded;
// in the warning colour when the elements are older than the age limit of
// Sky → Element sets… (the dialog that lists every set with its age).
//
// The age that matters is the elements' epoch, not the file's: SGP4's error
// grows with the time between the epoch and the moment predicted, and a
// fresh download can still carry old elements (a satellite no longer
// observed, a mirror that stopped updating). It is measured against the
// station's clock, since that is the moment the tab predicts for (a
// rehearsal of a 2018 pass with 2018 elements is fine). The download time
// is shown beside it as how current the copy is.

#include <QDateTime>
#include <QList>
#include <QString>
#include <QWidget>

class QLabel;
class QVBoxLayout;

namespace slew::sky {
class ElementSetSources;
}

namespace slew::ui {

// "12 min" under an hour, "5.2 h" under a day, "3.4 days" above: how the
// window says an age.
QString describeAgeDays(double days);
// The hours or days from `then` to now, or "no copy" without one.
QString describeAgeSince(const QDateTime &then);

class ElementSetAges : public QWidget {
    Q_OBJECT
public:
    explicit ElementSetAges(const sky::ElementSetSources *sources, QWidget *parent = nullptr);

    // Rewrites the lines for the station's time and the age limit in days.
    void refresh(double julianNow, double limitDays);
    QList<QLabel *> lines() const { return m_lines; }
    // The line is in the warning colour: its elements are past the limit.
    static bool isStale(const QLabel *line);

private:
    const sky::ElementSetSources *m_sources;
    QVBoxLayout *m_layout;
    QList<QLabel *> m_lines;
};

} // namespace slew::ui
