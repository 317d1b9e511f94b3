// Closing a VCD waveform, and knowing it was written whole. SystemC's tracer
// checks none of its writes, so a waveform cut short by a full disk or a
// file-size limit would pass as whole. Its last act on closing (SystemC
// 2.3.4) is a line with the time it was closed, "#<time in the file's unit>":
// a file that does not end with that line lost its end.
#pragma once
#include <systemc>

#include <string>

namespace arp::scm {

// Closes `tf`, whose file is `file` and time unit `unit`; an InputError naming
// `shown` (the name the user gave: `file` may be a temporary) if the file does
// not end at the time it was closed.
void close_vcd_checked(sc_core::sc_trace_file* tf, const std::string& file, const sc_core::sc_time& unit,
                       const std::string& shown);

}  // namespace arp::scm
