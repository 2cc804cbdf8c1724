// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Radio panel's fields for what to tune for a satellite, by hand:
// downlink and uplink frequencies as operators write them (145.8M,
// 435.125 MHz, 1296200k), the receive and transmit modes, which paths get
// Doppler, how the uplink follows the operator's dial, and the calibration
// offsets. Read by the station service's rules (its --downlink, --uplink,
// ... options): a bad field gets its message under it, and no plan is made.
// Or from the tracked satellite's transponders (the station's cache of
// SatNOGS DB and Gpredict lists): picking one fills the fields from it,
// which the operator may then change (a calibration offset, a mode).

#include "radio/radioplansettings.h"

#include "radio/radioplan.h"
#include "radio/transponder.h"

#include <QList>

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

    // The satellite's transponders to pick from (none: the picker is off).
    // The fields are left as they are.
    void setTransponders(const QList<radio::Transponder> &transponders);
    // Fills the fields from the transponder at `index` of those set, as
    // picking it does.
    void pickTransponder(int index);

signals:
    // Return pressed in a field: the operator means Apply.
    void applyAsked();
    // Something the operator should know of a transponder picked (a mode
    // left as the radio has it).
    void noted(const QString &text);

private:
    QLineEdit *addFrequencyField(const QString &name, const QString &placeholder, const QString &tip);
    QComboBox *addModeField(const QString &name, const QString &tip);
    QLabel *addError(const QString &name);
    void refuse(QWidget *field, QLabel *error, const QString &why);
    void clearRefusals();

    QComboBox *m_transponder;
    QList<radio::Transponder> m_transponders;
    QLineEdit *m_downlink, *m_uplink, *m_downlinkOffset, *m_uplinkOffset;
    QComboBox *m_receiveMode, *m_transmitMode, *m_doppler, *m_follows;
    QLabel *m_downlinkError, *m_uplinkError, *m_receiveModeError, *m_transmitModeError, *m_downlinkOffsetError,
        *m_uplinkOffsetError, *m_dopplerError;
};

} // namespace slew::ui
