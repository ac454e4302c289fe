// Automatic correspondence (figure_correspondence.h): skeletons matched as
// plane maps, chains resampled by arc length with dummy vertices (Surazhsky
// & Gotsman 2001, section 6).
#include "stickmorph/figure_correspondence.h"
#include "stickmorph/working_scale.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <utility>

#include "stickmorph/compatibility.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/errors.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/figure_parts.h"

namespace stickmorph {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Arc-length samples per chain (and per loop) for the geometric cost: enough
// to tell a stroke's shape, independent of how finely it is drawn.
constexpr int kChainSamples = 8;
constexpr int kLoopSamples = 128;
// A vertex pairs with one of the other figure when their arc lengths differ
// by less than this share of the spacing around both (then each has at most
// one candidate and the pairs keep their order along the chain).
constexpr double kMergeShare = 0.3;
// Corners (a turn of at least this many radians at a vertex) are matched to
// corners of the same sense within this share of the stroke, and become
// anchors of the arc-length map: the same letter drawn in two fonts has its
// corners at slightly different arc lengths, and a corner that lands on the
// other drawing's straight edge would round off while its partner corner
// grows beside it. A pair of corners up to kMaxCornerPairs candidates per
// stroke; beyond, arc length alone (the dynamic programme is quadratic).
constexpr double kCornerTurn = 0.7;  // 40 degrees
constexpr double kCornerWindow = 0.08;
constexpr std::size_t kMaxCornerPairs = 4'000'000;
// The cost of a matching is its similarity residual times 1 + this much
// times (1 - cos rotation), up to three times the residual for a half turn:
// a nearly symmetric figure (an X, a letter with a near half-turn symmetry)
// drawn twice can fit slightly better turned half round by accident of
// style, and a morph that spins it by 150 degrees where 30 would do is not
// what anyone drew. A factor, not a sum: an exact fit (residual 0) still
// beats every other, however far it turns, so a figure drawn turned by 120
// degrees keeps its own vertices.
constexpr double kRotationCharge = 1.0;
// Costs within this much of the best are ties, broken by the smaller
// rotation: a square matched onto a square has four equal fits.
constexpr double kTieRelative = 0.02;
constexpr double kTieAbsolute = 1e-9;  // roundoff of the residual of exact symmetries

// ---------------------------------------------------------------- tracks ---

/// A chain between two nodes, or a whole loop, as a walk along the figure:
/// vertices[k] to vertices[k + 1] over edges[k]. A loop repeats nothing: its
/// last edge closes back to vertices[0].
struct Track {
  std::vector<int> vertices;
  std::vector<int> edges;
  std::vector<double> arc;  ///< arc[k]: length from vertices[0] to vertices[k]; arc.back() the total
  bool closed = false;
  double length() const { return arc.back(); }
};

double distance(const Vec2& a, const Vec2& b) { return std::hypot(b[0] - a[0], b[1] - a[1]); }

Track make_track(const StickFigure& figure, std::vector<int> vertices, std::vector<int> edges, bool closed) {
  Track track;
  track.closed = closed;
  track.arc.push_back(0);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const int a = vertices[k], b = vertices[(k + 1) % vertices.size()];
    track.arc.push_back(track.arc.back() + distance(figure.vertices[a], figure.vertices[b]));
  }
  track.vertices = std::move(vertices);
  track.edges = std::move(edges);
  return track;
}

/// Parameter (arc length over total) of the track's k-th vertex.
double vertex_parameter(const Track& track, std::size_t k) { return track.arc[k] / track.length(); }

/// The point at parameter u in [0, 1] (a loop wraps u into [0, 1)): the
/// segment slot k it falls in and the fraction along that slot.
std::pair<std::size_t, double> locate(const Track& track, double u) {
  if (track.closed) u -= std::floor(u);
  u = std::clamp(u, 0.0, 1.0);
  const double s = u * track.length();
  std::size_t k = std::size_t(std::upper_bound(track.arc.begin(), track.arc.end(), s) - track.arc.begin());
  k = std::min(std::max<std::size_t>(k, 1), track.edges.size()) - 1;
  const double span = track.arc[k + 1] - track.arc[k];
  return {k, span > 0 ? std::clamp((s - track.arc[k]) / span, 0.0, 1.0) : 0.0};
}

Vec2 point_on(const Vec2& a, const Vec2& b, double f) {
  return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])};
}

Vec2 point_at(const StickFigure& figure, const Track& track, double u) {
  const auto [k, f] = locate(track, u);
  const Vec2& a = figure.vertices[track.vertices[k]];
  const Vec2& b = figure.vertices[track.vertices[(k + 1) % track.vertices.size()]];
  return point_on(a, b, f);
}

// -------------------------------------------------------------- skeleton ---

/// A figure's skeleton: the nodes (degree != 2) and the chains between them,
/// as a plane map whose darts are the figure darts that leave a node.
struct Skeleton {
  const StickFigure* figure = nullptr;
  Decomposition decomposition;
  std::vector<int> degree;
  std::vector<int> nodes;             ///< vertices of degree != 2, increasing
  std::vector<Track> chains;
  std::vector<int> chain_first;       ///< per chain: the dart leaving vertices[0] into it (-1 for a loop)
  std::vector<int> chain_of_dart;     ///< per figure dart leaving a node: its chain, else -1
  std::vector<char> forward;          ///< per such dart: runs the chain from vertices[0]
  std::vector<int> far_dart;          ///< per such dart: the dart leaving the other end into the chain
  std::vector<int> chain_of_vertex;   ///< per vertex of degree 2: its chain (or 0 for a loop)
  std::vector<int> slot_of_vertex;    ///< per vertex of degree 2: its index in the chain's vertices
  int loops = 0;                      ///< independent cycles, E - V + 1
  /// The rotation (radians) that fits are charged from: 0 for a figure on
  /// its own; for a part of a figure of several, the whole figure's, so that
  /// a symmetric part turns with the rest.
  double reference_rotation = 0;

  bool is_loop() const { return nodes.empty() && !figure->edges.empty(); }
  int dart_count() const { return int(chain_of_dart.size()); }
  bool leaves_node(int dart) const { return chain_of_dart[std::size_t(dart)] >= 0; }
  int node_of(int dart) const { return decomposition.rotation.tail[std::size_t(dart)]; }
  /// The next dart counter-clockwise around the dart's node.
  int ccw_next(int dart) const {
    const RotationSystem& rotation = decomposition.rotation;
    const auto& around = rotation.outgoing_ccw[std::size_t(node_of(dart))];
    return around[std::size_t((rotation.position[std::size_t(dart)] + 1) % int(around.size()))];
  }
};

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

[[noreturn]] void topology_differs(const std::string& what) {
  throw IncompatibleFiguresError(Incompatibility::TopologyDiffers,
                                 "correspond: the figures' topologies cannot be matched: " + what);
}

// The invariants that any matching needs, compared first so that the
// message says what differs in the user's terms.
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

// ------------------------------------------------------------------ cost ---

/// Weighted similarity fit of sample pairs: the residual
/// 1 - |sum w conj(a) b|^2 / (sum w |a|^2 * sum w |b|^2) of centred points
/// (0 for a perfect similarity, 1 for no relation) and the rotation.
struct Fit {
  double residual = 1;
  double rotation = 0;  ///< radians, counter-clockwise, in (-pi, pi]
  double reference = 0;  ///< the rotation charged from (Skeleton::reference_rotation)
  double cost() const { return residual * (1 + kRotationCharge * (1 - std::cos(rotation - reference))); }
  /// How far the rotation is from the reference, in [0, pi].
  double turn() const { return std::abs(std::remainder(rotation - reference, 2 * kPi)); }
};

struct SampleSet {
  std::vector<std::complex<double>> a, b;
  std::vector<double> w;
  void add(const Vec2& p, const Vec2& q, double weight) {
    a.emplace_back(p[0], p[1]);
    b.emplace_back(q[0], q[1]);
    w.push_back(weight);
  }
  Fit fit() const {
    double total = 0;
    std::complex<double> ca, cb;
    for (std::size_t k = 0; k < w.size(); ++k) {
      total += w[k];
      ca += w[k] * a[k];
      cb += w[k] * b[k];
    }
    Fit result;
    if (!(total > 0)) return result;
    ca /= total;
    cb /= total;
    std::complex<double> cross;
    double aa = 0, bb = 0;
    for (std::size_t k = 0; k < w.size(); ++k) {
      const std::complex<double> p = a[k] - ca, q = b[k] - cb;
      cross += w[k] * std::conj(p) * q;
      aa += w[k] * std::norm(p);
      bb += w[k] * std::norm(q);
    }
    if (!(aa > 0) || !(bb > 0)) {
      result.residual = (aa > 0) == (bb > 0) ? 0 : 1;
      return result;
    }
    result.residual = std::clamp(1.0 - std::norm(cross) / (aa * bb), 0.0, 1.0);
    result.rotation = std::arg(cross);
    return result;
  }
};

/// A monotone map from a source track's parameter to a target track's,
/// piecewise linear through anchors (u_k, w_k): the chain's ends and its
/// pins; for a loop, the pins or one shift, continued periodically.
struct ParameterMap {
  std::vector<double> u, w;  ///< increasing; a loop's w may exceed 1 (unwrapped)
  bool closed = false;

  double to_target(double x) const { return apply(u, w, x); }
  double to_source(double y) const { return apply(w, u, y); }

 private:
  double apply(const std::vector<double>& from, const std::vector<double>& to, double x) const {
    if (!closed) {
      std::size_t k = std::size_t(std::upper_bound(from.begin(), from.end(), x) - from.begin());
      k = std::min(std::max<std::size_t>(k, 1), from.size() - 1) - 1;
      const double span = from[k + 1] - from[k];
      return to[k] + (span > 0 ? (x - from[k]) / span : 0.0) * (to[k + 1] - to[k]);
    }
    // Periodic: shift x into [from[0], from[0] + 1) and add the closing anchor.
    const double base = from[0];
    double y = x - std::floor(x - base);
    std::size_t k = std::size_t(std::upper_bound(from.begin(), from.end(), y) - from.begin()) - 1;
    const double f0 = from[k], t0 = to[k];
    const double f1 = k + 1 < from.size() ? from[k + 1] : from[0] + 1;
    const double t1 = k + 1 < to.size() ? to[k + 1] : to[0] + 1;
    const double r = f1 > f0 ? (y - f0) / (f1 - f0) : 0.0;
    y = t0 + r * (t1 - t0);
    return y - std::floor(y);
  }
};

