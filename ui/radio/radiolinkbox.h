// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Radio panel's link: which radio (an editable list of URIs: the
// built-in simulated radio, a rigctld, the rotator controller's own radio,
// and the last ones used), Connect and Disconnect, and the link's state in
// words, with the tries to open it again after a loss. A URI the station's
// radio refuses is said under the list and changes nothing. The URI and
// whether the radio was connected are kept for the next start.

#include "radio/radiolink.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;

namespace slew::station {
class DopplerRadio;
}

namespace slew::ui {

class RadioLinkBox : public QWidget {
    Q_OBJECT
public:
    // The radio must outlive the box. Restores the kept URI, and connects
    // when the radio was connected at the last exit.
    explicit RadioLinkBox(station::DopplerRadio *radio, QWidget *parent = nullptr);

    // Sets the list to `uri` and connects to it, as the Connect button
    // does; false, with the refusal shown, when the radio refuses the URI.
    bool connectTo(const QString &uri);
    void disconnectRadio();

    // The URIs offered: the last used first, then the usual ones.
    QStringList offeredUris() const;

signals:
    void message(const QString &text); // for the event log

private:
    void onConnectClicked();
    void showState(radio::RadioLink::State state, const QString &detail);
    void showReopen(int attempt, int seconds);
    void showButtons();
    void remember(const QString &uri);
    void fillList(const QString &current);

    station::DopplerRadio *m_radio;
    QComboBox *m_uri;
    QPushButton *m_connect;
    QPushButton *m_disconnect;
    QLabel *m_state;
    QLabel *m_refusal;
    QString m_stateText; // the link's last state, to which a retry is added
};

} // namespace slew::ui
