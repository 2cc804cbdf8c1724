// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The station network: every station a broker knows (remote/
// stationdirectory.h), each on a tile with its antenna on a small plot,
// what it does and how old that is, and its alarms; Open shows one in a
// remote station window of its own. `slew --remote mqtts://USER@HOST:8883`
// with no station name opens it.

#include "remote/mqttsettings.h"

#include <QHash>
#include <QMainWindow>
#include <QTimer>

class QGridLayout;
class QLabel;

namespace slew::remote {
class StationDirectory;
}

namespace slew::ui {

class StationTile;

class StationNetworkWindow : public QMainWindow {
    Q_OBJECT
public:
    // The directory must outlive the window (parent it to the window).
    // `settings` opens a station's own window (a connection of its own).
    StationNetworkWindow(remote::StationDirectory *directory, const remote::MqttSettings &settings,
                         QWidget *parent = nullptr);

    StationTile *tile(const QString &name) const { return m_tiles.value(name); }
    int tileCount() const { return int(m_tiles.size()); }

public slots:
    // Opens the station in a remote station window (and returns it).
    QWidget *openStation(const QString &name);

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void addTile(const QString &name);
    void layOut(); // as many tiles a row as the width takes, in name order
    void updateHeader();
    void refresh(const QString &name);
    void refreshAll();

    remote::StationDirectory *m_directory;
    remote::MqttSettings m_settings;
    QGridLayout *m_grid;
    QLabel *m_header;
    QHash<QString, StationTile *> m_tiles;
    int m_columns = 0;
    QTimer m_ages;
};

} // namespace slew::ui