/// One chain of the source matched with one of the target, in a direction.
struct ChainMatch {
  int source_chain = -1;
  int target_chain = -1;
  bool reversed = false;  ///< the target chain is run from its last vertex
  ParameterMap map;       ///< source parameter -> target parameter along the run
};

/// A target track's parameter in the direction the match runs it.
double run_parameter(double w, bool reversed) { return reversed ? 1.0 - w : w; }

/// A candidate matching: node images and the chain pairs.
struct Candidate {
  std::vector<int> node_image;     ///< per source vertex: target node, -1 if not a node
  std::vector<ChainMatch> chains;  ///< per source chain
  Fit fit;
};

// Samples of every chain pair for the similarity fit, weighted by the
// chains' share of the drawings' lengths so that a long stroke counts more
// than a short one however finely either is drawn.
Fit candidate_fit(const Skeleton& source, const Skeleton& target, const std::vector<ChainMatch>& chains,
                  int samples_per_chain) {
  double source_total = 0, target_total = 0;
  for (const Track& t : source.chains) source_total += t.length();
  for (const Track& t : target.chains) target_total += t.length();
  SampleSet set;
  for (const ChainMatch& match : chains) {
    const Track& s = source.chains[std::size_t(match.source_chain)];
    const Track& t = target.chains[std::size_t(match.target_chain)];
    const double weight = (s.length() / source_total + t.length() / target_total) / (2.0 * (samples_per_chain + 1));
    const int count = s.closed ? samples_per_chain : samples_per_chain + 1;
    for (int k = 0; k < count; ++k) {
      const double u = (s.closed ? match.map.u[0] : 0.0) + double(k) / samples_per_chain;
      const double w = run_parameter(match.map.to_target(u), match.reversed);
      set.add(point_at(*source.figure, s, u), point_at(*target.figure, t, w), weight);
    }
  }
  Fit fit = set.fit();
  fit.reference = source.reference_rotation;
  return fit;
}

// --------------------------------------------------------------- pins ------

struct PinPlace {
  int source_chain = -1, target_chain = -1;
  double u = 0, w = 0;  ///< parameters along the stored tracks
};

/// Checks the pins against the figures (InvalidArgumentError) and sorts them
/// into node pins (source node -> target node) and chain pins.
/// The pins' own rules, before any matching (InvalidArgumentError): each
/// names vertices that exist, pins no vertex twice, and joins vertices of
/// one kind (nodes of the same degree, or two vertices of degree 2).
void check_pins(const std::vector<int>& source_degree, const std::vector<int>& target_degree,
                const std::vector<VertexPin>& pins) {
  const int ns = int(source_degree.size()), nt = int(target_degree.size());
  std::vector<int> source_seen(std::size_t(ns), -1), target_seen(std::size_t(nt), -1);
  for (std::size_t k = 0; k < pins.size(); ++k) {
    const VertexPin& pin = pins[k];
    const std::string name = "pin " + std::to_string(pin.source) + ":" + std::to_string(pin.target);
    if (pin.source < 0 || pin.source >= ns)
      throw InvalidArgumentError("correspond: " + name + ": the source has no vertex " + std::to_string(pin.source) +
                                 " (it has " + plural(ns, "vertex", "vertices") + ")");
    if (pin.target < 0 || pin.target >= nt)
      throw InvalidArgumentError("correspond: " + name + ": the target has no vertex " + std::to_string(pin.target) +
                                 " (it has " + plural(nt, "vertex", "vertices") + ")");
    if (source_seen[std::size_t(pin.source)] >= 0)
      throw InvalidArgumentError("correspond: source vertex " + std::to_string(pin.source) + " is pinned twice");
    if (target_seen[std::size_t(pin.target)] >= 0)
      throw InvalidArgumentError("correspond: target vertex " + std::to_string(pin.target) + " is pinned twice");
    source_seen[std::size_t(pin.source)] = target_seen[std::size_t(pin.target)] = int(k);
    const int ds = source_degree[std::size_t(pin.source)], dt = target_degree[std::size_t(pin.target)];
    if ((ds == 2) != (dt == 2) || (ds != 2 && ds != dt))
      throw InvalidArgumentError("correspond: " + name + " joins a vertex of degree " + std::to_string(ds) +
                                 " to one of degree " + std::to_string(dt) +
                                 " (a junction or end matches only one of the same degree, a vertex inside a "
                                 "stroke only one inside a stroke)");
  }
}

void classify_pins(const Skeleton& source, const Skeleton& target, const std::vector<VertexPin>& pins,
                   std::vector<std::pair<int, int>>& node_pins, std::vector<PinPlace>& chain_pins) {
  check_pins(source.degree, target.degree, pins);
  for (const VertexPin& pin : pins) {
    const int ds = source.degree[std::size_t(pin.source)];
    if (ds != 2) {
      node_pins.emplace_back(pin.source, pin.target);
      continue;
    }
    PinPlace place;
    place.source_chain = source.chain_of_vertex[std::size_t(pin.source)];
    place.target_chain = target.chain_of_vertex[std::size_t(pin.target)];
    place.u = vertex_parameter(source.chains[std::size_t(place.source_chain)],
                               std::size_t(source.slot_of_vertex[std::size_t(pin.source)]));
    place.w = vertex_parameter(target.chains[std::size_t(place.target_chain)],
                               std::size_t(target.slot_of_vertex[std::size_t(pin.target)]));
    chain_pins.push_back(place);
  }
}

/// The parameter map of an open chain pair through its pins, or nothing if
/// the pins on it are out of order in the matched direction.
std::optional<ParameterMap> chain_map(const std::vector<PinPlace>& pins, int source_chain, int target_chain,
                                      bool reversed) {
  std::vector<std::pair<double, double>> anchors{{0.0, 0.0}, {1.0, 1.0}};
  for (const PinPlace& pin : pins) {
    if (pin.source_chain != source_chain) continue;
    if (pin.target_chain != target_chain) return std::nullopt;
    anchors.emplace_back(pin.u, run_parameter(pin.w, reversed));
  }
  std::sort(anchors.begin(), anchors.end());
  ParameterMap map;
  for (std::size_t k = 0; k < anchors.size(); ++k) {
    if (k > 0 && !(anchors[k].second > anchors[k - 1].second)) return std::nullopt;
    map.u.push_back(anchors[k].first);
    map.w.push_back(anchors[k].second);
  }
  return map;
}

// --------------------------------------------------------- isomorphisms ---

/// The orientation-preserving isomorphism of the skeletons that sends
/// source dart `seed` to target dart `image`, if there is one: breadth first
/// over the two relations an isomorphism keeps, the next dart around a node
/// and the dart at the far end of a chain. Returns the image of every
/// source dart that leaves a node (-1 elsewhere).
std::optional<std::vector<int>> extend_isomorphism(const Skeleton& source, const Skeleton& target, int seed,
                                                   int image) {
  std::vector<int> forward(std::size_t(source.dart_count()), -1), backward(std::size_t(target.dart_count()), -1);
  std::vector<std::pair<int, int>> queue{{seed, image}};
  forward[std::size_t(seed)] = image;
  backward[std::size_t(image)] = seed;
  for (std::size_t next = 0; next < queue.size(); ++next) {
    const auto [d, e] = queue[next];
    if (source.degree[std::size_t(source.node_of(d))] != target.degree[std::size_t(target.node_of(e))])
      return std::nullopt;
    for (const auto& [dd, ee] : {std::pair{source.ccw_next(d), target.ccw_next(e)},
                                 std::pair{source.far_dart[std::size_t(d)], target.far_dart[std::size_t(e)]}}) {
      const int known = forward[std::size_t(dd)];
      if (known == ee) continue;
      if (known >= 0 || backward[std::size_t(ee)] >= 0) return std::nullopt;
      forward[std::size_t(dd)] = ee;
      backward[std::size_t(ee)] = dd;
      queue.emplace_back(dd, ee);
    }
  }
  return forward;
}

/// A source dart on the exterior face that leaves a node.
int exterior_dart(const Skeleton& skeleton) {
  const Decomposition& dec = skeleton.decomposition;
  for (int dart : dec.sequences[std::size_t(dec.exterior)].darts)
    if (skeleton.leaves_node(dart)) return dart;
  throw InternalError("correspond: the exterior face of a figure with nodes holds no dart leaving a node");
}

/// The candidate an isomorphism (the image of every source dart leaving a
/// node) gives, or nothing with `broken` saying which pin it breaks.
std::optional<Candidate> make_candidate(const Skeleton& source, const Skeleton& target, const std::vector<int>& map,
                                        const std::vector<std::pair<int, int>>& node_pins,
                                        const std::vector<PinPlace>& chain_pins, std::string& broken) {
  Candidate candidate;
  candidate.node_image.assign(source.figure->vertices.size(), -1);
  for (int dart = 0; dart < source.dart_count(); ++dart)
    if (source.leaves_node(dart))
      candidate.node_image[std::size_t(source.node_of(dart))] = target.node_of(map[std::size_t(dart)]);
  for (const auto& [s, t] : node_pins)
    if (candidate.node_image[std::size_t(s)] != t) {
      broken = "it would send source vertex " + std::to_string(s) + " to target vertex " +
               std::to_string(candidate.node_image[std::size_t(s)]) + ", not " + std::to_string(t);
      return std::nullopt;
    }
  for (std::size_t chain = 0; chain < source.chains.size(); ++chain) {
    const int e = map[std::size_t(source.chain_first[chain])];
    ChainMatch match;
    match.source_chain = int(chain);
    match.target_chain = target.chain_of_dart[std::size_t(e)];
    match.reversed = !target.forward[std::size_t(e)];
    std::optional<ParameterMap> pmap = chain_map(chain_pins, match.source_chain, match.target_chain, match.reversed);
    if (!pmap) {
      broken = "a pinned vertex inside a stroke would land on another stroke or out of order along it";
      return std::nullopt;
    }
    match.map = *pmap;
    candidate.chains.push_back(std::move(match));
  }
  return candidate;
}

