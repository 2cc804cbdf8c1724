#include "linkschemes.h"

#include "sim/simulatorscheme.h"

namespace slew {

void registerLinkSchemes()
{
    sim::registerSimulatorScheme();
}

} // namespace slew
