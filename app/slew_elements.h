// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `slew --update-elements [URL…]`: refresh element-set sources into the
// window's cache with no window, so a station can refresh from a timer; the
// URLs named join the window's sources. The work is in core/sky's
// ElementSetSources, shared with the window.

bool wantsUpdateElements(int argc, char **argv);

// Returns the exit code: 0 every source refreshed, 1 one or more did not
// (each named), 2 bad arguments or no sources.
int runUpdateElements(int argc, char **argv);

// `slew --update-transponders [URL…]`: the same for the transponder sources
// (core/radio's TransponderSources); the URLs given are kept as the sources.
bool wantsUpdateTransponders(int argc, char **argv);
int runUpdateTransponders(int argc, char **argv);