struct Search {
  int seed = -1;                 ///< the source dart every isomorphism is extended from
  std::vector<int> images;       ///< its image in each candidate keeping the exterior and the pins
  std::vector<Fit> fits;         ///< and each one's fit (only the winner is rebuilt in full)
  bool any_isomorphism = false;  ///< ignoring the exterior and the pins
  bool any_exterior = false;     ///< keeping the exterior, ignoring the pins
  std::string pin_conflict;      ///< why the first isomorphism keeping the exterior broke the pins
};

// Every orientation-preserving isomorphism is tried, pins or not, so that
// a pair whose pins no matching respects is told apart from a pair that
// matches in no way at all; the pins only filter. Each candidate is scored
// and dropped, so memory stays that of one candidate (a wheel of k spokes
// has k of them).
Search search_isomorphisms(const Skeleton& source, const Skeleton& target,
                           const std::vector<std::pair<int, int>>& node_pins, const std::vector<PinPlace>& chain_pins,
                           bool with_cost) {
  Search search;
  // Seed at the node whose degree is rarest among the target's nodes: the
  // fewest images to try, each O(skeleton) to extend.
  std::map<int, int> degree_count;
  for (int node : target.nodes) ++degree_count[target.degree[std::size_t(node)]];
  int seed_node = source.nodes[0];
  for (int node : source.nodes)
    if (degree_count[source.degree[std::size_t(node)]] < degree_count[source.degree[std::size_t(seed_node)]])
      seed_node = node;
  search.seed = source.decomposition.rotation.outgoing_ccw[std::size_t(seed_node)][0];
  const int source_exterior = exterior_dart(source);
  const int target_exterior = target.decomposition.exterior;
  for (int image_node : target.nodes) {
    if (target.degree[std::size_t(image_node)] != source.degree[std::size_t(seed_node)]) continue;
    for (int image : target.decomposition.rotation.outgoing_ccw[std::size_t(image_node)]) {
      const std::optional<std::vector<int>> map = extend_isomorphism(source, target, search.seed, image);
      if (!map) continue;
      search.any_isomorphism = true;
      const int exterior_image = (*map)[std::size_t(source_exterior)];
      if (target.decomposition.sequence_of_dart[std::size_t(exterior_image)] != target_exterior) continue;
      search.any_exterior = true;
      std::string broken;
      const std::optional<Candidate> candidate = make_candidate(source, target, *map, node_pins, chain_pins, broken);
      if (!candidate) {
        if (search.pin_conflict.empty()) search.pin_conflict = broken;
        continue;
      }
      search.images.push_back(image);
      search.fits.push_back(with_cost ? candidate_fit(source, target, candidate->chains, kChainSamples) : Fit{});
    }
  }
  return search;
}

/// The least-cost fit; near ties go to the smallest rotation (from the
/// reference).
std::size_t best_fit(const std::vector<Fit>& fits) {
  double least = std::numeric_limits<double>::infinity();
  for (const Fit& fit : fits) least = std::min(least, fit.cost());
  const double tie = least + kTieRelative * least + kTieAbsolute;
  std::size_t best = fits.size();
  for (std::size_t k = 0; k < fits.size(); ++k) {
    if (fits[k].cost() > tie) continue;
    if (best == fits.size() || fits[k].turn() < fits[best].turn()) best = k;
  }
  return best;
}

// ---------------------------------------------------------------- loops ---

/// Two loops, both counter-clockwise: the shift of least cost (or the pins'
/// map), as one candidate.
Candidate match_loops(const Skeleton& source, const Skeleton& target, const std::vector<PinPlace>& pins,
                      int& compared) {
  Candidate candidate;
  candidate.node_image.assign(source.figure->vertices.size(), -1);
  ChainMatch match;
  match.source_chain = 0;
  match.target_chain = 0;
  match.map.closed = true;
  if (!pins.empty()) {
    std::vector<std::pair<double, double>> anchors;
    for (const PinPlace& pin : pins) anchors.emplace_back(pin.u, pin.w);
    std::sort(anchors.begin(), anchors.end());
    // Counter-clockwise on both: the target parameters must increase once
    // unwrapped from the first pin's, within one turn.
    double previous = anchors[0].second;
    for (std::size_t k = 0; k < anchors.size(); ++k) {
      double w = anchors[k].second;
      while (w < previous) w += 1;
      if (k > 0 && !(w > previous)) w += 1;
      if (w >= anchors[0].second + 1)
        throw IncompatibleFiguresError(Incompatibility::PinsUnsatisfiable,
                                       "correspond: no matching respects every pin: the pinned vertices are not in "
                                       "the same counter-clockwise order around both loops");
      match.map.u.push_back(anchors[k].first);
      match.map.w.push_back(w);
      previous = w;
    }
    candidate.chains.push_back(match);
    candidate.fit = candidate_fit(source, target, candidate.chains, kLoopSamples);
    compared = 1;
    return candidate;
  }
  // Shifts on a grid of the samples' spacing; each local minimum of the
  // residual that could still win once its rotation is charged is refined
  // by golden-section search on the residual alone within a grid step (the
  // charge picks between fits, it must not pull a fit off its best shift),
  // and best_fit then decides by cost.
  auto fit_at = [&](double shift) {
    ChainMatch m = match;
    m.map.u = {0.0};
    m.map.w = {shift};
    return candidate_fit(source, target, {m}, kLoopSamples);
  };
  std::vector<Fit> grid(kLoopSamples);
  double least = std::numeric_limits<double>::infinity();
  for (int k = 0; k < kLoopSamples; ++k) {
    grid[std::size_t(k)] = fit_at(double(k) / kLoopSamples);
    least = std::min(least, grid[std::size_t(k)].cost());
  }
  const double tie = least + kTieRelative * least + kTieAbsolute;
  std::vector<std::pair<double, Fit>> refined;
  for (int k = 0; k < kLoopSamples; ++k) {
    const Fit& here = grid[std::size_t(k)];
    const Fit& before = grid[std::size_t((k + kLoopSamples - 1) % kLoopSamples)];
    const Fit& after = grid[std::size_t((k + 1) % kLoopSamples)];
    if (here.residual > tie || here.residual > before.residual || here.residual > after.residual) continue;
    double lo = double(k - 1) / kLoopSamples, hi = double(k + 1) / kLoopSamples;
    const double golden = 0.5 * (std::sqrt(5.0) - 1);
    double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
    double f1 = fit_at(x1).residual, f2 = fit_at(x2).residual;
    for (int iteration = 0; iteration < 40; ++iteration) {
      if (f1 <= f2) {
        hi = x2; x2 = x1; f2 = f1; x1 = hi - golden * (hi - lo); f1 = fit_at(x1).residual;
      } else {
        lo = x1; x1 = x2; f1 = f2; x2 = lo + golden * (hi - lo); f2 = fit_at(x2).residual;
      }
    }
    const double shift = 0.5 * (lo + hi);
    refined.emplace_back(shift - std::floor(shift), fit_at(shift));
  }
  compared = int(refined.size());
  std::vector<Fit> fits;
  for (const auto& [shift, fit] : refined) fits.push_back(fit);
  const auto& [shift, fit] = refined[best_fit(fits)];
  match.map.u = {0.0};
  match.map.w = {shift};
  candidate.chains.push_back(match);
  candidate.fit = fit;
  return candidate;
}

// --------------------------------------------------------------- corners ---

/// Signed turn at slot k of a track (counter-clockwise positive), walked in
/// the stored direction; 0 at a chain's ends.
double turn_at(const StickFigure& figure, const Track& track, std::size_t k) {
  const std::size_t n = track.vertices.size();
  if (!track.closed && (k == 0 || k + 1 == n)) return 0;
  const Vec2& a = figure.vertices[std::size_t(track.vertices[(k + n - 1) % n])];
  const Vec2& b = figure.vertices[std::size_t(track.vertices[k])];
  const Vec2& c = figure.vertices[std::size_t(track.vertices[(k + 1) % n])];
  const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - b[0], vy = c[1] - b[1];
  return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}

