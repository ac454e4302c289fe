// Keys drawn separately, matched onto one common figure; see
// key_pose_correspondence.h.
#include "stickmorph/key_pose_correspondence.h"

#include <chrono>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"

namespace stickmorph {
namespace {

std::string key_name(std::size_t k) { return "key " + std::to_string(k + 1); }

std::string pair_name(std::size_t k) { return key_name(k) + " and " + key_name(k + 1) + ": "; }

std::vector<std::array<std::int64_t, 2>> wide_edges(const std::vector<Edge>& edges) {
  std::vector<std::array<std::int64_t, 2>> wide;
  wide.reserve(edges.size());
  for (const Edge& e : edges) wide.push_back({e[0], e[1]});
  return wide;
}

Vec2 along(const Vec2& a, const Vec2& b, double f) { return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])}; }

double distance(const Vec2& a, const Vec2& b) { return std::hypot(b[0] - a[0], b[1] - a[1]); }

// Where each common vertex is on key k's own drawing. The common vertices
// that are key k's vertices are known (`vertex_of`); every other one is
// interior to a path of such non-key vertices between two key vertices a
// and b, which is the subdivided key edge (a, b): its fraction is its arc
// length along the path over the path's length (the path is straight: its
// points were placed on that one edge).
std::vector<MatchedPlace> places_on_key(const StickFigure& common, const StickFigure& key,
                                        const std::vector<int>& vertex_of, std::size_t k) {
  const std::size_t m = common.vertices.size();
  std::vector<MatchedPlace> places(m);
  std::vector<int> common_of(key.vertices.size(), -1);
  for (std::size_t i = 0; i < m; ++i)
    if (vertex_of[i] >= 0) {
      places[i].vertex = vertex_of[i];
      common_of[std::size_t(vertex_of[i])] = int(i);
    }
  std::vector<std::vector<int>> neighbours(m);
  for (const Edge& e : common.edges) {
    neighbours[std::size_t(e[0])].push_back(e[1]);
    neighbours[std::size_t(e[1])].push_back(e[0]);
  }
  std::map<std::pair<int, int>, int> key_edge;
  for (std::size_t e = 0; e < key.edges.size(); ++e) key_edge[{key.edges[e][0], key.edges[e][1]}] = int(e);
  for (std::size_t e = 0; e < key.edges.size(); ++e) {
    const int a = common_of[std::size_t(key.edges[e][0])], b = common_of[std::size_t(key.edges[e][1])];
    // The path from a that ends at b through non-key vertices.
    for (int first : neighbours[std::size_t(a)]) {
      std::vector<int> path{a};
      int previous = a, at = first;
      while (vertex_of[std::size_t(at)] < 0 && neighbours[std::size_t(at)].size() == 2) {
        path.push_back(at);
        const int next = neighbours[std::size_t(at)][0] == previous ? neighbours[std::size_t(at)][1]
                                                                    : neighbours[std::size_t(at)][0];
        previous = at;
        at = next;
      }
      if (at != b) continue;
      path.push_back(b);
      double total = 0;
      std::vector<double> length_to(path.size(), 0);
      for (std::size_t p = 1; p < path.size(); ++p) {
        total += distance(common.vertices[std::size_t(path[p - 1])], common.vertices[std::size_t(path[p])]);
        length_to[p] = total;
      }
      for (std::size_t p = 1; p + 1 < path.size(); ++p) {
        MatchedPlace& place = places[std::size_t(path[p])];
        place.edge = int(e);
        place.fraction = length_to[p] / total;
      }
      break;
    }
  }
  for (std::size_t i = 0; i < m; ++i)
    if (places[i].vertex < 0 && places[i].edge < 0)
      throw InternalError("correspond_key_poses: common vertex " + std::to_string(i) + " lies on no edge of " +
                          key_name(k));
  return places;
}

}  // namespace

