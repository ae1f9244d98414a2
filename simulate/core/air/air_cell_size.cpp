#include "air/air_cell_size.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "air/mac_grid.h"

namespace dp {

void check_air_cell_size(const SimulationSetup& setup) {
  if (!setup.air) return;
  const AirSettings& a = *setup.air;
  const MacGrid g = mac_grid_covering(a.domain_min, a.domain_max, a.resolution);
  const float limit = 2.0f * setup.support_radius();
  if (g.dx > limit) return;
  const Vec3 e = a.domain_max - a.domain_min;
  const float longest = std::fmax(e.x, std::fmax(e.y, e.z));
  std::ostringstream s;
  int most = static_cast<int>(std::floor(longest / limit)) + 1;
  while (most > 1 && mac_grid_covering(a.domain_min, a.domain_max, most).dx <= limit) --most;
  s << "air cell size " << g.dx << " m (resolution " << a.resolution << " along " << longest
    << " m) must exceed two support radii, " << limit << " m (paper Sec. 4.2); use at most " << most
    << " cells along the longest axis";
  throw std::invalid_argument(s.str());
}

}  // namespace dp