/// Adds matched corners to a chain pair's map as anchors: the order-keeping
/// matching of source corners to target corners of the same sense, each
/// pair within kCornerWindow under the map so far, that maximises the sum
/// of (1 - (gap / window)^2) * (smaller turn / larger turn) (a dynamic
/// programme like an alignment of two sequences). Anchors already there
/// (the ends, the pins, a loop's shift) stay, and a corner pair that would
/// cross one is dropped, so the map stays increasing.
void anchor_corners(const StickFigure& source, const Track& s, const StickFigure& target, const Track& t,
                    ChainMatch& match) {
  ParameterMap& map = match.map;
  const bool closed = s.closed;
  const double u0 = closed ? map.u[0] : 0.0, w0 = closed ? map.w[0] : 0.0;
  // Both sides in the common order: x along the source from the map's
  // first anchor, y along the target's run from its image.
  auto x_of = [&](double u) { return closed ? u - u0 - std::floor(u - u0) : u; };
  auto y_of = [&](double w) {  // w: stored target parameter
    const double run = run_parameter(w, match.reversed);
    return closed ? run - w0 - std::floor(run - w0) : run;
  };
  struct Corner {
    double x, y, turn;  // y: the target's own run coordinate (source side: 0)
    double mapped;      // target corners: x of their image under the map
  };
  std::vector<Corner> from_source, from_target;
  for (std::size_t k = 0; k < s.vertices.size(); ++k) {
    const double turn = turn_at(source, s, k);
    if (std::abs(turn) >= kCornerTurn) from_source.push_back({x_of(vertex_parameter(s, k)), 0, turn, 0});
  }
  for (std::size_t k = 0; k < t.vertices.size(); ++k) {
    const double turn = (match.reversed ? -1 : 1) * turn_at(target, t, k);
    if (std::abs(turn) < kCornerTurn) continue;
    const double w = vertex_parameter(t, k);
    from_target.push_back({0, y_of(w), turn, x_of(map.to_source(run_parameter(w, match.reversed)))});
  }
  if (from_source.empty() || from_target.empty() || from_source.size() * from_target.size() > kMaxCornerPairs) return;
  auto by_x = [](const Corner& a, const Corner& b) { return a.x < b.x; };
  auto by_y = [](const Corner& a, const Corner& b) { return a.y < b.y; };
  std::sort(from_source.begin(), from_source.end(), by_x);
  std::sort(from_target.begin(), from_target.end(), by_y);
  const std::size_t ns = from_source.size(), nt = from_target.size();
  auto score = [&](std::size_t i, std::size_t j) {
    const Corner& a = from_source[i];
    const Corner& b = from_target[j];
    if ((a.turn > 0) != (b.turn > 0)) return 0.0;
    const double gap = std::abs(a.x - b.mapped) / kCornerWindow;
    if (gap >= 1) return 0.0;
    return (1 - gap * gap) * std::min(std::abs(a.turn), std::abs(b.turn)) /
           std::max(std::abs(a.turn), std::abs(b.turn));
  };
  // best[i][j]: the best sum over the first i source and j target corners.
  std::vector<double> best((ns + 1) * (nt + 1), 0.0);
  auto at = [&](std::size_t i, std::size_t j) -> double& { return best[i * (nt + 1) + j]; };
  for (std::size_t i = 1; i <= ns; ++i)
    for (std::size_t j = 1; j <= nt; ++j) {
      const double pair = score(i - 1, j - 1);
      at(i, j) = std::max({at(i - 1, j), at(i, j - 1), pair > 0 ? at(i - 1, j - 1) + pair : 0.0});
    }
  std::vector<std::pair<double, double>> corners;  // (x, y), increasing
  for (std::size_t i = ns, j = nt; i > 0 && j > 0;) {
    const double pair = score(i - 1, j - 1);
    if (pair > 0 && at(i, j) == at(i - 1, j - 1) + pair) {
      corners.emplace_back(from_source[i - 1].x, from_target[j - 1].y);
      --i, --j;
    } else if (at(i, j) == at(i - 1, j)) {
      --i;
    } else {
      --j;
    }
  }
  std::reverse(corners.begin(), corners.end());
  // The anchors there are, in the same coordinates; a loop's first anchor
  // is (0, 0) and its last the first one turn on, (1, 1).
  std::vector<std::pair<double, double>> fixed;
  for (std::size_t k = 0; k < map.u.size(); ++k)
    fixed.emplace_back(x_of(map.u[k]), closed ? map.w[k] - w0 : map.w[k]);
  if (closed) fixed.emplace_back(1.0, 1.0);
  std::vector<std::pair<double, double>> merged = fixed;
  for (const auto& [x, y] : corners) {
    const auto next = std::upper_bound(fixed.begin(), fixed.end(), std::pair{x, -1.0},
                                       [](const auto& a, const auto& b) { return a.first < b.first; });
    if (next == fixed.begin() || next == fixed.end()) continue;
    const auto& before = *(next - 1);
    // Strictly between its neighbouring fixed anchors in both coordinates;
    // a corner that is itself a pinned vertex is already an anchor.
    if (x > before.first && x < next->first && y > before.second && y < next->second) merged.emplace_back(x, y);
  }
  std::sort(merged.begin(), merged.end());
  if (closed) merged.pop_back();
  ParameterMap result;
  result.closed = closed;
  for (const auto& [x, y] : merged) {
    result.u.push_back(closed ? u0 + x : x);
    result.w.push_back(closed ? w0 + y : y);
  }
  map = std::move(result);
}

// ------------------------------------------------------------ resampling ---

/// A place on a track: a vertex of it (slot k) or a dummy at parameter p.
struct Place {
  int vertex = -1;   ///< the figure's vertex, or -1
  double p = 0;      ///< parameter along the stored track
};

/// One matched vertex along a matched chain, in order.
struct Item {
  double order = 0;  ///< common parameter (the source's), for sorting
  Place source, target;
};

/// The matched vertices along a chain pair (interior only for a chain, all
/// for a loop), sorted by the source's parameter: every vertex of both
/// tracks exactly once, close pairs merged, the rest given dummy partners.
std::vector<Item> resample(const Track& s, const Track& t, const ChainMatch& match,
                           const std::vector<std::pair<int, int>>& pinned) {
  const bool closed = s.closed;
  const std::size_t first = closed ? 0 : 1;
  const std::size_t s_end = closed ? s.vertices.size() : s.vertices.size() - 1;
  const std::size_t t_end = closed ? t.vertices.size() : t.vertices.size() - 1;
  // The common parameter: the source's, unwrapped from the map's first
  // anchor for a loop so that sorting follows the loop.
  const double base = closed ? match.map.u[0] : 0.0;
  auto common = [&](double u) { return closed ? u - base - std::floor(u - base) : u; };
  std::vector<char> s_pinned(s.vertices.size(), 0), t_pinned(t.vertices.size(), 0);
  std::vector<Item> items;
  for (const auto& [sv, tv] : pinned) {
    std::size_t ks = first, kt = first;
    while (ks < s_end && s.vertices[ks] != sv) ++ks;
    while (kt < t_end && t.vertices[kt] != tv) ++kt;
    if (ks == s_end || kt == t_end) continue;  // a pin on another chain
    s_pinned[ks] = t_pinned[kt] = 1;
    const double u = vertex_parameter(s, ks);
    items.push_back({common(u), {sv, u}, {tv, vertex_parameter(t, kt)}});
  }
  struct Loose {
    double order;
    std::size_t slot;
  };
  std::vector<Loose> from_source, from_target;
  for (std::size_t k = first; k < s_end; ++k)
    if (!s_pinned[k]) from_source.push_back({common(vertex_parameter(s, k)), k});
  for (std::size_t k = first; k < t_end; ++k)
    if (!t_pinned[k]) {
      const double w = run_parameter(vertex_parameter(t, k), match.reversed);
      from_target.push_back({common(match.map.to_source(w)), k});
    }
  auto by_order = [](const Loose& a, const Loose& b) { return a.order < b.order; };
  std::sort(from_source.begin(), from_source.end(), by_order);
  std::sort(from_target.begin(), from_target.end(), by_order);
  // Spacing around each vertex on its own side: to its neighbours, the
  // chain's ends or pins (a loop wraps around).
  auto spacing = [&](const std::vector<Loose>& side, const std::vector<double>& fixed) {
    std::vector<double> all;
    for (const Loose& l : side) all.push_back(l.order);
    for (double f : fixed) all.push_back(f);
    std::sort(all.begin(), all.end());
    std::vector<double> gap(side.size(), 1.0);
    for (std::size_t k = 0; k < side.size(); ++k) {
      const double x = side[k].order;
      const auto at = std::lower_bound(all.begin(), all.end(), x);
      double g = 1.0;
      if (at != all.begin()) g = std::min(g, x - *(at - 1));
      else if (closed && all.size() > 1) g = std::min(g, x + 1 - all.back());
      if (at + 1 != all.end()) g = std::min(g, *(at + 1) - x);
      else if (closed && all.size() > 1) g = std::min(g, all.front() + 1 - x);
      gap[k] = g;
    }
    return gap;
  };
  std::vector<double> fixed;
  if (!closed) fixed = {0.0, 1.0};
  for (const Item& item : items) fixed.push_back(item.order);
  const std::vector<double> s_gap = spacing(from_source, fixed), t_gap = spacing(from_target, fixed);
  std::vector<int> partner(from_source.size(), -1);
  std::vector<char> t_taken(from_target.size(), 0);
  // The nearest target vertices on either side of each source vertex; on a
  // loop the sides wrap round the seam at the first anchor, where a vertex
  // just before the seam and one just after are neighbours.
  auto separation = [&](double a, double b) {
    const double d = std::abs(a - b);
    return closed ? std::min(d, 1.0 - d) : d;
  };
  for (std::size_t k = 0; k < from_source.size() && !from_target.empty(); ++k) {
    const double x = from_source[k].order;
    const std::size_t at =
        std::size_t(std::lower_bound(from_target.begin(), from_target.end(), Loose{x, 0}, by_order) -
                    from_target.begin());
    std::vector<std::size_t> sides;
    if (at < from_target.size()) sides.push_back(at);
    else if (closed) sides.push_back(0);
    if (at > 0) sides.push_back(at - 1);
    else if (closed) sides.push_back(from_target.size() - 1);
    for (const std::size_t j : sides) {
      if (t_taken[j] ||
          separation(from_target[j].order, x) >= kMergeShare * std::min(s_gap[k], t_gap[j]))
        continue;
      partner[k] = int(j);
      t_taken[j] = 1;
      break;
    }
  }
  for (std::size_t k = 0; k < from_source.size(); ++k) {
    const std::size_t slot = from_source[k].slot;
    const double u = vertex_parameter(s, slot);
    Item item{from_source[k].order, {s.vertices[slot], u}, {}};
    if (partner[k] >= 0) {
      const std::size_t ts = from_target[std::size_t(partner[k])].slot;
      item.target = {t.vertices[ts], vertex_parameter(t, ts)};
    } else {
      item.target = {-1, run_parameter(match.map.to_target(u), match.reversed)};
    }
    items.push_back(item);
  }
  for (std::size_t j = 0; j < from_target.size(); ++j) {
    if (t_taken[j]) continue;
    const std::size_t ts = from_target[j].slot;
    const double w = vertex_parameter(t, ts);
    const double u = match.map.to_source(run_parameter(w, match.reversed));
    items.push_back({from_target[j].order, {-1, u}, {t.vertices[ts], w}});
  }
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.order < b.order; });
  return items;
}

/// Where a place lies in the figure: its vertex, or a dummy on an edge.
/// `slot` (if not -1) is the track's edge the place must lie on: the one
/// between its neighbours in the matched sequence (dummy_slots).
MatchedPlace matched_place(const StickFigure& figure, const Track& track, const Place& place, Vec2& position,
                           char* track_runs_along = nullptr, int slot = -1) {
  MatchedPlace result;
  if (place.vertex >= 0) {
    result.vertex = place.vertex;
    position = figure.vertices[std::size_t(place.vertex)];
    return result;
  }
  auto [k, f] = locate(track, place.p);
  if (slot >= 0 && k != std::size_t(slot)) {
    // The parameter fell on a neighbouring edge: edges shorter than the
    // rounding of the arc length around them have the same arc values, and
    // locate takes the last. On the right edge, as near the parameter as
    // the arc allows (separate_on_edges parts it from the edge's ends).
    k = std::size_t(slot);
    double u = place.p;
    if (track.closed) u -= std::floor(u);
    const double at = std::clamp(u, 0.0, 1.0) * track.length();
    const double span = track.arc[k + 1] - track.arc[k];
    f = span > 0 ? std::clamp((at - track.arc[k]) / span, 0.0, 1.0) : 0.5;
  }
  const int a = track.vertices[k];
  const int edge = track.edges[k];
  // Reported along edges[edge] as listed.
  const bool along = figure.edges[std::size_t(edge)][0] == a;
  if (track_runs_along) *track_runs_along = along;
  result.edge = edge;
  result.fraction = along ? f : 1.0 - f;
  const Edge& e = figure.edges[std::size_t(edge)];
  position = point_on(figure.vertices[std::size_t(e[0])], figure.vertices[std::size_t(e[1])], result.fraction);
  return result;
}

