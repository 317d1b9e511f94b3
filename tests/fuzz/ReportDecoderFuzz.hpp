// The fuzz target for the Oculus report decoder (device reports are untrusted
// input): any bytes, as a DK1 or DK2 report (the first byte picks the model),
// must decode or be refused with a reason, never read past the buffer, and a
// decoded report must encode back to the same 64 bytes' fields. One of the
// fuzz targets (tests/fuzz/FuzzTargets); the ordinary tests also run it over
// a fixed random and mutated set of inputs.
#pragma once
#include <cstddef>
#include <cstdint>

namespace arp::fuzz {
// 0 always; a violated property aborts (so libFuzzer and the tests both see it).
int report_decoder_one_input(const uint8_t* data, size_t size);
}  // namespace arp::fuzz
