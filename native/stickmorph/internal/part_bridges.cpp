// Bridges between the parts of a figure (issue 14); see part_bridges.h.
#include "stickmorph/internal/part_bridges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "stickmorph/compatibility.h"
#include "stickmorph/errors.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/figure_parts.h"
#include "stickmorph/internal/corner_router.h"

namespace stickmorph::internal {
namespace {

// Corner k of sequence s: where the walk arrives at vertices[k] and leaves.
RouteCorner corner_of(const StickFigure& f, const Decomposition& d, int s, int k) {
  const CyclicSequence& seq = d.sequences[std::size_t(s)];
  RouteCorner c;
  c.vertex = seq.vertices[std::size_t(k)];
  if (seq.darts.empty()) return c;  // a lone vertex: every direction
  const std::size_t m = seq.vertices.size();
  c.next = seq.vertices[(std::size_t(k) + 1) % m];
  c.prev = dart_tail(f, seq.darts[std::size_t(k)]);
  return c;
}

// A box around the points with a margin of half their extent: routes
// between parts at the top level may have to pass outside the figure's
// convex hull (the exterior corner of a hull vertex opens only outwards).
std::vector<Vec2> frame_around(const std::vector<Vec2>& points) {
  Vec2 lo = points.front(), hi = points.front();
  for (const Vec2& p : points)
    for (int c = 0; c < 2; ++c)
      lo[std::size_t(c)] = std::min(lo[std::size_t(c)], p[std::size_t(c)]),
      hi[std::size_t(c)] = std::max(hi[std::size_t(c)], p[std::size_t(c)]);
  double margin = 0.5 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if (!(margin > 0)) margin = std::max(1.0, 1e-6 * std::max(std::abs(lo[0]), std::abs(lo[1])));
  return {{lo[0] - margin, lo[1] - margin}, {hi[0] + margin, lo[1] - margin}, {hi[0] + margin, hi[1] + margin},
          {lo[0] - margin, hi[1] + margin}};
}

// One figure with the bridges made so far: nodes (the figure's vertices,
// then the bends) and the segments that a new bridge must not meet.
struct Side {
  std::vector<Vec2> nodes;
  std::vector<Edge> segments;
  std::vector<int> degree;  // per node
  std::vector<std::vector<int>> bridged_to;  // per figure vertex: the nodes its bridges leave to
  CornerRouter router;

  Side(const StickFigure& f)
      : nodes(f.vertices), segments(f.edges), degree(f.vertices.size(), 0), bridged_to(f.vertices.size()),
        router(f.vertices, f.edges, frame_around(f.vertices)) {
    for (const Edge& e : f.edges) ++degree[std::size_t(e[0])], ++degree[std::size_t(e[1])];
  }

  // Exact: does the segment from p to q (nodes p_node and q_node, or -1 for
  // a free point) meet nothing but the segments at its own end nodes, and
  // those only there?
  bool clear(int p_node, const Vec2& p, int q_node, const Vec2& q) const {
    const double lo_x = std::min(p[0], q[0]), hi_x = std::max(p[0], q[0]);
    const double lo_y = std::min(p[1], q[1]), hi_y = std::max(p[1], q[1]);
    for (const Edge& e : segments) {
      const Vec2& a = nodes[std::size_t(e[0])];
      const Vec2& b = nodes[std::size_t(e[1])];
      if (std::max(a[0], b[0]) < lo_x || std::min(a[0], b[0]) > hi_x || std::max(a[1], b[1]) < lo_y ||
          std::min(a[1], b[1]) > hi_y)
        continue;
      const SegmentContact contact = segment_contact(p, q, a, b);
      if (contact == SegmentContact::Disjoint) continue;
      const bool shares = (p_node >= 0 && (e[0] == p_node || e[1] == p_node)) ||
                          (q_node >= 0 && (e[0] == q_node || e[1] == q_node));
      if (contact == SegmentContact::Touching && shares) continue;
      return false;
    }
    for (std::size_t w = 0; w < nodes.size(); ++w)
      if (degree[w] == 0 && int(w) != p_node && int(w) != q_node && on_segment(nodes[w], p, q)) return false;
    return true;
  }

  // Exact: does the direction from the corner's vertex to q leave it
  // strictly inside the corner's wedge?
  bool admits(const RouteCorner& c, const Vec2& q) const {
    if (c.next < 0) return true;
    return strictly_inside_corner(nodes[std::size_t(c.vertex)], nodes[std::size_t(c.next)],
                                  nodes[std::size_t(c.prev)], c.next == c.prev, q);
  }

  bool straight(const RouteCorner& from, const RouteCorner& to) const {
    const Vec2& p = nodes[std::size_t(from.vertex)];
    const Vec2& q = nodes[std::size_t(to.vertex)];
    return admits(from, q) && admits(to, p) && clear(from.vertex, p, to.vertex, q);
  }