/// Per item, the edge of `track` (its slot) that the item's place on this
/// side must lie on when it is not one of the track's vertices (-1 where it
/// is, or where the neighbours do not pin one edge down): the edge between
/// the nearest items before and after it that are the track's vertices, or
/// the chain's end nodes. The parameters alone cannot tell where edges are
/// shorter than the rounding of the arc length (a 10^37-long drawing with
/// vertices 10^20 apart: fuzz_correspond_pair), and a dummy on the wrong
/// side of a vertex breaks the subdivision. `vertex_of(item)` is the item's
/// vertex on this side or -1; `reversed` when the items run the track
/// backwards.
template <class VertexOf>
std::vector<int> dummy_slots(const Track& track, std::size_t figure_vertices, const std::vector<Item>& items,
                             const VertexOf& vertex_of, bool reversed) {
  const int n = int(track.vertices.size());
  std::vector<int> slot_of(figure_vertices, -1);
  for (int k = 0; k < n; ++k) slot_of[std::size_t(track.vertices[std::size_t(k)])] = k;
  std::vector<int> vertex_slot(items.size(), -1);
  for (std::size_t k = 0; k < items.size(); ++k) {
    const int v = vertex_of(items[k]);
    if (v >= 0) vertex_slot[k] = slot_of[std::size_t(v)];
  }
  const int m = int(items.size());
  // The slots of the track's vertices before and after each item in the
  // sequence, in one pass each way (a long run of dummies between two
  // vertices must not be walked once per dummy): a chain starts at one end
  // node and stops at the other, a loop wraps round, so its first items
  // follow its last vertex and its last items precede its first.
  const int none = -1;
  int last_vertex = none, first_vertex = none;
  for (int k = 0; k < m; ++k)
    if (vertex_slot[std::size_t(k)] >= 0) {
      if (first_vertex == none) first_vertex = vertex_slot[std::size_t(k)];
      last_vertex = vertex_slot[std::size_t(k)];
    }
  std::vector<int> before(items.size()), after(items.size());
  int seen = track.closed ? last_vertex : (reversed ? n - 1 : 0);
  for (int k = 0; k < m; ++k) {
    before[std::size_t(k)] = seen;
    if (vertex_slot[std::size_t(k)] >= 0) seen = vertex_slot[std::size_t(k)];
  }
  seen = track.closed ? first_vertex : (reversed ? 0 : n - 1);
  for (int k = m - 1; k >= 0; --k) {
    after[std::size_t(k)] = seen;
    if (vertex_slot[std::size_t(k)] >= 0) seen = vertex_slot[std::size_t(k)];
  }
  std::vector<int> slots(items.size(), -1);
  for (int k = 0; k < m; ++k) {
    const int b = before[std::size_t(k)], a = after[std::size_t(k)];
    if (vertex_slot[std::size_t(k)] >= 0 || b < 0 || a < 0) continue;
    // One edge apart along the track, in the items' direction.
    const int next = track.closed ? (b + (reversed ? n - 1 : 1)) % n : b + (reversed ? -1 : 1);
    if (next == a) slots[std::size_t(k)] = reversed ? a : b;
  }
  return slots;
}

