// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A target to track by name, for a station seen from afar, through its
// face (face/stationface.h): what it came to (done, the station's answer
// in its own words, or the broker's refusal) shows under it. Everything
// else in the control column is the station window's own (go-to, jog,
// Park and Home, presets). Off while the station is not live.

#include "face/outcome.h"

#include <QHash>
#include <QWidget>

class QLabel;
class QLineEdit;
class QPushButton;

namespace slew::face {
class StationFace;
}

namespace slew::ui {

class RemoteControls : public QWidget {
    Q_OBJECT
public:
    explicit RemoteControls(face::StationFace *station, QWidget *parent = nullptr);

    QString message() const;

public slots:
    void setLive(bool live);
    void showMessage(const QString &text, bool problem);

private:
    // What an intent came to; an answer still to come is waited for by id.
    void said(const QString &what, const face::Outcome &outcome);

    face::StationFace *m_station;
    QLineEdit *m_target;
    QPushButton *m_track;
    QPushButton *m_untrack;
    QLabel *m_message;
    QHash<QString, QString> m_awaiting; // id -> what was asked
};

} // namespace slew::ui
