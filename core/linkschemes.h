#pragma once
// Makes every link kind that lives outside core/transport known to
// createLink(): `sim:` (core/sim) and `rotctld://` (core/bridge). Each program and test calls it once at start.

namespace slew {

void registerLinkSchemes();

} // namespace slew
