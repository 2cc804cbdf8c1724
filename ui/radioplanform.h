// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Radio panel's fields for what to tune for a satellite, by hand:
// downlink and uplink frequencies as operators write them (145.8M,
// 435.125 MHz, 1296200k), the receive and transmit modes, which paths get
// Doppler, how the uplink follows the operator's dial, and the calibration
// offsets. Read by the station service's rules (its --downlink, --uplink,
// ... options): a bad field gets its message under it, and no plan is made.
// Room is left for a transponder picker: disabled until transponders are
// loaded.

#include "radioplansettings.h"

#include "radio/radioplan.h"

#include <QWidget>

#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;

namespace slew::ui {

class RadioPlanForm : public QWidget {
    Q_OBJECT
public:
    explicit RadioPlanForm(QWidget *parent = nullptr);

    void setTexts(const RadioPlanTexts &texts);
    RadioPlanTexts texts() const;

    // The plan the fields say, for satellite `noradId` (0: any); nothing,
    // with a message under each bad field, when one is bad.
    std::optional<radio::RadioPlan> readPlan(int noradId);
    // True while some field shows a refusal.
    bool showsRefusal() const;

signals:
    // Return pressed in a field: the operator means Apply.
    void applyAsked();

private:
    QLineEdit *addFrequencyField(const QString &name, const QString &placeholder, const QString &tip);
    QComboBox *addModeField(const QString &name, const QString &tip);
    QLabel *addError(const QString &name);
    void refuse(QWidget *field, QLabel *error, const QString &why);
    void clearRefusals();

    QComboBox *m_transponder;
    QLineEdit *m_downlink, *m_uplink, *m_downlinkOffset, *m_uplinkOffset;
    QComboBox *m_receiveMode, *m_transmitMode, *m_doppler, *m_follows;
    QLabel *m_downlinkError, *m_uplinkError, *m_receiveModeError, *m_transmitModeError, *m_downlinkOffsetError,
        *m_uplinkOffsetError, *m_dopplerError;
};

} // namespace slew::ui