KeyPoseCorrespondence correspond_key_poses(const std::vector<StickFigure>& keys,
                                           const KeyPoseCorrespondenceOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (keys.size() < 2)
    throw InvalidArgumentError("a key-pose sequence needs at least two keys, got " + std::to_string(keys.size()));
  if (options.pins.size() > keys.size() - 1)
    throw InvalidArgumentError("pins: one list per pair of consecutive keys (" + std::to_string(keys.size() - 1) +
                               "), got " + std::to_string(options.pins.size()));
  const std::size_t count = keys.size();
  // The common figure on every key so far (positions per key, one edge
  // list) and, per key, the key vertex each common vertex is (-1: a dummy).
  std::vector<std::vector<Vec2>> positions{keys[0].vertices};
  std::vector<Edge> edges = keys[0].edges;
  std::vector<std::vector<int>> vertex_of(1);
  for (std::size_t i = 0; i < keys[0].vertices.size(); ++i) vertex_of[0].push_back(int(i));

  KeyPoseCorrespondence result;
  for (std::size_t k = 0; k + 1 < count; ++k) {
    // The common figure as drawn on key k; its vertices are checked valid
    // for k = 0 (key 1 itself) and were validated below for later keys.
    StickFigure on_key;
    on_key.vertices = positions[k];
    on_key.edges = edges;
    CorrespondenceOptions pair_options;
    if (k < options.pins.size()) {
      // Key k's own vertex numbers to the common figure's.
      std::vector<int> common_of(keys[k].vertices.size(), -1);
      for (std::size_t i = 0; i < vertex_of[k].size(); ++i)
        if (vertex_of[k][i] >= 0) common_of[std::size_t(vertex_of[k][i])] = int(i);
      for (const VertexPin& pin : options.pins[k]) {
        if (pin.source < 0 || std::size_t(pin.source) >= common_of.size())
          throw InvalidArgumentError(pair_name(k) + "pin " + std::to_string(pin.source) + ":" +
                                     std::to_string(pin.target) + " names vertex " + std::to_string(pin.source) +
                                     " of " + key_name(k) + ", which has " + std::to_string(common_of.size()) +
                                     " vertices");
        pair_options.pins.push_back({common_of[std::size_t(pin.source)], pin.target});
      }
    }
    FigureCorrespondence match;
    try {
      match = correspond_figures(on_key, keys[k + 1], pair_options);
    } catch (const IncompatibleFiguresError& error) {
      throw IncompatibleFiguresError(error.kind(), pair_name(k) + error.what(), error.vertices());
    } catch (const VerificationError& error) {
      throw VerificationError(pair_name(k) + error.what());
    } catch (const InvalidArgumentError& error) {
      throw InvalidArgumentError(pair_name(k) + error.what());
    }
    // The new dummies on the common figure's edges, on every earlier key
    // at the same fraction of the same edge (key_pose_correspondence.h).
    const std::size_t before = positions[k].size(), after = match.source.vertices.size();
    for (std::size_t j = 0; j < k; ++j) {
      positions[j].resize(after);
      vertex_of[j].resize(after, -1);
      for (std::size_t i = before; i < after; ++i) {
        const MatchedPlace& place = match.source_places[i];
        const Edge& e = edges[std::size_t(place.edge)];
        positions[j][i] = along(positions[j][std::size_t(e[0])], positions[j][std::size_t(e[1])], place.fraction);
      }
    }
    positions[k] = match.source.vertices;
    vertex_of[k].resize(after, -1);
    positions.push_back(match.target.vertices);
    std::vector<int> next_vertex_of(after, -1);
    for (std::size_t i = 0; i < after; ++i) next_vertex_of[i] = match.target_places[i].vertex;
    vertex_of.push_back(std::move(next_vertex_of));
    edges = match.source.edges;
    match.pair.reset();
    result.matches.push_back(std::move(match));
  }

  // Every key on the final common figure, validated: the keys before the
  // last match got their dummies at rounded points of their edges.
  const auto wide = wide_edges(edges);
  for (std::size_t k = 0; k < count; ++k) {
    try {
      result.keys.push_back(make_stick_figure(positions[k], wide, keys[k].name));
    } catch (const InvalidFigureError& error) {
      throw VerificationError(key_name(k) + ": its drawing subdivided for the common figure is not valid in "
                              "floating point (vertices closer together than its edges can resolve): " +
                              error.what());
    }
    result.places.push_back(places_on_key(result.keys[k], keys[k], vertex_of[k], k));
  }
  result.milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

bool is_valid(const KeyPoseCorrespondence& c, const std::vector<StickFigure>& keys) {
  if (c.keys.size() != keys.size() || c.places.size() != keys.size() || keys.empty()) return false;
  const std::size_t m = c.keys[0].vertices.size();
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const StickFigure& common = c.keys[k];
    const StickFigure& key = keys[k];
    if (common.vertices.size() != m || common.edges != c.keys[0].edges || !is_valid(common)) return false;
    if (c.places[k].size() != m) return false;
    std::vector<int> seen(key.vertices.size(), 0);
    for (std::size_t i = 0; i < m; ++i) {
      const MatchedPlace& place = c.places[k][i];
      if (place.vertex >= 0) {
        if (std::size_t(place.vertex) >= key.vertices.size() || ++seen[std::size_t(place.vertex)] > 1) return false;
        if (common.vertices[i] != key.vertices[std::size_t(place.vertex)]) return false;
        if (k == 0 && place.vertex != int(i)) return false;
      } else {
        if (place.edge < 0 || std::size_t(place.edge) >= key.edges.size()) return false;
        if (!(place.fraction > 0 && place.fraction < 1)) return false;
        const Edge& e = key.edges[std::size_t(place.edge)];
        const Vec2 expected =
            along(key.vertices[std::size_t(e[0])], key.vertices[std::size_t(e[1])], place.fraction);
        const double scale = distance(key.vertices[std::size_t(e[0])], key.vertices[std::size_t(e[1])]);
        if (distance(expected, common.vertices[i]) > 1e-9 * scale) return false;
      }
    }
    for (int s : seen)
      if (s != 1) return false;
  }
  return true;
}

}  // namespace stickmorph
