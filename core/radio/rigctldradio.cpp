// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigctldradio.h"

namespace slew::radio {

RigctldRadioLink::RigctldRadioLink(QString uri, QString host, quint16 port, QObject *parent)
    : ScriptedRadioLink(std::move(uri), std::make_unique<RigctldPerformer>(std::move(host), port), parent)
{
}

} // namespace slew::radio
