#include "linkschemes.h"

#include "bridge/rotctldlink.h"
#include "sim/simulatorscheme.h"

namespace slew {

void registerLinkSchemes()
{
    sim::registerSimulatorScheme();
    bridge::RotctldLink::registerScheme();
}

} // namespace slew
