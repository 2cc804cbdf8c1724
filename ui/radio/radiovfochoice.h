// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How the station's radio is used around a pass, as the service's
// --radio-vfos and --radio-restore set it: which VFOs carry the two paths
// (split, VFOA receiving and VFOB transmitting, as most radios and Gpredict
// do; or an IC-9700-style radio in satellite mode, Sub receiving and Main
// transmitting), and whether the radio is put back as it was found once the
// pass is over. Both are kept for the next start. A layout the radio's link
// cannot address (a rigctld not started with -o) is refused in words
// under the choice and the radio keeps split.

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;

namespace slew::station {
class DopplerRadio;
}

namespace slew::ui {

class RadioVfoChoice : public QWidget {
    Q_OBJECT
public:
    // The radio must outlive the widget. Restores the kept choices.
    // Made before the radio's link, so a link made then already uses the
    // layout chosen.
    explicit RadioVfoChoice(station::DopplerRadio *radio, QWidget *parent = nullptr);

signals:
    void message(const QString &text); // for the event log

private:
    // The layout chosen, given to the radio (for its link, and the links made after).
    void applyToLink();
    void onLayoutChosen();
    void onRestoreToggled(bool restore);

    station::DopplerRadio *m_radio;
    QComboBox *m_layout;
    QCheckBox *m_restore;
    QLabel *m_refusal;
};

} // namespace slew::ui
