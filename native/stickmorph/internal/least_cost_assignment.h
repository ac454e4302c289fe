// The assignment problem: rows to columns at least total cost.
//
// Used by the correspondence of figures of several parts (issue 14) to pair
// the parts of one nesting depth; the Hungarian method with potentials,
// O(k^3), exact on the given costs (no heuristic pairing).
#pragma once

#include <vector>

namespace stickmorph::internal {

// The assignment of least total cost (the Hungarian method with
// potentials, O(k^3)): row i gets column result[i].
std::vector<int> least_cost_assignment(const std::vector<std::vector<double>>& cost);

}  // namespace stickmorph::internal
