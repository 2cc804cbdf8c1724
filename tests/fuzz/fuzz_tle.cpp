// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: the TLE reader and what is done with each set it accepts
// (elementsetfuzz.h says what is checked).
//
// Input: a file's bytes (any bytes: a download, a cache, a --tle file).
//
// Built with libFuzzer when SLEW_FUZZ is on (packaging/dev.sh fuzz); the
// normal build replays the seed corpus through it (corpusreplay.cpp).

#include "elementsetfuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    return slew::fuzz::fuzzGpReader(data, size, slew::sky::ElementSetForm::Tle);
}