  // Exact: is the path from corner `from` through `bends` to corner `to`
  // a valid bridge? It leaves and enters inside the corners' wedges, meets
  // nothing made so far but its two end vertices' own edges there, and does
  // not meet itself (consecutive segments share only their common point).
  bool path_clear(const RouteCorner& from, const RouteCorner& to, const std::vector<Vec2>& bends) const {
    std::vector<Vec2> path{nodes[std::size_t(from.vertex)]};
    path.insert(path.end(), bends.begin(), bends.end());
    path.push_back(nodes[std::size_t(to.vertex)]);
    const std::size_t segments_count = path.size() - 1;
    if (!admits(from, path[1]) || !admits(to, path[segments_count - 1])) return false;
    for (std::size_t i = 0; i < segments_count; ++i) {
      if (!clear(i == 0 ? from.vertex : -1, path[i], i + 1 == segments_count ? to.vertex : -1, path[i + 1]))
        return false;
      for (std::size_t j = i + 1; j < segments_count; ++j) {
        const SegmentContact contact = segment_contact(path[i], path[i + 1], path[j], path[j + 1]);
        if (contact == SegmentContact::Disjoint) continue;
        if (j == i + 1 && contact == SegmentContact::Touching) continue;
        return false;
      }
    }
    return true;
  }

  // A routed path, shortened greedily: from each point, the farthest later
  // point that a valid straight shortcut reaches (only a few are tried, so
  // that a long path costs linear work). The shortened path, or else the
  // route itself, if it passes path_clear (a midpoint rounded across an
  // edge, or a shortcut across the path's own later part, would not).
  bool routed(const RouteCorner& from, const RouteCorner& to, std::vector<Vec2>& bends) const {
    std::vector<Vec2> raw;
    if (!router.route(from, to, raw)) return false;
    std::vector<Vec2> path{nodes[std::size_t(from.vertex)]};
    path.insert(path.end(), raw.begin(), raw.end());
    path.push_back(nodes[std::size_t(to.vertex)]);
    const std::size_t last = path.size() - 1;
    // A straight shortcut from point i to point j, exactly checked.
    auto valid = [&](std::size_t i, std::size_t j) {
      if (i == 0 && !admits(from, path[j])) return false;
      if (j == last && !admits(to, path[i])) return false;
      return clear(i == 0 ? from.vertex : -1, path[i], j == last ? to.vertex : -1, path[j]);
    };
    bends.clear();
    std::size_t i = 0;
    while (i < last) {
      // The end if it is in sight; else the farthest point in sight found
      // by doubling the step and then halving the gap (O(log) checks).
      std::size_t next = i + 1;
      if (i + 2 <= last && valid(i, last)) {
        next = last;
      } else {
        std::size_t good = i + 1, step = 2;
        while (i + step < last && valid(i, i + step)) good = i + step, step *= 2;
        std::size_t bad = std::min(i + step, last);
        while (bad - good > 1) {
          const std::size_t middle = good + (bad - good) / 2;
          (valid(i, middle) ? good : bad) = middle;
        }
        next = good;
      }
      if (next < last) bends.push_back(path[next]);
      i = next;
    }
    if (path_clear(from, to, bends)) return true;
    bends = raw;
    return path_clear(from, to, bends);
  }

  // A corner of the figure as it is now: the bridges that leave its vertex
  // inside its wedge split it into several, in counter-clockwise order from
  // `next`. Compatible figures have the same order (the bridges left the
  // same corners in both), so the source's order serves both.
  std::vector<RouteCorner> split(const RouteCorner& c) const {
    const std::vector<int>& out = bridged_to[std::size_t(c.vertex)];
    const Vec2& v = nodes[std::size_t(c.vertex)];
    std::vector<int> inside;
    for (int b : out)
      if (c.next < 0 || admits(c, nodes[std::size_t(b)])) inside.push_back(b);
    if (inside.empty()) return {c};
    // Counter-clockwise from a reference direction: first the half-turn
    // left of it, then the rest (exact orientation tests).
    const int reference = c.next >= 0 ? c.next : inside.front();
    const Vec2& r = nodes[std::size_t(reference)];
    auto half = [&](int b) { return orientation(v, r, nodes[std::size_t(b)]) > 0 ? 0 : 1; };
    std::sort(inside.begin(), inside.end(), [&](int a, int b) {
      if (a == reference || b == reference) return a == reference && b != reference;
      const int ha = half(a), hb = half(b);
      if (ha != hb) return ha < hb;
      return orientation(v, nodes[std::size_t(a)], nodes[std::size_t(b)]) > 0;
    });
    std::vector<RouteCorner> pieces;
    if (c.next < 0) {
      // A lone vertex with bridges: the wedges between consecutive ones,
      // each from one bridge counter-clockwise to the next (one bridge: all
      // round, a tip).
      for (std::size_t i = 0; i < inside.size(); ++i)
        pieces.push_back({c.vertex, inside[i], inside[(i + 1) % inside.size()]});
      return pieces;
    }
    int from = c.next;
    for (int b : inside) {
      pieces.push_back({c.vertex, from, b});
      from = b;
    }
    pieces.push_back({c.vertex, from, c.prev});
    return pieces;
  }

