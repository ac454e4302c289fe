#include "stickmorph/decomposition.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "stickmorph/exact_predicates.h"
#include "stickmorph/figure_parts.h"
#include "stickmorph/internal/geometry.h"
#include "stickmorph/internal/stage_counters.h"

namespace stickmorph {
namespace {

using internal::kPi;

// Angle of the polygon at corner v between the incoming edge from u and the
// outgoing edge to w: the clockwise sweep from direction (u - v) to direction
// (w - v), in (0, 2*pi]. Algorithm 1 turns clockwise at each vertex, so this
// is the angle on the side of the region being walked.
double corner_angle(const Vec2& u, const Vec2& v, const Vec2& w, bool same_edge) {
  if (same_edge) return 2 * kPi;  // tip of a dangling edge: a full turn
  // Exact half-turn class: cross(u - v, w - v) < 0 means w is less than a
  // half-turn clockwise from u.
  const int turn = orientation(v, u, w);
  if (turn == 0) return kPi;  // collinear and distinct: opposite directions
  // The unsigned angle between the two directions, in [0, pi]. Differences
  // of doubles are exact or correctly rounded (Sterbenz), so cross and dot
  // are accurate to a few ulps of |a||b| and the angle to a few ulps of pi;
  // the exact class then places it below or above pi. Computing the sweep
  // from two atan2 values instead can wrap a near-0 angle to 2*pi.
  double ax = u[0] - v[0], ay = u[1] - v[1];
  double bx = w[0] - v[0], by = w[1] - v[1];
  // The angle does not change when either direction is scaled, but its
  // cross and dot products underflow below |a||b| ~ 1e-300 and overflow
  // above 1e300 (a figure of size 1e-200 read as angle sum 0). Directions
  // far from unit length are scaled by a power of two, exactly, first;
  // others are left alone, so that ordinary figures decompose bit for bit
  // as before.
  const auto unit_scale = [](double& x, double& y) {
    const double largest = std::max(std::abs(x), std::abs(y));
    if (largest == 0) return;
    const int exponent = std::ilogb(largest);
    if (exponent > -400 && exponent < 400) return;
    x = std::ldexp(x, -exponent);
    y = std::ldexp(y, -exponent);
  };
  unit_scale(ax, ay);
  unit_scale(bx, by);
  const double between = internal::angle_between(ax, ay, bx, by);
  return turn < 0 ? between : 2 * kPi - between;
}

}  // namespace

int dart_tail(const StickFigure& figure, int dart) {
  return figure.edges[dart_edge(dart)][dart & 1];
}

int dart_head(const StickFigure& figure, int dart) {
  return figure.edges[dart_edge(dart)][1 - (dart & 1)];
}

int RotationSystem::next_in_face(int dart) const {
  const int twin = dart_twin(dart);
  const std::vector<int>& around = outgoing_ccw[tail[twin]];
  const int degree = int(around.size());
  // The counter-clockwise list read backwards is the clockwise order.
  return around[(position[twin] + degree - 1) % degree];
}

RotationSystem rotation_system(const StickFigure& figure) {
  const int darts = 2 * int(figure.edges.size());
  RotationSystem rs;
  rs.outgoing_ccw.assign(figure.vertices.size(), {});
  rs.position.assign(darts, -1);
  rs.tail.assign(darts, -1);
  for (int d = 0; d < darts; ++d) {
    rs.tail[d] = dart_tail(figure, d);
    rs.outgoing_ccw[rs.tail[d]].push_back(d);
  }
  for (std::size_t v = 0; v < figure.vertices.size(); ++v) {
    std::vector<int>& around = rs.outgoing_ccw[v];
    const Vec2& origin = figure.vertices[v];
    // Exact angular order; no two edges at v share a direction in a valid
    // figure (that would be an overlap).
    std::sort(around.begin(), around.end(), [&](int a, int b) {
      return compare_direction_ccw(origin, figure.vertices[dart_head(figure, a)],
                                   figure.vertices[dart_head(figure, b)]) < 0;
    });
    for (std::size_t k = 0; k < around.size(); ++k) rs.position[around[k]] = int(k);
  }
  return rs;
}

Decomposition decompose(const StickFigure& figure) {
  internal::stage_counters().decompositions.fetch_add(1, std::memory_order_relaxed);
  Decomposition dec;
  dec.rotation = rotation_system(figure);
  const int darts = 2 * int(figure.edges.size());
  dec.sequence_of_dart.assign(darts, -1);

  // Algorithm 1, lines 4-14: walk each unmarked dart around its region.
  for (int start = 0; start < darts; ++start) {
    if (dec.sequence_of_dart[start] >= 0) continue;
    const int index = int(dec.sequences.size());
    CyclicSequence seq;
    int dart = start;
    do {
      dec.sequence_of_dart[dart] = index;
      seq.darts.push_back(dart);
      seq.vertices.push_back(dart_head(figure, dart));
      dart = dec.rotation.next_in_face(dart);
    } while (dart != start);

    // The paper's rule: interior iff the angle sum is pi*(n-2); the exterior
    // sums to pi*(n+2).
    const std::size_t n = seq.darts.size();
    for (std::size_t k = 0; k < n; ++k) {
      const int in = seq.darts[k];
      const int out = seq.darts[(k + 1) % n];
      const Vec2& u = figure.vertices[dart_tail(figure, in)];
      const Vec2& v = figure.vertices[dart_head(figure, in)];
      const Vec2& w = figure.vertices[dart_head(figure, out)];
      seq.angle_sum += corner_angle(u, v, w, dart_edge(in) == dart_edge(out));
    }
    const double excess = (seq.angle_sum - kPi * double(n)) / (2 * kPi);
    const long turns = std::lround(excess);
    if (turns != 1 && turns != -1)
      throw InternalError("decomposition: cyclic sequence " + std::to_string(index) + " of " +
                          std::to_string(n) + " corners has angle sum " +
                          format_double(seq.angle_sum) + ", neither pi*(n-2) nor pi*(n+2)");
    seq.exterior = turns == 1;
    dec.sequences.push_back(std::move(seq));
  }

  // A lone vertex (a part of its own, issue 14): the whole plane minus a
  // point is its exterior, a sequence with no darts.
  for (std::size_t v = 0; v < figure.vertices.size(); ++v)
    if (dec.rotation.outgoing_ccw[v].empty()) {
      CyclicSequence lone;
      lone.vertices = {int(v)};
      lone.exterior = true;
      dec.sequences.push_back(lone);
    }

  // One exterior sequence per part, in the order of the parts.
  const FigureParts parts = figure_parts(figure);
  dec.exterior_of_part.assign(std::size_t(parts.count()), -1);
  for (std::size_t i = 0; i < dec.sequences.size(); ++i)
    if (dec.sequences[i].exterior) {
      const int part = parts.part_of_vertex[std::size_t(dec.sequences[i].vertices.front())];
      int& slot = dec.exterior_of_part[std::size_t(part)];
      if (slot >= 0)
        throw InternalError("decomposition: cyclic sequences " + std::to_string(slot) + " and " +
                            std::to_string(i) + " are both exterior to part " + std::to_string(part));
      slot = int(i);
    }
  for (std::size_t part = 0; part < dec.exterior_of_part.size(); ++part)
    if (dec.exterior_of_part[part] < 0)
      throw InternalError("decomposition: part " + std::to_string(part) + " has no exterior cyclic sequence");
  dec.exterior = dec.exterior_of_part.front();
  return dec;
}

bool is_valid(const Decomposition& dec, const StickFigure& figure) {
  const int darts = 2 * int(figure.edges.size());
  if (dec.rotation.outgoing_ccw.size() != figure.vertices.size()) return false;
  if (int(dec.sequence_of_dart.size()) != darts) return false;
  if (dec.exterior < 0 || dec.exterior >= int(dec.sequences.size())) return false;

  std::vector<int> seen(darts, 0);
  int exterior_count = 0;
  for (std::size_t i = 0; i < dec.sequences.size(); ++i) {
    const CyclicSequence& seq = dec.sequences[i];
    exterior_count += seq.exterior;
    // A lone vertex's sequence: one vertex, no darts, exterior.
    if (seq.darts.empty() && (seq.vertices.size() != 1 || !seq.exterior)) return false;
    if (!seq.darts.empty() && seq.darts.size() != seq.vertices.size()) return false;
    for (std::size_t k = 0; k < seq.darts.size(); ++k) {
      const int d = seq.darts[k];
      if (d < 0 || d >= darts || ++seen[d] != 1) return false;
      if (dec.sequence_of_dart[d] != int(i)) return false;
      if (seq.vertices[k] != dart_head(figure, d)) return false;
      if (dec.rotation.next_in_face(d) != seq.darts[(k + 1) % seq.darts.size()]) return false;
    }
  }
  const FigureParts parts = figure_parts(figure);
  if (exterior_count != parts.count() || int(dec.exterior_of_part.size()) != parts.count()) return false;
  for (int part = 0; part < parts.count(); ++part) {
    const int e = dec.exterior_of_part[std::size_t(part)];
    if (e < 0 || e >= int(dec.sequences.size()) || !dec.sequences[std::size_t(e)].exterior) return false;
    if (parts.part_of_vertex[std::size_t(dec.sequences[std::size_t(e)].vertices.front())] != part) return false;
  }
  if (dec.exterior != dec.exterior_of_part.front()) return false;
  if (std::count(seen.begin(), seen.end(), 1) != darts) return false;
  // Euler's formula for a plane graph of P parts, each counting its own
  // exterior: V - E + F = 2P.
  const long euler = long(figure.vertices.size()) - long(figure.edges.size()) +
                     long(dec.sequences.size());
  return euler == 2L * parts.count();
}

}  // namespace stickmorph
