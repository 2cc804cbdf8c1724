// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The strip across the top of a remote window that says plainly it is
// remote: which station, on which broker, and how old the last state is;
// blue while the station is live, grey with the reason when it is not (the
// broker lost, the station offline or silent), as a lost link dims the
// local window.

#include <QLabel>
#include <QTimer>

namespace slew::remote {
class RemoteStation;
}

namespace slew::ui {

class RemoteBanner : public QLabel {
    Q_OBJECT
public:
    explicit RemoteBanner(remote::RemoteStation *station, QWidget *parent = nullptr);

    // "state 0.4 s old", "no state yet".
    static QString ageText(qint64 ageMs);

public slots:
    void refresh();

private:
    remote::RemoteStation *m_station;
    QTimer m_tick;
};

} // namespace slew::ui
