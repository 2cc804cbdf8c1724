#pragma once
// Named positions: stored from where the rotator is now, recalled with one
// click or Alt and the number shown beside each (KeyboardControl, which the
// window asks first while "Ask before moving" is on). Kept in QSettings, so
// they survive a restart. Recalled and stored through the station's face
// (face/stationface.h), here or on a broker alike.

#include "model/presets.h"
#include "face/stationface.h"

#include <QPointF>
#include <QWidget>

#include <optional>

class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace slew::ui {

class PresetPanel : public QWidget {
    Q_OBJECT
public:
    explicit PresetPanel(face::StationFace *station, QWidget *parent = nullptr);

    const model::PresetList &presets() const { return m_presets; }

public slots:
    bool recall(int index); // 0-based; Alt+1 recalls index 0
    bool storeCurrent(const QString &name);
    bool removeSelected();
    void moveEnded(); // the move a "Going to" line describes has ended

signals:
    void moveSent(const QString &what, std::optional<QPointF> target);

private:
    void refresh();
    void save() const;
    void say(const QString &text, bool error);

    face::StationFace *m_station;
    QString m_awaiting; // the id of a recall the station has yet to answer
    model::PresetList m_presets;
    QListWidget *m_list;
    QLineEdit *m_name;
    QPushButton *m_store;
    QPushButton *m_remove;
    QLabel *m_message;
    bool m_going = false; // m_message says where a recalled preset is going
};

} // namespace slew::ui
