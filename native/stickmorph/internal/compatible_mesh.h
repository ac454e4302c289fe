// The working form of a compatible triangulation while it is built
// (paper, sections 4.1-4.2): one list of triangles over nodes that have a
// position in each polygon of the pair, and the small operations that every
// stage of the construction shares.
//
// Nodes 0..corners-1 are the polygon's corners, in order (several corners
// can be the same figure vertex: a polygon of a stick figure goes round both
// sides of an edge, section 3); the rest are Steiner vertices.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <unordered_set>
#include <utility>
#include <vector>

#include "stickmorph/compatible_triangulation.h"

namespace stickmorph::internal {

using Triangle = std::array<int, 3>;

/// Smallest angle (radians) of a triangle that the construction creates from
/// existing vertices (redundancy removal, shared diagonals). Exact arithmetic
/// would accept thinner ones whose positivity is only rounding; the morph's
/// convex weights need tan of half-angles that stay finite.
constexpr double kMinNewAngle = 1e-6;

/// A triangulation embedded in both polygons of a pair.
struct CompatibleMesh {
  int corners = 0;
  std::vector<Vec2> source, target;  ///< #nodes
  std::vector<Triangle> triangles;
  std::vector<char> alive;           ///< per triangle: removal marks triangles dead
};

/// Exact: triangle t is counter-clockwise at positions `pos`.
bool positive(const std::vector<Vec2>& pos, const Triangle& t);

/// The live triangles around each node.
std::vector<std::vector<int>> triangles_around(const CompatibleMesh& mesh);

/// Link of an interior node v whose live triangles are `star`: its
/// neighbours in counter-clockwise order, or empty if the star is not one
/// closed fan.
std::vector<int> link_of(const CompatibleMesh& mesh, const std::vector<int>& star, int v);

/// Identity of a node once corners are merged with their figure vertex:
/// two corners at the same vertex are the same point of the triangulation.
long node_key(const PolygonPair& pair, int corners, int node);

/// Identity of the undirected edge a-b by node_key: a construction step that
/// adds an edge whose key exists would double an edge through repeated
/// corners, and the result would not be a simplicial complex.
std::pair<long, long> edge_key(const PolygonPair& pair, int corners, int a, int b);

/// A set of edge_key values. Only membership is ever asked, so a hash set:
/// std::set's tree walks and node allocations were a tenth of a
/// 10^3-vertex polygon's triangulation (perf, section 4.2's reduction and
/// the spiderweb's splits).
struct EdgeKeyHash {
  std::size_t operator()(const std::pair<long, long>& key) const noexcept {
    return std::hash<long>()(key.first) * 0x9E3779B97F4A7C15ull ^ std::hash<long>()(key.second);
  }
};
using EdgeKeySet = std::unordered_set<std::pair<long, long>, EdgeKeyHash>;

/// Smallest angle of every triangle, in the source and in the target.
double mesh_min_angle(const CompatibleMesh& mesh);

}  // namespace stickmorph::internal
