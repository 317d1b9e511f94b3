// Slot i of a ring of n slots, for 0 <= i < 2n (a head plus a count, or a
// head plus one): a compare and a subtraction. The ring sizes are run-time
// values, so `i % n` is a 64-bit divide -- 10 to 20 cycles, several times a
// pixel clock in every FIFO and register stage of the timed models.
#pragma once
#include <cstddef>

namespace arp::stage {

inline size_t ring_index(size_t i, size_t n) { return i < n ? i : i - n; }

}  // namespace arp::stage