/// Points placed inside one edge (dummies on a source edge, or source
/// vertices on a target edge), in the chain's order: a run of consecutive
/// places on the same edge. Where rounding a + f (b - a) merges two of them,
/// or one with an end of the edge (an edge far longer than the spacing of
/// the other drawing's vertices: 10 target vertices within 1e-16 of the
/// edge's length), the run is spread evenly along the whole edge instead,
/// in the same order. Only such a nearly degenerate run moves; the matched
/// figure is validated exactly afterwards all the same.
void separate_on_edges(const StickFigure& figure, std::vector<MatchedPlace>& places, std::vector<Vec2>& at,
                       const std::vector<char>& track_runs_along) {
  std::size_t begin = 0;
  while (begin < places.size()) {
    if (places[begin].vertex >= 0 || places[begin].edge < 0) {
      ++begin;
      continue;
    }
    const int edge = places[begin].edge;
    std::size_t end = begin + 1;
    while (end < places.size() && places[end].vertex < 0 && places[end].edge == edge) ++end;
    const Edge& e = figure.edges[std::size_t(edge)];
    const Vec2& a = figure.vertices[std::size_t(e[0])];
    const Vec2& b = figure.vertices[std::size_t(e[1])];
    // The track runs along the edge as listed or against it (not read from
    // the fractions: rounded ones tie).
    const bool along = track_runs_along[begin] != 0;
    const Vec2& first = along ? a : b;
    const Vec2& last = along ? b : a;
    bool merged = at[begin] == first || at[end - 1] == last;
    for (std::size_t k = begin + 1; k < end && !merged; ++k) merged = at[k] == at[k - 1];
    if (merged) {
      const double count = double(end - begin + 1);
      for (std::size_t k = begin; k < end; ++k) {
        const double g = double(k - begin + 1) / count;
        places[k].fraction = along ? g : 1.0 - g;
        at[k] = point_on(a, b, places[k].fraction);
      }
    }
    begin = end;
  }
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

CorrespondenceMode parse_correspondence_mode(const std::string& name) {
  if (name == "index") return CorrespondenceMode::ByIndex;
  if (name == "auto") return CorrespondenceMode::Auto;
  throw InvalidArgumentError("unknown correspondence '" + name + "' (choose index or auto)");
}

std::string correspondence_mode_name(CorrespondenceMode mode) {
  return mode == CorrespondenceMode::Auto ? "auto" : "index";
}

VertexPin parse_vertex_pin(const std::string& text) {
  const std::size_t colon = text.find(':');
  auto whole = [](const std::string& part, int& value) {
    if (part.empty() || part.size() > 9) return false;
    for (char c : part)
      if (c < '0' || c > '9') return false;
    value = std::stoi(part);
    return true;
  };
  VertexPin pin;
  if (colon == std::string::npos || !whole(text.substr(0, colon), pin.source) ||
      !whole(text.substr(colon + 1), pin.target))
    throw InvalidArgumentError("a pin is SOURCE:TARGET, two vertex indices such as 3:7, got '" + text + "'");
  return pin;
}

namespace {

// One connected figure matched to another (steps 1 to 4 of the header);
// `reference_rotation`: Skeleton::reference_rotation.
FigureCorrespondence correspond_connected(const StickFigure& source, const StickFigure& target,
                                          const CorrespondenceOptions& options, double reference_rotation = 0) {
  const auto start = std::chrono::steady_clock::now();
  Skeleton s = make_skeleton(source);
  s.reference_rotation = reference_rotation;
  const Skeleton t = make_skeleton(target);
  std::vector<std::pair<int, int>> node_pins;
  std::vector<PinPlace> chain_pins;
  classify_pins(s, t, options.pins, node_pins, chain_pins);
  compare_invariants(s, t);

  FigureCorrespondence result;
  result.skeleton_nodes = int(s.nodes.size());
  result.skeleton_chains = int(s.chains.size());
  Candidate chosen;
  if (source.edges.empty()) {
    // Two single vertices (compare_invariants): they match.
    chosen.node_image = {0};
    chosen.fit.residual = 0;  // a point fits a point exactly
    result.candidates = 1;
  } else if (s.is_loop()) {
    chosen = match_loops(s, t, chain_pins, result.candidates);
  } else {
    Search search = search_isomorphisms(s, t, node_pins, chain_pins, true);
    if (search.images.empty()) {
      if (!search.any_isomorphism) {
        // Reflected, would the skeletons match? Then say so.
        StickFigure mirrored = target;
        for (Vec2& p : mirrored.vertices) p[0] = -p[0];
        const Skeleton m = make_skeleton(mirrored);
        if (search_isomorphisms(s, m, {}, {}, false).any_exterior)
          throw IncompatibleFiguresError(Incompatibility::MirrorImage,
                                         "correspond: the target is a mirror image of the source: its junctions "
                                         "see their strokes in the reverse order, and a morph cannot reflect");
        topology_differs("the strokes meet in another arrangement (no matching of the junctions keeps the "
                         "counter-clockwise order of the strokes around every junction)");
      }
      if (!search.any_exterior)
        throw IncompatibleFiguresError(Incompatibility::ExteriorDiffers,
                                       "correspond: the figures match only with another face outside (the source's "
                                       "outer boundary would become an inner one)");
      throw IncompatibleFiguresError(Incompatibility::PinsUnsatisfiable,
                                     "correspond: no matching respects every pin (the first one tried breaks one: " +
                                         search.pin_conflict + ")");
    }
    result.candidates = int(search.images.size());
    // The winner rebuilt in full from its seed image (the search kept its fit only).
    const std::size_t best = best_fit(search.fits);
    const std::optional<std::vector<int>> map = extend_isomorphism(s, t, search.seed, search.images[best]);
    std::string broken;
    std::optional<Candidate> winner = map ? make_candidate(s, t, *map, node_pins, chain_pins, broken) : std::nullopt;
    if (!winner) throw InternalError("correspond: the best matching could not be rebuilt");
    chosen = std::move(*winner);
    chosen.fit = search.fits[best];
  }
  result.residual = chosen.fit.residual;
  result.rotation_degrees = chosen.fit.rotation * 180.0 / kPi;

  // The matched vertices: the source's first, then dummies for the
  // target's vertices that have no source partner, in target order.
  const int ns = int(source.vertices.size()), nt = int(target.vertices.size());
  std::vector<int> target_partner(std::size_t(ns), -1);   // source vertex -> target vertex or -1
  std::vector<int> matched_of_target(std::size_t(nt), -1);
  std::vector<Vec2> source_positions = source.vertices;
  std::vector<Vec2> target_positions(static_cast<std::size_t>(ns));
  result.source_places.resize(std::size_t(ns));
  result.target_places.resize(std::size_t(ns));
  for (int v = 0; v < ns; ++v) result.source_places[std::size_t(v)].vertex = v;
  for (int v = 0; v < ns; ++v)
    if (chosen.node_image[std::size_t(v)] >= 0) {
      const int image = chosen.node_image[std::size_t(v)];
      target_partner[std::size_t(v)] = image;
      result.target_places[std::size_t(v)].vertex = image;
      target_positions[std::size_t(v)] = target.vertices[std::size_t(image)];
      matched_of_target[std::size_t(image)] = v;
    }
  std::vector<std::pair<int, int>> all_pins;
  for (const VertexPin& pin : options.pins) all_pins.emplace_back(pin.source, pin.target);

  struct PendingDummy {  // a target vertex with no source partner
    int target_vertex;
    MatchedPlace source_place;
    Vec2 source_position;
  };
  std::vector<PendingDummy> dummies;
  // Edges as (matched vertex, matched vertex) with the target vertex of a
  // dummy standing in until the dummies are numbered (encoded as -1 - t).
  std::vector<std::array<int, 2>> chain_edges;
  for (const ChainMatch& match : chosen.chains) {
    const Track& st = s.chains[std::size_t(match.source_chain)];
    const Track& tt = t.chains[std::size_t(match.target_chain)];
    ChainMatch anchored = match;
    anchor_corners(source, st, target, tt, anchored);
    const std::vector<Item> items = resample(st, tt, anchored, all_pins);
    // Where each item lies on the other drawing, then kept apart where
    // rounding would merge points of one edge (separate_on_edges).
    std::vector<MatchedPlace> source_side(items.size()), target_side(items.size());
    std::vector<Vec2> source_side_at(items.size()), target_side_at(items.size());
    std::vector<char> source_along(items.size(), 1), target_along(items.size(), 1);
    const std::vector<int> source_slots = dummy_slots(
        st, source.vertices.size(), items, [](const Item& item) { return item.source.vertex; }, false);
    const std::vector<int> target_slots = dummy_slots(
        tt, target.vertices.size(), items, [](const Item& item) { return item.target.vertex; }, anchored.reversed);
    for (std::size_t k = 0; k < items.size(); ++k) {
      if (items[k].source.vertex < 0)
        source_side[k] =
            matched_place(source, st, items[k].source, source_side_at[k], &source_along[k], source_slots[k]);
      target_side[k] =
          matched_place(target, tt, items[k].target, target_side_at[k], &target_along[k], target_slots[k]);
    }
    separate_on_edges(source, source_side, source_side_at, source_along);
    separate_on_edges(target, target_side, target_side_at, target_along);
    std::vector<int> sequence;
    if (!st.closed) sequence.push_back(st.vertices.front());
    for (std::size_t k = 0; k < items.size(); ++k) {
      const Item& item = items[k];
      if (item.source.vertex >= 0) {
        const int v = item.source.vertex;
        result.target_places[std::size_t(v)] = target_side[k];
        target_positions[std::size_t(v)] = target_side_at[k];
        if (item.target.vertex >= 0) {
          target_partner[std::size_t(v)] = item.target.vertex;
          matched_of_target[std::size_t(item.target.vertex)] = v;
        }
        sequence.push_back(v);
      } else {
        dummies.push_back(PendingDummy{item.target.vertex, source_side[k], source_side_at[k]});
        sequence.push_back(-1 - item.target.vertex);
      }
    }
    if (!st.closed) sequence.push_back(st.vertices.back());
    const std::size_t count = st.closed ? sequence.size() : sequence.size() - 1;
    for (std::size_t k = 0; k < count; ++k) chain_edges.push_back({sequence[k], sequence[(k + 1) % sequence.size()]});
  }
  // Dummies numbered in target order after the source's vertices.
  std::sort(dummies.begin(), dummies.end(),
            [](const PendingDummy& a, const PendingDummy& b) { return a.target_vertex < b.target_vertex; });
  for (const PendingDummy& dummy : dummies) {
    const int index = int(source_positions.size());
    matched_of_target[std::size_t(dummy.target_vertex)] = index;
    source_positions.push_back(dummy.source_position);
    target_positions.push_back(target.vertices[std::size_t(dummy.target_vertex)]);
    result.source_places.push_back(dummy.source_place);
    MatchedPlace place;
    place.vertex = dummy.target_vertex;
    result.target_places.push_back(place);
  }
  for (int v = 0; v < nt; ++v)
    if (matched_of_target[std::size_t(v)] < 0)
      throw InternalError("correspond: target vertex " + std::to_string(v) + " was left unmatched");
  auto resolve = [&](int code) { return code >= 0 ? code : matched_of_target[std::size_t(-1 - code)]; };
  std::vector<std::array<std::int64_t, 2>> edges;
  edges.reserve(chain_edges.size());
  for (const auto& [a, b] : chain_edges) edges.push_back({resolve(a), resolve(b)});

  // The matched figures, validated like any input; then the proof that the
  // pair is compatible (section 2.1), which the construction promises.
  try {
    result.source = make_stick_figure(std::move(source_positions), edges, source.name);
    result.target = make_stick_figure(std::move(target_positions), edges, target.name);
  } catch (const InvalidFigureError& error) {
    throw VerificationError(std::string("correspond: the matched figure cannot be drawn in floating point: ") +
                            error.what() + " (vertices of one drawing closer together than the other's rounding)");
  }
  const CompatibilityReport report = check_compatibility(result.source, result.target);
  if (!report.compatible())
    throw InternalError("correspond: the matched figures are not compatible: " + report.reason);
  result.milliseconds = milliseconds_since(start);
  return result;
}

}  // namespace

// ------------------------------------------------------ several parts ---
//
// Issue 14: figures of several parts are matched part to part. The parts
// are paired first (same shape class, same nesting depth, nearest place in
// the figure), each pair is matched as above, and the matched parts are put
// together: the source's n vertices first, then every dummy in target order,
// as for one part. The whole matched pair is then checked, nesting included.

namespace {

// One part as a figure of its own, with the way back to the whole figure.
struct PartFigure {
  StickFigure figure;
  std::vector<int> global_vertex;  // local vertex -> figure vertex
  std::vector<int> global_edge;    // local edge -> figure edge
};

PartFigure part_figure(const StickFigure& whole, const FigureParts& parts, int part) {
  PartFigure result;
  result.global_vertex = parts.vertices[std::size_t(part)];
  std::vector<int> local(whole.vertices.size(), -1);
  for (std::size_t k = 0; k < result.global_vertex.size(); ++k) {
    local[std::size_t(result.global_vertex[k])] = int(k);
    result.figure.vertices.push_back(whole.vertices[std::size_t(result.global_vertex[k])]);
  }
  // Same order and direction as in the whole figure, so that a dummy's
  // fraction along its edge means the same in both.
  for (std::size_t e = 0; e < whole.edges.size(); ++e)
    if (local[std::size_t(whole.edges[e][0])] >= 0) {
      result.figure.edges.push_back({local[std::size_t(whole.edges[e][0])], local[std::size_t(whole.edges[e][1])]});
      result.global_edge.push_back(int(e));
    }
  result.figure.name = whole.name;
  return result;
}

// What a matching of two parts needs (compare_invariants): the number of
// independent cycles and the degrees of the nodes (vertices of degree
// other than 2), and nothing but a vertex for a lone vertex.
struct PartShape {
  int cycles = 0;
  std::vector<int> node_degrees;  // sorted
  bool operator==(const PartShape& other) const {
    return cycles == other.cycles && node_degrees == other.node_degrees;
  }
};

PartShape part_shape(const StickFigure& part) {
  PartShape shape;
  shape.cycles = int(part.edges.size()) - int(part.vertices.size()) + 1;
  std::vector<int> degree(part.vertices.size(), 0);
  for (const Edge& e : part.edges) ++degree[std::size_t(e[0])], ++degree[std::size_t(e[1])];
  for (int d : degree)
    if (d != 2) shape.node_degrees.push_back(d);
  std::sort(shape.node_degrees.begin(), shape.node_degrees.end());
  return shape;
}

std::string describe_shape(const PartShape& shape, std::size_t vertices) {
  if (vertices == 1) return "a lone vertex";
  int ends = 0;
  for (int d : shape.node_degrees) ends += d == 1;
  std::string text = plural(shape.cycles, "loop", "loops") + ", " + plural(ends, "end", "ends");
  const std::size_t junctions = shape.node_degrees.size() - std::size_t(ends);
  if (junctions) text += ", " + plural((long long)junctions, "junction", "junctions");
  return text;
}

// Where a part is in its figure: the centre and the diagonal of its
// bounding box, relative to the whole figure's box (centre at 0, diagonal
// 1). Boxes do not depend on how densely a stroke is sampled.
struct PartPlace {
  Vec2 center{0, 0};
  double size = 0;
};

std::vector<PartPlace> part_places(const StickFigure& whole, const FigureParts& parts) {
  auto box = [&](const std::vector<int>& vertices, Vec2& lo, Vec2& hi) {
    lo = hi = whole.vertices[std::size_t(vertices.front())];
    for (int v : vertices)
      for (int c = 0; c < 2; ++c) {
        lo[std::size_t(c)] = std::min(lo[std::size_t(c)], whole.vertices[std::size_t(v)][std::size_t(c)]);
        hi[std::size_t(c)] = std::max(hi[std::size_t(c)], whole.vertices[std::size_t(v)][std::size_t(c)]);
      }
  };
  std::vector<int> all(whole.vertices.size());
  std::iota(all.begin(), all.end(), 0);
  Vec2 lo, hi;
  box(all, lo, hi);
  const Vec2 center{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
  double diagonal = distance(lo, hi);
  if (!(diagonal > 0)) diagonal = 1;
  std::vector<PartPlace> places;
  for (const std::vector<int>& vertices : parts.vertices) {
    Vec2 a, b;
    box(vertices, a, b);
    PartPlace place;
    place.center = {(0.5 * (a[0] + b[0]) - center[0]) / diagonal, (0.5 * (a[1] + b[1]) - center[1]) / diagonal};
    place.size = distance(a, b) / diagonal;
    places.push_back(place);
  }
  return places;
}

// The assignment of least total cost (the Hungarian method with
// potentials, O(k^3)): row i gets column result[i].
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

std::string without_prefix(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0 ? text.substr(prefix.size()) : text;
}

FigureCorrespondence correspond_parts(const StickFigure& source, const StickFigure& target,
                                      const CorrespondenceOptions& options, const FigureParts& source_parts,
                                      const FigureParts& target_parts) {
  const auto start = std::chrono::steady_clock::now();
  const int k = source_parts.count();
  // The pins' own rules first: a bad pin is the caller's mistake whatever
  // the figures are.
  auto degrees = [](const StickFigure& f) {
    std::vector<int> degree(f.vertices.size(), 0);
    for (const Edge& e : f.edges) ++degree[std::size_t(e[0])], ++degree[std::size_t(e[1])];
    return degree;
  };
  check_pins(degrees(source), degrees(target), options.pins);
  if (target_parts.count() != k)
    topology_differs("the source has " + plural(k, "part", "parts") + " and the target " +
                     std::to_string(target_parts.count()) + " (parts are the connected pieces of a figure)");
  const int ns = int(source.vertices.size());

  std::vector<PartFigure> source_pieces, target_pieces;
  std::vector<PartShape> source_shapes, target_shapes;
  for (int p = 0; p < k; ++p) {
    source_pieces.push_back(part_figure(source, source_parts, p));
    target_pieces.push_back(part_figure(target, target_parts, p));
    source_shapes.push_back(part_shape(source_pieces.back().figure));
    target_shapes.push_back(part_shape(target_pieces.back().figure));
  }
  // Nesting depth: how many parts enclose a part. Matched parts must agree.
  const PartNesting source_nesting = part_nesting(source, decompose(source), source_parts);
  const PartNesting target_nesting = part_nesting(target, decompose(target), target_parts);
  // And what they hold: a part's shape with the sorted contents of the
  // parts directly inside it, recursively, so that a square holding a
  // triangle is never paired with an empty hexagon (its triangle would have
  // nowhere to go).
  auto contents = [](const std::vector<PartShape>& shapes, const PartNesting& nesting) {
    const std::size_t count = shapes.size();
    std::vector<std::string> text(count);
    std::vector<std::size_t> order(count);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return nesting.enclosing[a].size() > nesting.enclosing[b].size();
    });
    std::vector<std::vector<std::string>> inside(count);
    for (std::size_t part : order) {  // the deepest first
      std::sort(inside[part].begin(), inside[part].end());
      std::string t = std::to_string(shapes[part].cycles) + ":";
      for (int d : shapes[part].node_degrees) t += std::to_string(d) + ",";
      t += "(";
      for (const std::string& child : inside[part]) t += child + ";";
      text[part] = t + ")";
      if (nesting.parent_part[part] >= 0) inside[std::size_t(nesting.parent_part[part])].push_back(text[part]);
    }
    return text;
  };
  const std::vector<std::string> source_contents = contents(source_shapes, source_nesting);
  const std::vector<std::string> target_contents = contents(target_shapes, target_nesting);

  // Pins pair parts.
  std::vector<int> forced(std::size_t(k), -1), forced_by(std::size_t(k), -1);
  std::vector<std::string> forcing_pin(static_cast<std::size_t>(k));
  for (const VertexPin& pin : options.pins) {
    const int a = source_parts.part_of_vertex[std::size_t(pin.source)];
    const int b = target_parts.part_of_vertex[std::size_t(pin.target)];
    const std::string name = "pin " + std::to_string(pin.source) + ":" + std::to_string(pin.target);
    if ((forced[std::size_t(a)] >= 0 && forced[std::size_t(a)] != b) ||
        (forced_by[std::size_t(b)] >= 0 && forced_by[std::size_t(b)] != a))
      throw IncompatibleFiguresError(Incompatibility::PinsUnsatisfiable,
                                     "correspond: " + name + " and " +
                                         forcing_pin[std::size_t(forced[std::size_t(a)] >= 0 ? a : forced_by[std::size_t(b)])] +
                                         " pair one part of a figure with two parts of the other");
    forced[std::size_t(a)] = b;
    forced_by[std::size_t(b)] = a;
    forcing_pin[std::size_t(a)] = name;
  }

  const std::vector<PartPlace> source_places = part_places(source, source_parts);
  const std::vector<PartPlace> target_places = part_places(target, target_parts);
  auto allowed = [&](int a, int b) {
    return source_contents[std::size_t(a)] == target_contents[std::size_t(b)] &&
           source_nesting.enclosing[std::size_t(a)].size() == target_nesting.enclosing[std::size_t(b)].size() &&
           (forced[std::size_t(a)] < 0 || forced[std::size_t(a)] == b) &&
           (forced_by[std::size_t(b)] < 0 || forced_by[std::size_t(b)] == a);
  };

  // The reference pair: the source's largest part and the target part of
  // its shape and depth nearest in size. Its match gives the whole figure's
  // rotation and scale, which place the other parts (a target turned a
  // quarter turn has its parts a quarter turn round) and which symmetric
  // parts are charged from (Skeleton::reference_rotation).
  int reference = 0;
  for (int a = 1; a < k; ++a)
    if (source_places[std::size_t(a)].size > source_places[std::size_t(reference)].size) reference = a;
  int reference_partner = -1;
  for (int b = 0; b < k; ++b)
    if (allowed(reference, b) &&
        (reference_partner < 0 || std::abs(target_places[std::size_t(b)].size - source_places[std::size_t(reference)].size) <
                                      std::abs(target_places[std::size_t(reference_partner)].size -
                                               source_places[std::size_t(reference)].size)))
      reference_partner = b;
  std::vector<FigureCorrespondence> matched(static_cast<std::size_t>(k));
  std::vector<bool> done(std::size_t(k), false);
  auto match_pair = [&](int a, int b, double reference_rotation) {
    const PartFigure& sp = source_pieces[std::size_t(a)];
    const PartFigure& tp = target_pieces[std::size_t(b)];
    CorrespondenceOptions local;
    for (const VertexPin& pin : options.pins)
      if (source_parts.part_of_vertex[std::size_t(pin.source)] == a) {
        VertexPin l;
        l.source = int(std::find(sp.global_vertex.begin(), sp.global_vertex.end(), pin.source) - sp.global_vertex.begin());
        l.target = int(std::find(tp.global_vertex.begin(), tp.global_vertex.end(), pin.target) - tp.global_vertex.begin());
        local.pins.push_back(l);
      }
    const std::string which = "correspond: " + describe_part(source_parts, a) + " of the source and " +
                              describe_part(target_parts, b) + " of the target (numbered within each part): ";
    try {
      matched[std::size_t(a)] = correspond_connected(sp.figure, tp.figure, local, reference_rotation);
    } catch (const IncompatibleFiguresError& error) {
      throw IncompatibleFiguresError(error.kind(), which + without_prefix(error.what(), "correspond: "),
                                     {sp.global_vertex.front()});
    } catch (const InvalidArgumentError& error) {
      throw InvalidArgumentError(which + without_prefix(error.what(), "correspond: "));
    }
    done[std::size_t(a)] = true;
  };
  double rotation = 0, scale = 1;
  if (reference_partner >= 0) {
    match_pair(reference, reference_partner, 0.0);
    rotation = matched[std::size_t(reference)].rotation_degrees * kPi / 180.0;
    if (source_places[std::size_t(reference)].size > 0 && target_places[std::size_t(reference_partner)].size > 0)
      scale = target_places[std::size_t(reference_partner)].size / source_places[std::size_t(reference)].size;
  }
  // Where part a would be in the target if the whole figure moved like the
  // reference pair.
  auto predicted = [&](int a) {
    if (reference_partner < 0) return source_places[std::size_t(a)].center;
    const Vec2& o = source_places[std::size_t(reference)].center;
    const Vec2& p = source_places[std::size_t(a)].center;
    const double dx = p[0] - o[0], dy = p[1] - o[1];
    const double c = std::cos(rotation), s = std::sin(rotation);
    const Vec2& q = target_places[std::size_t(reference_partner)].center;
    return Vec2{q[0] + scale * (c * dx - s * dy), q[1] + scale * (s * dx + c * dy)};
  };

  // The parts paired level by level from the outside in, so that a part's
  // partner lies in its parent's partner (the matched figures then nest
  // alike wherever the parents' faces correspond). A pairing that cannot
  // match costs more than any that can (kBarred), so that the assignment
  // uses one only where nothing else is left.
  constexpr double kBarred = 1e12;
  std::vector<int> partner(std::size_t(k), -1);
  std::size_t deepest = 0;
  for (int a = 0; a < k; ++a) deepest = std::max(deepest, source_nesting.enclosing[std::size_t(a)].size());
  for (std::size_t depth = 0; depth <= deepest; ++depth) {
    std::vector<int> rows, columns;
    for (int a = 0; a < k; ++a)
      if (source_nesting.enclosing[std::size_t(a)].size() == depth) rows.push_back(a);
    for (int b = 0; b < k; ++b)
      if (target_nesting.enclosing[std::size_t(b)].size() == depth) columns.push_back(b);
    if (rows.empty()) continue;
    if (rows.size() != columns.size()) {
      // Name a part of the figure that has more at this depth: its smallest
      // (the part that moved is more often a dot or a counter than the
      // part around it).
      const bool source_more = rows.size() > columns.size();
      const std::vector<int>& more = source_more ? rows : columns;
      const std::vector<PartPlace>& places = source_more ? source_places : target_places;
      int named = more.front();
      for (int part : more)
        if (places[std::size_t(part)].size < places[std::size_t(named)].size) named = part;
      const std::string where = depth == 0 ? std::string("at the top level (inside no other part)")
                                           : "inside " + plural((long long)depth, "other part", "other parts");
      throw IncompatibleFiguresError(
          Incompatibility::NestingDiffers,
          "correspond: the parts nest differently: the source has " + plural((long long)rows.size(), "part", "parts") +
              " " + where + " and the target " + std::to_string(columns.size()) + " (" +
              describe_part(source_more ? source_parts : target_parts, named) + " of the " +
              (source_more ? "source" : "target") + " is one of them)",
          source_more ? std::vector<int>{source_parts.vertices[std::size_t(named)].front()} : std::vector<int>{});
    }
    std::vector<std::vector<double>> cost(rows.size(), std::vector<double>(columns.size(), 0.0));
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (std::size_t j = 0; j < columns.size(); ++j) {
        const int a = rows[i], b = columns[j];
        const int parent = source_nesting.parent_part[std::size_t(a)];
        bool possible = allowed(a, b) &&
                        (parent < 0 || partner[std::size_t(parent)] == target_nesting.parent_part[std::size_t(b)]) &&
                        (a != reference || reference_partner < 0 || b == reference_partner);
        const Vec2 x = predicted(a);
        const PartPlace& y = target_places[std::size_t(b)];
        const double dx = x[0] - y.center[0], dy = x[1] - y.center[1];
        const double ds = scale * source_places[std::size_t(a)].size - y.size;
        cost[i][j] = (possible ? 0.0 : kBarred) + dx * dx + dy * dy + 0.25 * ds * ds;
      }
    const std::vector<int> chosen = least_cost_assignment(cost);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const int a = rows[i], b = columns[std::size_t(chosen[i])];
      if (cost[i][std::size_t(chosen[i])] >= kBarred) {
        const PartShape& shape = source_shapes[std::size_t(a)];
        std::string why = "no part of the target is left for " + describe_part(source_parts, a) + " of the source (" +
                          describe_shape(shape, source_parts.vertices[std::size_t(a)].size()) + ", inside " +
                          plural((long long)depth, "other part", "other parts") +
                          ") that has its shape, holds the same parts and lies in the part matched to its parent";
        if (forced[std::size_t(a)] >= 0) {
          why += "; " + forcing_pin[std::size_t(a)] + " pairs it with " +
                 describe_part(target_parts, forced[std::size_t(a)]) + " of the target";
          throw IncompatibleFiguresError(Incompatibility::PinsUnsatisfiable, "correspond: " + why,
                                         {source_parts.vertices[std::size_t(a)].front()});
        }
        topology_differs(why);
      }
      partner[std::size_t(a)] = b;
    }
  }

  // Each pair matched on its own, charged from the whole figure's rotation.
  FigureCorrespondence result;
  std::size_t largest = 0;
  double weight = 0;
  for (int a = 0; a < k; ++a) {
    if (!done[std::size_t(a)]) match_pair(a, partner[std::size_t(a)], rotation);
    const FigureCorrespondence& m = matched[std::size_t(a)];
    const PartFigure& sp = source_pieces[std::size_t(a)];
    result.skeleton_nodes += m.skeleton_nodes;
    result.skeleton_chains += m.skeleton_chains;
    result.candidates += m.candidates;
    // The residual of the whole: the parts' residuals weighted by their
    // matched vertices.
    result.residual += m.residual * double(m.source_places.size());
    weight += double(m.source_places.size());
    if (sp.figure.vertices.size() > largest) {
      largest = sp.figure.vertices.size();
      result.rotation_degrees = m.rotation_degrees;
    }
  }
  if (weight > 0) result.residual /= weight;

  // Put together: the source's vertices keep their numbers; the dummies of
  // every part follow, ordered by the target vertex they stand for.
  std::vector<std::pair<int, std::pair<int, int>>> dummies;  // (target vertex, (part, local matched index))
  for (int a = 0; a < k; ++a) {
    const FigureCorrespondence& m = matched[std::size_t(a)];
    const PartFigure& tp = target_pieces[std::size_t(partner[std::size_t(a)])];
    for (std::size_t i = source_pieces[std::size_t(a)].global_vertex.size(); i < m.source_places.size(); ++i)
      dummies.push_back({tp.global_vertex[std::size_t(m.target_places[i].vertex)], {a, int(i)}});
  }
  std::sort(dummies.begin(), dummies.end());
  std::vector<std::vector<int>> global_index(static_cast<std::size_t>(k));
  for (int a = 0; a < k; ++a) {
    global_index[std::size_t(a)] = source_pieces[std::size_t(a)].global_vertex;
    global_index[std::size_t(a)].resize(matched[std::size_t(a)].source_places.size(), -1);
  }
  for (std::size_t d = 0; d < dummies.size(); ++d)
    global_index[std::size_t(dummies[d].second.first)][std::size_t(dummies[d].second.second)] = ns + int(d);
  const std::size_t m_total = std::size_t(ns) + dummies.size();
  std::vector<Vec2> source_positions(m_total), target_positions(m_total);
  result.source_places.resize(m_total);
  result.target_places.resize(m_total);
  std::vector<std::array<std::int64_t, 2>> edges;
  auto globalise = [](MatchedPlace place, const PartFigure& piece) {
    if (place.vertex >= 0) place.vertex = piece.global_vertex[std::size_t(place.vertex)];
    if (place.edge >= 0) place.edge = piece.global_edge[std::size_t(place.edge)];
    return place;
  };
  for (int a = 0; a < k; ++a) {
    const FigureCorrespondence& m = matched[std::size_t(a)];
    const PartFigure& sp = source_pieces[std::size_t(a)];
    const PartFigure& tp = target_pieces[std::size_t(partner[std::size_t(a)])];
    const std::vector<int>& index = global_index[std::size_t(a)];
    for (std::size_t i = 0; i < m.source_places.size(); ++i) {
      const std::size_t g = std::size_t(index[i]);
      source_positions[g] = m.source.vertices[i];
      target_positions[g] = m.target.vertices[i];
      result.source_places[g] = globalise(m.source_places[i], sp);
      result.target_places[g] = globalise(m.target_places[i], tp);
    }
    for (const Edge& e : m.source.edges) edges.push_back({index[std::size_t(e[0])], index[std::size_t(e[1])]});
  }
  try {
    result.source = make_stick_figure(std::move(source_positions), edges, source.name);
    result.target = make_stick_figure(std::move(target_positions), edges, target.name);
  } catch (const InvalidFigureError& error) {
    // Each matched part is valid; together they can only fail where a dummy,
    // rounded off its edge, touches a part close by.
    throw VerificationError(std::string("correspond: the matched parts cannot be drawn in floating point: ") +
                            error.what());
  }
  // Each part pair is compatible by construction; the nesting is the pair's
  // own (the matched part i is the source's part i), and is checked here.
  const CompatibilityReport report = check_compatibility(result.source, result.target);
  if (report.kind == Incompatibility::NestingDiffers)
    throw IncompatibleFiguresError(Incompatibility::NestingDiffers,
                                   "correspond: with the parts matched by shape and place, " + report.reason +
                                       " (vertices of the matched figure)",
                                   report.vertices);
  if (!report.compatible())
    throw InternalError("correspond: the matched figures are not compatible: " + report.reason);
  result.milliseconds = milliseconds_since(start);
  return result;
}

}  // namespace

