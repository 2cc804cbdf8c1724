// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The operator's controls for a remote station: go-to fields checked
// against the travel it published as the operator types, a jog pad whose
// buttons hold a lease while pressed (remote/remotestation.h), Park, Home,
// and a target to track. What each command came to (the station's reply,
// in the gate's own words, or the broker's refusal) shows under them.
// Everything but Stop (which is elsewhere, and always works) is off while
// the station is not live.

#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace slew::remote {
class RemoteStation;
}

namespace slew::ui {

class RemoteControls : public QWidget {
    Q_OBJECT
public:
    explicit RemoteControls(remote::RemoteStation *station, QWidget *parent = nullptr);

    QString message() const;

public slots:
    void setFields(double az, double el);
    bool go();
    void setLive(bool live);
    void showMessage(const QString &text, bool problem);

private:
    QPushButton *jogButton(const QString &text, const QString &name, double az, double el);
    void revalidate();

    remote::RemoteStation *m_station;
    QLineEdit *m_az;
    QLineEdit *m_el;
    QPushButton *m_go;
    QDoubleSpinBox *m_speed;
    QList<QPushButton *> m_jog;
    QPushButton *m_park;
    QPushButton *m_home;
    QLineEdit *m_target;
    QPushButton *m_track;
    QPushButton *m_untrack;
    QLabel *m_message;
};

} // namespace slew::ui
