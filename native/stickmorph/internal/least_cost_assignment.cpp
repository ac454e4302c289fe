// Least-cost assignment, the Hungarian method (least_cost_assignment.h).
#include "stickmorph/internal/least_cost_assignment.h"

#include <cstddef>
#include <limits>

namespace stickmorph::internal {

std::vector<int> least_cost_assignment(const std::vector<std::vector<double>>& cost) {
  const std::size_t k = cost.size();
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  std::vector<double> u(k + 1, 0), v(k + 1, 0);
  std::vector<std::size_t> p(k + 1, 0), way(k + 1, 0);
  for (std::size_t i = 1; i <= k; ++i) {
    p[0] = i;
    std::size_t j0 = 0;
    std::vector<double> least(k + 1, kInfinity);
    std::vector<bool> used(k + 1, false);
    do {
      used[j0] = true;
      const std::size_t i0 = p[j0];
      double delta = kInfinity;
      std::size_t j1 = 0;
      for (std::size_t j = 1; j <= k; ++j)
        if (!used[j]) {
          const double reduced = cost[i0 - 1][j - 1] - u[i0] - v[j];
          if (reduced < least[j]) least[j] = reduced, way[j] = j0;
          if (least[j] < delta) delta = least[j], j1 = j;
        }
      for (std::size_t j = 0; j <= k; ++j)
        if (used[j]) u[p[j]] += delta, v[j] -= delta;
        else least[j] -= delta;
      j0 = j1;
    } while (p[j0] != 0);
    do {
      const std::size_t j1 = way[j0];
      p[j0] = p[j1];
      j0 = j1;
    } while (j0);
  }
  std::vector<int> result(k, -1);
  for (std::size_t j = 1; j <= k; ++j) result[p[j] - 1] = int(j - 1);
  return result;
}

}  // namespace stickmorph::internal