namespace {

FigureCorrespondence correspond_at_scale(const StickFigure& source, const StickFigure& target,
                                         const CorrespondenceOptions& options) {
  const FigureParts source_parts = figure_parts(source), target_parts = figure_parts(target);
  if (source_parts.count() == 1 && target_parts.count() == 1) return correspond_connected(source, target, options);
  return correspond_parts(source, target, options, source_parts, target_parts);
}

}  // namespace

FigureCorrespondence correspond_figures(const StickFigure& source, const StickFigure& target,
                                        const CorrespondenceOptions& options) {
  // In the morph's working scale (working_scale.h): the similarity fits and
  // arc lengths square coordinates, which overflow for figures near 1e99
  // (a NaN residual) and underflow near 1e-200. The match is scale-free
  // (its residual and rotation are ratios); only the matched positions
  // are multiplied back.
  const int exponent = working_scale_exponent(source, target);
  if (exponent == 0) return correspond_at_scale(source, target, options);
  FigureCorrespondence matched =
      correspond_at_scale(scaled_figure(source, exponent), scaled_figure(target, exponent), options);
  for (StickFigure* figure : {&matched.source, &matched.target})
    for (Vec2& p : figure->vertices)
      for (double& c : p) c = std::ldexp(c, -exponent);
  // Exact but for dummies that land within 2^-1022 of 0: checked again.
  if (!is_valid(matched, source, target))
    throw NumericRangeError("the matched figures, once written at the figures' own scale, are no longer valid: "
                            "their dummy vertices round below the smallest normal double");
  return matched;
}

