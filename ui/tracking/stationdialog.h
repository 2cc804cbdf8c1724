// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Sky → Station…: where the antenna stands, as LAT,LON[,HEIGHT_M] or a
// Maidenhead locator, and its horizon mask file (core/sky/horizonmask.h).
// Both are checked as they are typed (the mask file read), OK stays disabled
// while either is wrong, and both are kept in the settings for pass
// prediction, the schedule and tracking.

#include "sky/site.h"

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
    static bool savedStation(sky::Site *out, QString *text = nullptr);

    // The station typed, with the horizon mask named (if any).
    sky::Site station() const { return m_station; }

    void accept() override;

private:
    void check();

    QLineEdit *m_edit = nullptr;
    QLabel *m_feedback = nullptr;
    QLineEdit *m_horizon = nullptr;
    QLabel *m_horizonFeedback = nullptr;
    std::shared_ptr<const sky::HorizonMask> m_mask; // the file's, as last read
    QDialogButtonBox *m_buttons = nullptr;
    sky::Site m_station;
};

} // namespace slew::ui
