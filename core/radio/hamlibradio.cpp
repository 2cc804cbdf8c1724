// SPDX-License-Identifier: GPL-3.0-or-later
#include "hamlibradio.h"

namespace slew::radio {

HamlibRadioLink::HamlibRadioLink(HamlibRadioConfig config, QObject *parent)
    : ScriptedRadioLink(config.uri, std::make_unique<HamlibPerformer>(config), parent)
{
}

int HamlibRadioLink::liveWorkers()
{
    return HamlibWorker::liveCount();
}

} // namespace slew::radio
