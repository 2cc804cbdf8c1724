#pragma once
// Azimuth and elevation fields checked against the station's travel while
// the operator types, by the station's own gate as its face previews it
// (face/stationface.h), here or on a broker alike. A position outside it
// is shown as such and the Go button stays off, so nothing out of range is
// ever sent; what the station answers shows under the fields.

#include "face/stationface.h"

#include <QPointF>
#include <QWidget>

#include <optional>

class QLabel;
class QLineEdit;
class QPushButton;

namespace slew::ui {

class GotoPanel : public QWidget {
    Q_OBJECT
public:
    explicit GotoPanel(face::StationFace *station, QWidget *parent = nullptr);

    struct Checked {
        std::optional<double> azimuth; // the position the rotator would be sent to
        std::optional<double> elevation;
        QString message; // what is wrong, or what will happen
        bool azimuthBad = false;
        bool elevationBad = false;
    };
    // Parses and checks the fields as they stand (accepts ',' as the decimal point).
    Checked check() const;

signals:
    // Enter in a field sent the go-to: the field should give up the focus,
    // so that Space, the next key the operator reaches for, is Stop.
    void sentByEnter();
    // A go-to went to the wire: what it is, for the Events log, and where to.
    void moveSent(const QString &what, std::optional<QPointF> target);

public slots:
    void setFields(double az, double el);
    bool go(); // false, with the reason shown, when the fields are not a legal position

private:
    void followAxes(); // an azimuth-only rotator fixes elevation at 0
    void revalidate();
    void showRefusal(const QString &why);

    face::StationFace *m_station;
    bool m_azimuthOnly = false;
    QString m_awaiting; // the id of the go-to the station has yet to answer
    QLineEdit *m_az;
    QLineEdit *m_el;
    QPushButton *m_go;
    QLabel *m_message;
};

} // namespace slew::ui