  void add(int from, int to, const std::vector<Vec2>& bends) {
    int previous = from;
    for (const Vec2& b : bends) {
      const int node = int(nodes.size());
      nodes.push_back(b);
      degree.push_back(0);
      if (router.add_node(b) != node) throw InternalError("part bridges: the router's nodes are out of step");
      link(previous, node);
      previous = node;
    }
    link(previous, to);
  }

  void link(int a, int b) {
    if (std::size_t(a) < bridged_to.size()) bridged_to[std::size_t(a)].push_back(b);
    if (std::size_t(b) < bridged_to.size()) bridged_to[std::size_t(b)].push_back(a);
    segments.push_back({a, b});
    ++degree[std::size_t(a)], ++degree[std::size_t(b)];
    router.add_constraint(a, b);
  }
};

double distance(const Vec2& a, const Vec2& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

}  // namespace

BridgedFigures bridge_parts(const CompatiblePair& pair) {
  const StickFigure& source = pair.source();
  const StickFigure& target = pair.target();
  const Decomposition& dec = pair.source_decomposition();
  const FigureParts& parts = pair.figure_parts();
  const PartNesting& nesting = pair.source_nesting();
  const int count = parts.count();
  Side sides[2] = {Side(source), Side(target)};
  BridgedFigures result;

  // Parts from the outside in; the first part at the top level is the root.
  std::vector<int> order(static_cast<std::size_t>(count));
  for (int p = 0; p < count; ++p) order[std::size_t(p)] = p;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return nesting.enclosing[std::size_t(a)].size() < nesting.enclosing[std::size_t(b)].size();
  });
  std::vector<bool> bridged(std::size_t(count), false);

