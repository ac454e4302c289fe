// How often the once-per-figure stages ran: Algorithm 1 (decompose) and the
// compatibility check of section 2.1 (issue 27). A morph checks its pair
// once at the boundary (CompatiblePair) and every later stage takes the
// checked pair, so these count figures, not stages; the test
// tests/cpp/test_compatible_pair.cpp reads them around one morph call.
// Relaxed atomics: a count, no ordering, nothing else depends on them.
#pragma once

#include <atomic>

namespace stickmorph::internal {

struct StageCounters {
  std::atomic<long> decompositions{0};        ///< decompose() calls
  std::atomic<long> compatibility_checks{0};  ///< check_compatibility() calls (with decompositions given)
};

/// The process's counters.
StageCounters& stage_counters();

}  // namespace stickmorph::internal
