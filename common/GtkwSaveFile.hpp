// GTKWave save files: a readable, grouped view of a VCD written by arpsim --
// one group per module (clocks and scan position first), 1-bit signals as
// binary, counters and positions as decimal, colours and data as hex.
#pragma once
#include <cstdint>
#include <istream>
#include <string>

namespace arp {

// The .gtkw text for the signals declared in `vcd_path`'s header; `dumpfile`
// is what the save file names as its waveform (as given, relative or not).
// The view opens at the VCD's first timestamp, zoomed to show `view` time
// units from there across the wave area (0: its first 200 timestamps, about a
// hundred clock cycles), so a
// window traced late in a run opens where something moves. InputError naming
// the VCD when it cannot be read, declares nothing or has no $enddefinitions.
// The header is read a command a line, as SystemC writes it ($scope, $var,
// $upscope lead their lines; a $comment may span lines; $enddefinitions is
// found anywhere on its line).
std::string gtkw_for_vcd(const std::string& vcd_path, const std::string& dumpfile, int64_t view = 0);
// The same from a stream (`vcd_path` names it in messages); reads only the header and the first 200 timestamps.
std::string gtkw_for_vcd(std::istream& vcd, const std::string& vcd_path, const std::string& dumpfile, int64_t view = 0);

}  // namespace arp
