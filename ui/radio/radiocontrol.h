// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The radio as every station window shows it, through the station's face
// (face/stationface.h): a line with its link, who has its dial and where
// it is tuned, and the button that takes the dial from the Doppler
// steering or hands it back. The same for a station in this process and
// one on a broker; the local Radio tab has the rest (the link, the plan,
// the passband) behind the window's local door.

#include <QWidget>

class QLabel;
class QPushButton;

namespace slew::face {
class StationFace;
struct StationState;
}

namespace slew::ui {

// "Radio: connected · Doppler steering tunes it · receive 435.123 456 MHz,
// transmit 145.912 345 MHz"; "Radio: none set" before one is.
QString describeRadio(const face::StationState &state);

class RadioStateLine : public QWidget {
    Q_OBJECT
public:
    // The face must outlive the line.
    explicit RadioStateLine(face::StationFace *face, QWidget *parent = nullptr);
    QString text() const;

private:
    void showState();
    face::StationFace *m_face;
    QLabel *m_line;
};

// "Stop radio control" / "Resume radio control", as the state says the dial
// is held; a refusal (handing back from afar under the operator's hold) is
// said as a message.
class RadioControlButton : public QWidget {
    Q_OBJECT
public:
    explicit RadioControlButton(face::StationFace *face, QWidget *parent = nullptr);
    QPushButton *button() const { return m_button; }

signals:
    void message(const QString &text);

private:
    void showState();
    void toggle();
    face::StationFace *m_face;
    QPushButton *m_button;
    QString m_awaiting; // the answer from afar still to come
};

} // namespace slew::ui
