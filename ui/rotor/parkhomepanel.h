// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Park and Home. Homing (RESET) runs against the end stops and can take a
// while, so it shows progress until GS reports both axes idle again, and can
// be cancelled (which stops the rotator). Nothing here blocks or pops up.
//
// "Idle again" needs the homing to have been seen moving first. GS is polled
// about once a second, so a short homing (a few degrees from the switches)
// can start and end between two GS answers, more so on a loaded machine; the
// position, polled ten times as often, moving away from where it was when
// Home was pressed counts as moving too.
//
// It asks and watches through the station's face (face/stationface.h), here
// or on a broker alike: a station's answer that comes later shows as any.

#include "face/stationface.h"

#include <QPointF>
#include <QTimer>
#include <QWidget>

#include <optional>

class QLabel;
class QProgressBar;
class QPushButton;

namespace slew::ui {

class ParkHomePanel : public QWidget {
    Q_OBJECT
public:
    static constexpr int kHomingTimeoutMs = 180000;

    explicit ParkHomePanel(face::StationFace *station, QWidget *parent = nullptr);

    bool isHoming() const { return m_homing; }

public slots:
    bool park();
    bool home();
    void cancelHoming();  // stops the rotator
    void abandonHoming(); // Stop was pressed elsewhere: just stop waiting
    void moveEnded();     // the park the message describes has ended

signals:
    void moveSent(const QString &what, std::optional<QPointF> target); // park
    void homingStarted();
    void homingFinished(bool ok, const QString &message);

private:
    void follow(const face::StationState &state);
    // `statusChanged`: the state brings a new GS reading; `homingFailed`:
    // the error register has just said homing failed.
    void followHoming(const face::StationState &state, bool statusChanged, bool homingFailed);
    void finish(bool ok, const QString &message);
    void updateEnabled();
    QString parkText() const; // where PARK goes, or that it is not read yet
    void refused(const QString &what, const QString &why);

    face::StationFace *m_station;
    face::StationState m_state; // as last said
    QString m_awaiting;         // the id of a park or home the station has yet to answer
    QString m_awaitingWhat;     // "Not parking", "Not homing"
    QPushButton *m_park;
    QPushButton *m_home;
    QPushButton *m_cancel;
    QPushButton *m_clearFault;
    QProgressBar *m_progress;
    QLabel *m_message;
    QTimer m_timeout;
    bool m_homing = false;
    bool m_parking = false; // m_message says where a park is going
    bool m_sawMoving = false;
    bool m_hasStart = false;   // the first fresh position after Home was pressed
    double m_startAz = 0.0, m_startEl = 0.0;
};

} // namespace slew::ui
