// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The History page of the Tracking tab: the passes the station recorded, newest first, with
// their figures (target, AOS, highest elevation, how each ended, pointing
// RMS and worst, commands, Doppler RMS; a rehearsed pass marked so at its
// AOS), a filter by target, Export CSV…
// of what is listed (passhistorycsv.h), and the picture of the selected
// pass (passreportpicture.h) in a window of its own. It reads the
// Station's pass records and writes nothing into them.

#include "records/passrecord.h"

#include <QList>
#include <QWidget>

class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;
class QTimer;

namespace slew::station {
class Station;
}

namespace slew::ui {

class PassPictureDialog;

class HistoryPanel : public QWidget {
    Q_OBJECT
public:
    // The station must outlive the panel.
    explicit HistoryPanel(station::Station *station, QWidget *parent = nullptr);

    // Reads the passes again; done by itself when a pass begins or ends,
    // the filter changes, or the tab is shown.
    void refresh();
    const QList<records::PassRecord> &listed() const { return m_passes; }
    bool exportCsv(const QString &path, QString *error) const;
    // The selected pass's picture in its own window; null (and a message
    // under the table) when none is selected or it has no samples.
    PassPictureDialog *showSelectedPicture();

signals:
    void message(const QString &text);

protected:
    void showEvent(QShowEvent *event) override;

private:
    void fill();
    void chooseExportFile();
    std::optional<records::PassRecord> selected() const;

    station::Station *m_station;
    QLineEdit *m_filter;
    QPushButton *m_picture;
    QPushButton *m_export;
    QTableWidget *m_table;
    QLabel *m_status;
    QTimer *m_reload;
    QList<records::PassRecord> m_passes;
};

} // namespace slew::ui
