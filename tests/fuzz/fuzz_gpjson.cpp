// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzz target: the reader of GP data as JSON (CelesTrak's numbers, Space-Track's strings), and the writer of the same form
// on what it accepts (elementsetfuzz.h says what is checked).
//
// Built with libFuzzer when SLEW_FUZZ is on (packaging/dev.sh fuzz); the
// normal build replays the seed corpus through it (corpusreplay.cpp).

#include "elementsetfuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    return slew::fuzz::fuzzGpReader(data, size, slew::sky::ElementSetForm::Json);
}