  for (int part : order) {
    const int parent = nesting.parent_part[std::size_t(part)];
    const int parent_face = nesting.parent_sequence[std::size_t(part)];
    // Where the bridge may land: the parent's face and the exteriors of the
    // parts already bridged that lie directly in the same face.
    std::vector<int> goal_sequences;
    if (parent >= 0) goal_sequences.push_back(parent_face);
    for (int other = 0; other < count; ++other)
      if (other != part && bridged[std::size_t(other)] && nesting.parent_part[std::size_t(other)] == parent &&
          nesting.parent_sequence[std::size_t(other)] == parent_face)
        goal_sequences.push_back(dec.exterior_of_part[std::size_t(other)]);
    bridged[std::size_t(part)] = true;
    if (goal_sequences.empty()) {
      if (parent >= 0) throw InternalError("part bridges: part " + std::to_string(part) + " has no face to join");
      continue;  // the root
    }

    std::vector<RouteCorner> starts, goals;
    const int own = dec.exterior_of_part[std::size_t(part)];
    // No bridge has reached this part yet (its parent's face and its
    // siblings are bridged before it, its children after).
    for (std::size_t k = 0; k < dec.sequences[std::size_t(own)].vertices.size(); ++k)
      starts.push_back(corner_of(source, dec, own, int(k)));
    // The corners of the face as the bridges so far have made it.
    for (int s : goal_sequences)
      for (std::size_t k = 0; k < dec.sequences[std::size_t(s)].vertices.size(); ++k)
        for (const RouteCorner& c : sides[0].split(corner_of(source, dec, s, int(k)))) goals.push_back(c);

    // The nearest corner pairs (in both figures together). First the goal
    // corners nearest to the part, then the part's corners nearest to those,
    // so that a part among thousands costs linear work, not a product.
    constexpr std::size_t kNearest = 64;
    auto centre_of = [&](const Side& side, const std::vector<RouteCorner>& corners) {
      Vec2 c{0, 0};
      for (const RouteCorner& corner : corners)
        c[0] += side.nodes[std::size_t(corner.vertex)][0] / double(corners.size()),
        c[1] += side.nodes[std::size_t(corner.vertex)][1] / double(corners.size());
      return c;
    };
    auto nearest = [&](std::vector<RouteCorner>& corners, const std::vector<RouteCorner>& to) {
      if (corners.size() <= kNearest) return;
      const Vec2 centres[2] = {centre_of(sides[0], to), centre_of(sides[1], to)};
      std::vector<std::pair<double, std::size_t>> reach;  // squared distances, summed over both
      reach.reserve(corners.size());
      for (std::size_t i = 0; i < corners.size(); ++i) {
        double sum = 0;
        for (int f = 0; f < 2; ++f) {
          const Vec2& q = sides[f].nodes[std::size_t(corners[i].vertex)];
          sum += (q[0] - centres[f][0]) * (q[0] - centres[f][0]) + (q[1] - centres[f][1]) * (q[1] - centres[f][1]);
        }
        reach.emplace_back(sum, i);
      }
      std::nth_element(reach.begin(), reach.begin() + std::ptrdiff_t(kNearest), reach.end());
      std::vector<RouteCorner> kept;
      for (std::size_t i = 0; i < kNearest; ++i) kept.push_back(corners[reach[i].second]);
      corners = std::move(kept);
    };
    nearest(goals, starts);
    nearest(starts, goals);
    std::vector<std::pair<double, std::pair<std::size_t, std::size_t>>> pairs;
    pairs.reserve(starts.size() * goals.size());
    for (std::size_t a = 0; a < starts.size(); ++a)
      for (std::size_t b = 0; b < goals.size(); ++b) {
        double cost = 0;
        for (const Side& side : sides)
          cost += distance(side.nodes[std::size_t(starts[a].vertex)], side.nodes[std::size_t(goals[b].vertex)]);
        pairs.push_back({cost, {a, b}});
      }
    constexpr std::size_t kStraightTries = 48, kRoutedTries = 6;
    std::partial_sort(pairs.begin(), pairs.begin() + std::ptrdiff_t(std::min(pairs.size(), kStraightTries)),
                      pairs.end());
    bool done = false;
    for (std::size_t t = 0; t < pairs.size() && t < kStraightTries && !done; ++t) {
      const RouteCorner& from = starts[pairs[t].second.first];
      const RouteCorner& to = goals[pairs[t].second.second];
      if (sides[0].straight(from, to) && sides[1].straight(from, to)) {
        for (Side& side : sides) side.add(from.vertex, to.vertex, {});
        done = true;
      }
    }
    if (!done) {
      // Routed in each figure on its own; the fewest bends win.
      std::size_t best_bends = std::numeric_limits<std::size_t>::max();
      std::vector<Vec2> best[2];
      RouteCorner best_from, best_to;
      for (std::size_t t = 0; t < pairs.size() && t < kRoutedTries; ++t) {
        const RouteCorner& from = starts[pairs[t].second.first];
        const RouteCorner& to = goals[pairs[t].second.second];
        std::vector<Vec2> bends[2];
        if (!sides[0].routed(from, to, bends[0]) || !sides[1].routed(from, to, bends[1])) continue;
        const std::size_t most = std::max(bends[0].size(), bends[1].size());
        if (most >= best_bends) continue;
        // As many bends in both: the shorter path padded with straight ones,
        // checked again (a padded midpoint is rounded).
        bool padded_clear = true;
        for (int f = 0; f < 2 && padded_clear; ++f) {
          pad_bends(sides[f].nodes[std::size_t(from.vertex)], sides[f].nodes[std::size_t(to.vertex)], bends[f],
                    int(most));
          padded_clear = sides[f].path_clear(from, to, bends[f]);
        }
        if (padded_clear) {
          best_bends = most;
          best[0] = std::move(bends[0]);
          best[1] = std::move(bends[1]);
          best_from = from;
          best_to = to;
        }
      }
      if (best_bends == std::numeric_limits<std::size_t>::max())
        throw VerificationError("bridging the figure's parts: no path that is valid in exact arithmetic joins " +
                                describe_part(parts, part) + " to the face it lies in in both figures");
      for (int f = 0; f < 2; ++f) sides[f].add(best_from.vertex, best_to.vertex, best[f]);
      result.bends += int(best_bends);
    }
    ++result.bridges;
  }

  // The bridged pair, checked exactly: both valid figures of one part and
  // compatible (the construction promises it; rounding of a bend could
  // break it).
  std::vector<std::array<std::int64_t, 2>> edges;
  for (const Edge& e : sides[0].segments) edges.push_back({e[0], e[1]});
  try {
    result.source = make_stick_figure(sides[0].nodes, edges, source.name);
    result.target = make_stick_figure(sides[1].nodes, edges, target.name);
  } catch (const InvalidFigureError& error) {
    throw VerificationError(std::string("bridging the figure's parts: a bridge is not valid in exact arithmetic: ") +
                            error.what());
  }
  if (figure_parts(result.source).count() != 1)
    throw InternalError("part bridges: the bridged figure still has several parts");
  try {
    result.pair = CompatiblePair::check(result.source, result.target);
  } catch (const IncompatibleFiguresError& error) {
    // The reason without the error's own "incompatible figures: ".
    const std::string what = error.what(), prefix = "incompatible figures: ";
    throw VerificationError("bridging the figure's parts: the bridged figures are not compatible: " +
                            (what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what));
  }
  return result;
}

}  // namespace stickmorph::internal
