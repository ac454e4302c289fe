// Skeletons of figures and the invariants of a matching
// (correspondence_skeleton.h; Surazhsky & Gotsman 2001, section 6).
#include "stickmorph/internal/correspondence_skeleton.h"

#include <algorithm>

#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"
#include "stickmorph/exact_predicates.h"

namespace stickmorph::internal {

namespace {

// "2 ends and junctions of degree 3, 3": a skeleton's node degrees in words.
std::string describe_nodes(const Skeleton& skeleton) {
  if (skeleton.figure->edges.empty()) return "a single vertex";
  if (skeleton.is_loop()) return "one closed loop with no junction or end";
  int ends = 0;
  std::vector<int> junctions;
  for (int node : skeleton.nodes) {
    if (skeleton.degree[std::size_t(node)] == 1)
      ++ends;
    else
      junctions.push_back(skeleton.degree[std::size_t(node)]);
  }
  std::sort(junctions.begin(), junctions.end());
  std::string text = plural(ends, "end", "ends");
  if (junctions.empty()) return text + " and no junction";
  text += junctions.size() == 1 ? " and a junction of degree " : " and junctions of degree ";
  for (std::size_t k = 0; k < junctions.size() && k < 12; ++k) text += (k ? ", " : "") + std::to_string(junctions[k]);
  if (junctions.size() > 12) text += ", ... (" + std::to_string(junctions.size()) + " junctions)";
  return text;
}

}  // namespace

Skeleton make_skeleton(const StickFigure& figure) {
  Skeleton skeleton;
  skeleton.figure = &figure;
  skeleton.decomposition = decompose(figure);
  const RotationSystem& rotation = skeleton.decomposition.rotation;
  const std::size_t n = figure.vertices.size(), darts = 2 * figure.edges.size();
  skeleton.degree.assign(n, 0);
  for (std::size_t v = 0; v < n; ++v) skeleton.degree[v] = int(rotation.outgoing_ccw[v].size());
  for (std::size_t v = 0; v < n; ++v)
    if (skeleton.degree[v] != 2) skeleton.nodes.push_back(int(v));
  skeleton.loops = int(figure.edges.size()) - int(n) + 1;
  skeleton.chain_of_dart.assign(darts, -1);
  skeleton.forward.assign(darts, 0);
  skeleton.far_dart.assign(darts, -1);
  skeleton.chain_of_vertex.assign(n, -1);
  skeleton.slot_of_vertex.assign(n, -1);
  // The dart leaving head(d) on the other edge of a degree-2 vertex.
  auto continue_through = [&](int dart) {
    const int head = dart_head(figure, dart);
    const auto& around = rotation.outgoing_ccw[std::size_t(head)];
    return around[0] == dart_twin(dart) ? around[1] : around[0];
  };
  if (skeleton.is_loop()) {
    // Walk the loop counter-clockwise (interior on the left), from vertex 0.
    int dart = rotation.outgoing_ccw[0][0];
    std::vector<int> vertices, edges;
    for (std::size_t k = 0; k < figure.edges.size(); ++k) {
      vertices.push_back(dart_tail(figure, dart));
      edges.push_back(dart_edge(dart));
      dart = continue_through(dart);
    }
    std::vector<Vec2> corners;
    for (int v : vertices) corners.push_back(figure.vertices[std::size_t(v)]);
    if (signed_area_sign(corners) < 0) {
      std::reverse(vertices.begin() + 1, vertices.end());
      std::reverse(edges.begin(), edges.end());
    }
    for (std::size_t k = 0; k < vertices.size(); ++k) {
      skeleton.chain_of_vertex[std::size_t(vertices[k])] = 0;
      skeleton.slot_of_vertex[std::size_t(vertices[k])] = int(k);
    }
    skeleton.chains.push_back(make_track(figure, std::move(vertices), std::move(edges), true));
    skeleton.chain_first.push_back(-1);
    return skeleton;
  }
  for (int node : skeleton.nodes) {
    for (int first : rotation.outgoing_ccw[std::size_t(node)]) {
      if (skeleton.chain_of_dart[std::size_t(first)] >= 0) continue;  // walked from its other end
      std::vector<int> vertices{node}, edges;
      int dart = first;
      while (true) {
        edges.push_back(dart_edge(dart));
        const int head = dart_head(figure, dart);
        vertices.push_back(head);
        if (skeleton.degree[std::size_t(head)] != 2) break;
        dart = continue_through(dart);
      }
      const int chain = int(skeleton.chains.size());
      const int last = dart_twin(dart);
      skeleton.chain_of_dart[std::size_t(first)] = chain;
      skeleton.forward[std::size_t(first)] = 1;
      skeleton.chain_of_dart[std::size_t(last)] = chain;
      skeleton.forward[std::size_t(last)] = 0;
      skeleton.far_dart[std::size_t(first)] = last;
      skeleton.far_dart[std::size_t(last)] = first;
      skeleton.chain_first.push_back(first);
      for (std::size_t k = 1; k + 1 < vertices.size(); ++k) {
        skeleton.chain_of_vertex[std::size_t(vertices[k])] = chain;
        skeleton.slot_of_vertex[std::size_t(vertices[k])] = int(k);
      }
      skeleton.chains.push_back(make_track(figure, std::move(vertices), std::move(edges), false));
    }
  }
  return skeleton;
}

std::string plural(long long count, const char* one, const char* many) {
  return std::to_string(count) + " " + (count == 1 ? one : many);
}

[[noreturn]] void topology_differs(const std::string& what) {
  throw IncompatibleFiguresError(Incompatibility::TopologyDiffers,
                                 "correspond: the figures' topologies cannot be matched: " + what);
}

void compare_invariants(const Skeleton& source, const Skeleton& target) {
  if (source.loops != target.loops)
    topology_differs("the source has " + plural(source.loops, "loop", "loops") + " (independent cycles), the target " +
                     std::to_string(target.loops) +
                     (source.loops == 0 || target.loops == 0 ? " (an open figure cannot become a closed one)" : ""));
  std::vector<int> source_degrees, target_degrees;
  for (int node : source.nodes) source_degrees.push_back(source.degree[std::size_t(node)]);
  for (int node : target.nodes) target_degrees.push_back(target.degree[std::size_t(node)]);
  std::sort(source_degrees.begin(), source_degrees.end());
  std::sort(target_degrees.begin(), target_degrees.end());
  if (source_degrees != target_degrees || source.is_loop() != target.is_loop() ||
      source.figure->edges.empty() != target.figure->edges.empty())
    topology_differs("the source has " + describe_nodes(source) + ", the target " + describe_nodes(target));
}

}  // namespace stickmorph::internal
