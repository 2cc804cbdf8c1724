// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Sky → Station…: where the antenna stands, as LAT,LON[,HEIGHT_M] or a
// Maidenhead locator. The text is checked as it is typed (core/sky's
// parseStation), OK stays disabled while it is wrong, and the station is
// kept in the settings for pass prediction and tracking.

#include "sky/station.h"

#include <QDialog>

class QDialogButtonBox;
class QLabel;
class QLineEdit;

namespace slew::ui {

class StationDialog : public QDialog {
    Q_OBJECT
public:
    explicit StationDialog(QWidget *parent = nullptr);

    // The station the settings hold; false when none has been set.
    static bool savedStation(sky::Station *out, QString *text = nullptr);

    sky::Station station() const { return m_station; }

    void accept() override;

private:
    void check();

    QLineEdit *m_edit = nullptr;
    QLabel *m_feedback = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
    sky::Station m_station;
};

} // namespace slew::ui
