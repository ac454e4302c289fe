// Adjacency of a list of triangles: the one mesh-connectivity type of the
// engine.
//
// Every stage that walks a triangulation needs the same two relations: the
// triangles at each node (the star, section 4.2's unit of re-triangulation
// and smoothing) and the triangle on the left of each directed side (the
// neighbour across a side, the twin test of a disk's interior edges, the
// dual tree of section 4.1). They were rebuilt in several places, each with
// its own container; this type builds them once.
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace stickmorph::internal {

using Triangle = std::array<int, 3>;

class TriangleAdjacency {
 public:
  /// Adjacency of `triangles` over nodes 0..nodes-1. With `alive` given,
  /// triangles whose entry is 0 are left out. Node ids must be in range.
  TriangleAdjacency(int nodes, const std::vector<Triangle>& triangles, const std::vector<char>& alive = {});

  int nodes() const { return int(around_.size()); }

  /// The triangles at `node`, in increasing index.
  const std::vector<int>& around(int node) const { return around_[node]; }
  /// All stars at once (for callers that then edit them).
  const std::vector<std::vector<int>>& stars() const { return around_; }

  /// The stars alone, as around() would give them, without indexing the
  /// sides: for callers that only walk stars (the rounding repair builds
  /// them on every failed attempt of a spiderweb of 10^5 triangles, where
  /// the side index would cost more than the repair).
  static std::vector<std::vector<int>> stars_of(int nodes, const std::vector<Triangle>& triangles,
                                                const std::vector<char>& alive = {});

  /// The triangle that has the directed side a -> b (counter-clockwise in
  /// it), or -1; where several have it (an overlap), the first.
  int left_of(int a, int b) const {
    const auto it = side_.find(key(a, b));
    return it == side_.end() ? -1 : it->second / 3;
  }
  /// The slot j of that triangle whose side runs from corner j to corner j+1, or -1.
  int slot_of(int a, int b) const {
    const auto it = side_.find(key(a, b));
    return it == side_.end() ? -1 : it->second % 3;
  }

  /// A directed side used by two triangles: the first such, in triangle
  /// order (the later triangle is `second`).
  struct RepeatedSide {
    int a = -1, b = -1;
    int first = -1, second = -1;
  };
  /// The first repeated side, or one with first == -1.
  const RepeatedSide& repeated_side() const { return repeated_; }

 private:
  std::int64_t key(int a, int b) const { return std::int64_t(a) * std::int64_t(around_.size()) + b; }

  std::vector<std::vector<int>> around_;
  std::unordered_map<std::int64_t, int> side_;  // directed side -> 3 * triangle + slot
  RepeatedSide repeated_;
};

}  // namespace stickmorph::internal
