#include "CubeFaceBasis.hpp"

namespace arp::host {

Dir3 memory_texel_direction(int face, int x, int y, int S) {
  const double sc = 2.0 * (x + 0.5) / S - 1.0, tc = 2.0 * (y + 0.5) / S - 1.0;
  switch (face) {
    case 0: return {1, -tc, -sc};
    case 1: return {-1, -tc, sc};
    case 2: return {sc, 1, tc};
    case 3: return {sc, -1, -tc};
    case 4: return {sc, -tc, 1};
    default: return {-sc, -tc, -1};
  }
}

}  // namespace arp::host