bool is_valid(const FigureCorrespondence& c, const StickFigure& source, const StickFigure& target) {
  const std::size_t m = c.source.vertices.size();
  if (c.target.vertices.size() != m || c.source_places.size() != m || c.target_places.size() != m) return false;
  if (c.source.edges != c.target.edges || !is_valid(c.source) || !is_valid(c.target)) return false;
  auto check_side = [&](const StickFigure& figure, const StickFigure& matched, const std::vector<MatchedPlace>& places) {
    std::vector<int> seen(figure.vertices.size(), 0);
    for (std::size_t i = 0; i < m; ++i) {
      const MatchedPlace& place = places[i];
      if (place.vertex >= 0) {
        if (place.vertex >= int(figure.vertices.size()) || seen[std::size_t(place.vertex)]++) return false;
        if (matched.vertices[i] != figure.vertices[std::size_t(place.vertex)]) return false;
        continue;
      }
      if (place.edge < 0 || place.edge >= int(figure.edges.size())) return false;
      if (!(place.fraction > 0 && place.fraction < 1)) return false;
      const Edge& e = figure.edges[std::size_t(place.edge)];
      if (matched.vertices[i] != point_on(figure.vertices[std::size_t(e[0])], figure.vertices[std::size_t(e[1])],
                                          place.fraction))
        return false;
    }
    if (std::find(seen.begin(), seen.end(), 0) != seen.end()) return false;
    // Every matched edge on one original edge: its ends are that edge's
    // vertices or dummies on it, and the original edges are covered once.
    std::vector<double> covered(figure.edges.size(), 0.0);
    for (const Edge& me : matched.edges) {
      const MatchedPlace& a = places[std::size_t(me[0])];
      const MatchedPlace& b = places[std::size_t(me[1])];
      int edge = a.vertex < 0 ? a.edge : b.vertex < 0 ? b.edge : -1;
      if (edge < 0) {
        edge = find_edge(figure, a.vertex, b.vertex);
        if (edge < 0) return false;
      }
      const Edge& e = figure.edges[std::size_t(edge)];
      auto along = [&](const MatchedPlace& p) -> double {
        if (p.vertex < 0) return p.edge == edge ? p.fraction : -1.0;
        return p.vertex == e[0] ? 0.0 : p.vertex == e[1] ? 1.0 : -1.0;
      };
      const double fa = along(a), fb = along(b);
      if (fa < 0 || fb < 0 || fa == fb) return false;
      covered[std::size_t(edge)] += std::abs(fb - fa);
    }
    for (double share : covered)
      if (std::abs(share - 1.0) > 1e-9) return false;
    return true;
  };
  return check_side(source, c.source, c.source_places) && check_side(target, c.target, c.target_places);
}

}  // namespace stickmorph
