// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Calibration by the sun or the moon. The operator jogs the antenna onto the
// body (the signal peaks, or the feed's shadow is centred) and presses
// "Aligned on the sun": the calibration offsets that make the reading point
// there are computed (tracking/skyalignment.h), put in the session's profile
// at once, so the plot, the rotctld server and the tracker all use them, and
// remembered for this rotator's link (model/savedcalibration.h).

#include "sky/site.h"
#include "sky/sunmoon.h"

#include <QWidget>

#include <functional>
#include <optional>

class QLabel;
class QPushButton;

namespace slew::session {
class RotatorSession;
}

namespace slew::ui {

class AlignmentPanel : public QWidget {
    Q_OBJECT
public:
    explicit AlignmentPanel(session::RotatorSession *session, QWidget *parent = nullptr);

    void setStation(const std::optional<sky::Site> &station);
    // The time to align at, as a UTC Julian date: the system clock unless a
    // test sets another.
    void setClock(std::function<double()> julianNow) { m_now = std::move(julianNow); }

public slots:
    void alignOn(slew::sky::SkyBody body);
    void clearOffsets();

signals:
    void message(const QString &text);

private:
    void applyOffsets(double az, double el);
    void showOffsets();
    void updateButtons();

    session::RotatorSession *m_session;
    std::optional<sky::Site> m_station;
    std::function<double()> m_now;
    QLabel *m_offsets;
    QLabel *m_result;
    QPushButton *m_sun;
    QPushButton *m_moon;
    QPushButton *m_clear;
};

} // namespace slew::ui
