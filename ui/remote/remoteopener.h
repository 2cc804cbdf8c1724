// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Opens what a broker address names (remote/brokeraddress.h): one
// station's remote window when the address ends in /NAME, the station
// network window when it does not. For `slew --remote` and the window's
// File → Open remote station….

#include "remote/brokeraddress.h"

class QMainWindow;

namespace slew::ui {

// The window, shown, deleted when closed, with its broker connection
// inside it; null with *error when the connection cannot be made (a CA
// file that cannot be used, say). A broker that does not answer is not an
// error: the window opens and says so.
QMainWindow *openRemoteWindow(const remote::BrokerAddress &address, const QString &password, QString *error);

} // namespace slew::ui
