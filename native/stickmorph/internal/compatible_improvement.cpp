// Better-shaped compatible triangulations; see compatible_improvement.h.
#include "stickmorph/internal/compatible_improvement.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>
#include <unordered_map>
#include <unordered_set>

#include "stickmorph/cancellation.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/internal/compatible_mesh.h"
#include "stickmorph/internal/geometry.h"
#include "stickmorph/internal/smoothing.h"
#include "stickmorph/internal/triangle_adjacency.h"

namespace stickmorph::internal {
namespace {

// The point at p's barycentric coordinates in triangle t of `from`, in
// triangle t of `to`; false if t is not positive (in doubles) in `from`.
bool map_through(const std::vector<Vec2>& from, const std::vector<Vec2>& to, const Triangle& t, const Vec2& p,
                 Vec2& image) {
  const Vec2 &a = from[t[0]], &b = from[t[1]], &c = from[t[2]];
  const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  if (!(area > 0)) return false;
  const double l0 = ((b[0] - p[0]) * (c[1] - p[1]) - (b[1] - p[1]) * (c[0] - p[0])) / area;
  const double l1 = ((c[0] - p[0]) * (a[1] - p[1]) - (c[1] - p[1]) * (a[0] - p[0])) / area;
  const double l2 = 1 - l0 - l1;
  const Vec2 &ta = to[t[0]], &tb = to[t[1]], &tc = to[t[2]];
  image = {l0 * ta[0] + l1 * tb[0] + l2 * tc[0], l0 * ta[1] + l1 * tb[1] + l2 * tc[1]};
  return true;
}

std::uint64_t edge_id(int a, int b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

// A compatible triangulation being improved: its triangles, which
// triangles hold each edge, and a journal of changes for undoing a
// refinement step that did not pay.
class Mesh {
 public:
  Mesh(std::vector<Vec2>& source, std::vector<Vec2>& target, std::vector<Triangle>& triangles,
       const std::vector<std::pair<int, int>>& fixed_edges)
      : source_(source), target_(target), triangles_(triangles) {
    for (const auto& [a, b] : fixed_edges) fixed_.insert(edge_id(a, b));
    sides_.reserve(triangles.size() * 2);
    for (int t = 0; t < int(triangles.size()); ++t) attach(t);
  }

  const Triangle& triangle(int t) const { return triangles_[std::size_t(t)]; }
  int triangle_count() const { return int(triangles_.size()); }
  int node_count() const { return int(source_.size()); }

  // The smallest angle of triangle t over both embeddings.
  double quality(int t) const {
    const Triangle& tr = triangle(t);
    return both_min_angle(tr[0], tr[1], tr[2]);
  }

  // The triangle across edge a -> b of triangle t (-1 on the boundary).
  int across(int t, int a, int b) const {
    const auto found = sides_.find(edge_id(a, b));
    if (found == sides_.end()) return -1;
    return found->second[0] == t ? found->second[1] : found->second[0];
  }
  bool is_edge(int a, int b) const { return sides_.count(edge_id(a, b)) > 0; }
  bool is_fixed(int a, int b) const { return fixed_.count(edge_id(a, b)) > 0; }

  // Flips edge a-b if its quadrilateral is strictly convex in both
  // embeddings, the other diagonal is not an edge already (the result stays
  // simplicial), and the two triangles' smallest angle over both
  // embeddings clearly grows. The quadrilateral's four sides go to `sides`.
  bool try_flip(int a, int b, std::vector<std::pair<int, int>>& sides) {
    if (is_fixed(a, b)) return false;
    const auto found = sides_.find(edge_id(a, b));
    if (found == sides_.end() || found->second[0] < 0 || found->second[1] < 0) return false;
    int t1 = found->second[0], t2 = found->second[1];
    // t1 = (a, b, c) with a -> b counter-clockwise, t2 = (b, a, d).
    if (!has_directed(t1, a, b)) std::swap(t1, t2);
    const int c = opposite(t1, a, b), d = opposite(t2, a, b);
    if (c < 0 || d < 0 || c == d || is_edge(c, d)) return false;
    // The quadrilateral a, d, b, c counter-clockwise: the new triangles
    // positive in both embeddings is its strict convexity at a and b (at c
    // and d it is the old triangles').
    if (!positive_in_both(a, d, c) || !positive_in_both(d, b, c)) return false;
    const double before = std::min(quality(t1), quality(t2));
    const double after = std::min(both_min_angle(a, d, c), both_min_angle(d, b, c));
    // A clear gain only: rounding in the angles must not let two flips undo
    // each other.
    if (!(after > before * (1 + 1e-9) + 1e-15)) return false;
    replace(t1, {a, d, c});
    replace(t2, {d, b, c});
    sides.emplace_back(a, d);
    sides.emplace_back(d, b);
    sides.emplace_back(b, c);
    sides.emplace_back(c, a);
    return true;
  }

  // Lawson's flips from the edges given, to no further gain.
  int flip_from(std::vector<std::pair<int, int>> pending) {
    int flips = 0;
    long steps = 0;
    std::vector<std::pair<int, int>> sides;
    while (!pending.empty()) {
      if (++steps % 4096 == 0) poll_cancellation();
      const auto [a, b] = pending.back();
      pending.pop_back();
      sides.clear();
      if (!try_flip(a, b, sides)) continue;
      ++flips;
      pending.insert(pending.end(), sides.begin(), sides.end());
    }
    return flips;
  }

  // Splits triangle t by a new node at source position p (strictly inside
  // t there), placed in the target at the same barycentric coordinates, if
  // the three new triangles are positive in both embeddings (exact). The
  // new node's index, or -1.
  int insert(int t, const Vec2& p_source) {
    const Triangle tr = triangle(t);
    Vec2 p_target;
    if (!map_through(source_, target_, tr, p_source, p_target)) return -1;
    const int v = node_count();
    source_.push_back(p_source);
    target_.push_back(p_target);
    journal_nodes_ += 1;
    if (!positive_in_both(tr[0], tr[1], v) || !positive_in_both(tr[1], tr[2], v) ||
        !positive_in_both(tr[2], tr[0], v)) {
      source_.pop_back();
      target_.pop_back();
      journal_nodes_ -= 1;
      return -1;
    }
    replace(t, {tr[0], tr[1], v});
    append({tr[1], tr[2], v});
    append({tr[2], tr[0], v});
    return v;
  }

  // Moves node v of one embedding (the target's if `in_target`) to the
  // best of a few candidates for the smallest angle of its star there: the
  // mean of its neighbours, and halfway there, a few times over; a
  // candidate counts only with every triangle of the star positive
  // (exact), so v stays in the kernel of its link. The star's triangles
  // are found through the triangles changed since begin(), which hold
  // every triangle of a node added since.
  void relocate(int v, bool in_target) {
    std::vector<Vec2>& pos = in_target ? target_ : source_;
    std::vector<int> star;
    for (int t : changed())
      for (int u : triangle(t))
        if (u == v) star.push_back(t);
    if (star.empty()) return;
    auto star_quality = [&] {
      double least = kPi;
      for (int t : star) {
        const Triangle& tr = triangle(t);
        if (orientation(pos[tr[0]], pos[tr[1]], pos[tr[2]]) <= 0) return -1.0;
        least = std::min(least, triangle_min_angle(pos[tr[0]], pos[tr[1]], pos[tr[2]]));
      }
      return least;
    };
    for (int round = 0; round < 3; ++round) {
      Vec2 mean{0, 0};
      int count = 0;
      for (int t : star)
        for (int u : triangle(t))
          if (u != v) mean[0] += pos[u][0], mean[1] += pos[u][1], ++count;
      mean[0] /= count;
      mean[1] /= count;
      const Vec2 old = pos[v];
      double best = star_quality();
      Vec2 best_point = old;
      for (double step : {1.0, 0.5}) {
        pos[v] = {old[0] + step * (mean[0] - old[0]), old[1] + step * (mean[1] - old[1])};
        const double q = star_quality();
        if (q > best) best = q, best_point = pos[v];
      }
      pos[v] = best_point;
    }
  }

  // The journal: begin() marks a state that undo() returns to.
  void begin() {
    journal_.clear();
    journal_nodes_ = 0;
    journal_triangles_ = triangle_count();
  }
  // The triangles changed or added since begin().
  std::vector<int> changed() const {
    std::vector<int> result;
    for (const auto& [t, old] : journal_) result.push_back(t);
    for (int t = journal_triangles_; t < triangle_count(); ++t) result.push_back(t);
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
  }
  // The smallest quality of the triangles changed since begin(), as they
  // were then.
  double quality_before() const {
    double least = kPi;
    std::unordered_set<int> seen;
    for (const auto& [t, old] : journal_)
      if (seen.insert(t).second) least = std::min(least, both_min_angle(old[0], old[1], old[2]));
    return least;
  }
  void undo() {
    for (int t = triangle_count() - 1; t >= journal_triangles_; --t) {
      detach(t);
      triangles_.pop_back();
    }
    for (auto it = journal_.rbegin(); it != journal_.rend(); ++it) {
      detach(it->first);
      triangles_[std::size_t(it->first)] = it->second;
      attach(it->first);
    }
    source_.resize(source_.size() - std::size_t(journal_nodes_));
    target_.resize(target_.size() - std::size_t(journal_nodes_));
    begin();
  }

  const std::vector<Vec2>& source() const { return source_; }
  const std::vector<Vec2>& target() const { return target_; }

 private:
  std::vector<Vec2>& source_;
  std::vector<Vec2>& target_;
  std::vector<Triangle>& triangles_;
  std::unordered_set<std::uint64_t> fixed_;
  std::unordered_map<std::uint64_t, std::array<int, 2>> sides_;  // the two triangles of each edge (-1: none)
  std::vector<std::pair<int, Triangle>> journal_;  // triangles replaced since begin(), their first old value first
  int journal_triangles_ = 0;
  int journal_nodes_ = 0;

  double both_min_angle(int a, int b, int c) const {
    return std::min(triangle_min_angle(source_[a], source_[b], source_[c]),
                    triangle_min_angle(target_[a], target_[b], target_[c]));
  }
  bool positive_in_both(int a, int b, int c) const {
    return orientation(source_[a], source_[b], source_[c]) > 0 && orientation(target_[a], target_[b], target_[c]) > 0;
  }
  bool has_directed(int t, int a, int b) const {
    const Triangle& tr = triangle(t);
    for (int j = 0; j < 3; ++j)
      if (tr[j] == a && tr[(j + 1) % 3] == b) return true;
    return false;
  }
  int opposite(int t, int a, int b) const {
    for (int v : triangle(t))
      if (v != a && v != b) return v;
    return -1;
  }
  void attach(int t) {
    const Triangle& tr = triangle(t);
    for (int j = 0; j < 3; ++j) {
      auto [it, added] = sides_.try_emplace(edge_id(tr[j], tr[(j + 1) % 3]), std::array<int, 2>{-1, -1});
      (it->second[0] < 0 ? it->second[0] : it->second[1]) = t;
    }
  }
  void detach(int t) {
    const Triangle& tr = triangle(t);
    for (int j = 0; j < 3; ++j) {
      const auto it = sides_.find(edge_id(tr[j], tr[(j + 1) % 3]));
      if (it == sides_.end()) continue;
      if (it->second[0] == t) it->second[0] = -1;
      if (it->second[1] == t) it->second[1] = -1;
      if (it->second[0] < 0 && it->second[1] < 0) sides_.erase(it);
    }
  }
  void replace(int t, const Triangle& value) {
    if (t < journal_triangles_) journal_.emplace_back(t, triangle(t));
    detach(t);
    triangles_[std::size_t(t)] = value;
    attach(t);
  }
  void append(const Triangle& value) {
    triangles_.push_back(value);
    attach(triangle_count() - 1);
  }
};

// Where to put a new node against triangle t's worst angle, in the source
// embedding (t's worst there) or the target: Ungor's off-centre, on the
// bisector of t's shortest edge at the distance that gives the new
// triangle over that edge the angle `goal` at the new node, or the
// circumcentre where that is nearer (Ungor 2009, "Off-centers: a new type
// of Steiner points for computing size-optimal quality-guaranteed Delaunay
// triangulations"). In t's own embedding; false if t is degenerate there.
bool off_centre(const std::vector<Vec2>& pos, const Triangle& t, double goal, Vec2& point) {
  int shortest = 0;
  double length2[3];
  for (int j = 0; j < 3; ++j) {
    const Vec2& p = pos[t[j]];
    const Vec2& q = pos[t[(j + 1) % 3]];
    length2[j] = (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]);
    if (length2[j] < length2[shortest]) shortest = j;
  }
  const Vec2& p = pos[t[shortest]];
  const Vec2& q = pos[t[(shortest + 1) % 3]];
  const Vec2& r = pos[t[(shortest + 2) % 3]];
  const double h = std::sqrt(length2[shortest]);
  if (!(h > 0)) return false;
  // The unit normal of p -> q towards r (the triangle is counter-clockwise,
  // so r is on the left).
  const double nx = -(q[1] - p[1]) / h, ny = (q[0] - p[0]) / h;
  const Vec2 mid{0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])};
  // The circumcentre's distance from the midpoint along the normal.
  const double ax = q[0] - p[0], ay = q[1] - p[1], bx = r[0] - p[0], by = r[1] - p[1];
  const double d = 2 * (ax * by - ay * bx);
  if (!(d > 0)) return false;
  const double ux = (by * (ax * ax + ay * ay) - ay * (bx * bx + by * by)) / d;
  const double uy = (ax * (bx * bx + by * by) - bx * (ax * ax + ay * ay)) / d;
  const double circum = (p[0] + ux - mid[0]) * nx + (p[1] + uy - mid[1]) * ny;
  const double off = 0.5 * h / std::tan(0.5 * goal);
  const double distance = std::min(circum, off);
  if (!(distance > 0) || !std::isfinite(distance)) return false;
  point = {mid[0] + distance * nx, mid[1] + distance * ny};
  // Outside t (an oblique sliver, whose apex lies far to one side of the
  // short edge's bisector, as a far enclosure vertex does): the point at
  // that height on the median to the apex instead, inside t, or halfway
  // up it.
  const double height = (r[0] - mid[0]) * nx + (r[1] - mid[1]) * ny;
  const bool inside = orientation(p, q, point) > 0 && orientation(q, r, point) > 0 && orientation(r, p, point) > 0;
  if (!inside && height > 0) {
    const double s = std::min(0.5, distance / height);
    point = {mid[0] + s * (r[0] - mid[0]), mid[1] + s * (r[1] - mid[1])};
  }
  return true;
}

// The triangle of `mesh` that holds `point` strictly inside in the
// embedding `pos`, walking from triangle `start` across edges that are not
// fixed (a walk stopped by the figure or the boundary finds none): -1.
int locate(const Mesh& mesh, const std::vector<Vec2>& pos, int start, const Vec2& point) {
  int t = start;
  for (int step = 0; step < 64; ++step) {
    const Triangle& tr = mesh.triangle(t);
    int exit = -1;
    for (int j = 0; j < 3; ++j) {
      const int side = orientation(pos[tr[j]], pos[tr[(j + 1) % 3]], point);
      if (side == 0) return -1;  // on an edge: not a split of one triangle
      if (side < 0) {
        exit = j;
        break;
      }
    }
    if (exit < 0) return t;
    const int a = tr[exit], b = tr[(exit + 1) % 3];
    if (mesh.is_fixed(a, b)) return -1;
    t = mesh.across(t, a, b);
    if (t < 0) return -1;
  }
  return -1;
}

// Compatible refinement: the worst triangle first, a node at its off-centre
// (in the embedding where it is worst), mapped to the other embedding
// through the triangle that holds it, then Lawson's flips from there; kept
// only when the triangles it changed are all better than the worst of them
// was (else undone, and that triangle is not tried again).
int refine(Mesh& mesh, double goal, int budget) {
  using Entry = std::pair<double, int>;  // quality, triangle
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const double q = mesh.quality(t);
    if (q < goal) queue.emplace(q, t);
  }
  std::unordered_set<std::uint64_t> hopeless;  // triangles tried in vain, by their nodes
  auto key = [](const Triangle& t) {
    Triangle s = t;
    std::sort(s.begin(), s.end());
    return (std::uint64_t(std::uint32_t(s[0])) * 0x9E3779B1u) ^ (std::uint64_t(std::uint32_t(s[1])) << 21) ^
           (std::uint64_t(std::uint32_t(s[2])) << 42);
  };
  int added = 0;
  long steps = 0;
  while (!queue.empty() && added < budget) {
    if (++steps % 256 == 0) poll_cancellation();
    const auto [q, t] = queue.top();
    queue.pop();
    if (mesh.quality(t) != q || hopeless.count(key(mesh.triangle(t)))) continue;  // changed since queued
    const Triangle tr = mesh.triangle(t);
    const bool in_target = triangle_min_angle(mesh.target()[tr[0]], mesh.target()[tr[1]], mesh.target()[tr[2]]) <
                           triangle_min_angle(mesh.source()[tr[0]], mesh.source()[tr[1]], mesh.source()[tr[2]]);
    Vec2 point;
    mesh.begin();
    bool kept = false;
    if (off_centre(in_target ? mesh.target() : mesh.source(), tr, goal, point)) {
      // insert() takes a source position: a target point is located in
      // the target and mapped back through the same barycentric split.
      const int holder = locate(mesh, in_target ? mesh.target() : mesh.source(), t, point);
      if (holder >= 0) {
        Vec2 source_point = point;
        const Triangle h = mesh.triangle(holder);
        const bool mapped = !in_target || map_through(mesh.target(), mesh.source(), h, point, source_point);
        const int v = mapped ? mesh.insert(holder, source_point) : -1;
        if (v >= 0) {
          // The new node's place in the other embedding is free within its
          // star's kernel: the barycentric image of the off-centre there
          // can be a poor one where the two shapes differ.
          mesh.relocate(v, !in_target);
          mesh.flip_from({{h[0], h[1]}, {h[1], h[2]}, {h[2], h[0]}});
          mesh.relocate(v, !in_target);
          const std::vector<int> changed = mesh.changed();
          double after = kPi;
          for (int c : changed) after = std::min(after, mesh.quality(c));
          // t itself must have been split or flipped away.
          const bool t_gone = std::find(changed.begin(), changed.end(), t) != changed.end();
          kept = t_gone && after > mesh.quality_before() * (1 + 1e-9);
          if (kept) {
            ++added;
            for (int c : changed) {
              const double cq = mesh.quality(c);
              if (cq < goal) queue.emplace(cq, c);
            }
          }
        }
      }
    }
    if (!kept) {
      mesh.undo();
      hopeless.insert(key(mesh.triangle(t)));
    }
  }
  return added;
}

// Steiner positions for the smallest angle (issue 30): every movable node
// whose star has an angle below `goal` in one embedding, by a pattern
// search there (eight directions, the step halved when none gains, from a
// quarter of the mean distance to the neighbours), a move kept only when
// every triangle of the star stays positive (exact: the node stays in its
// link's kernel) and the star's smallest angle grows. Laplacian smoothing
// (smoothing.h) aims at even spacing; this aims at the angle itself, which
// is what a distorted embedding (one letter drawn into another) needs.
void optimise_positions(std::vector<Vec2>& pos, const std::vector<Triangle>& triangles, int first_movable,
                        double goal) {
  const std::vector<std::vector<int>> around =
      TriangleAdjacency::stars_of(int(pos.size()), triangles, std::vector<char>());
  auto star_quality = [&](int v) {
    double least = kPi;
    for (int t : around[std::size_t(v)]) {
      const Triangle& tr = triangles[std::size_t(t)];
      if (orientation(pos[tr[0]], pos[tr[1]], pos[tr[2]]) <= 0) return -1.0;
      least = std::min(least, triangle_min_angle(pos[tr[0]], pos[tr[1]], pos[tr[2]]));
    }
    return least;
  };
  static const double kDirections[8][2] = {{1, 0}, {0.7071067811865476, 0.7071067811865476}, {0, 1},
                                           {-0.7071067811865476, 0.7071067811865476}, {-1, 0},
                                           {-0.7071067811865476, -0.7071067811865476}, {0, -1},
                                           {0.7071067811865476, -0.7071067811865476}};
  for (int v = first_movable; v < int(pos.size()); ++v) {
    if (around[std::size_t(v)].empty()) continue;
    double best = star_quality(v);
    if (!(best >= 0) || best >= goal) continue;
    double spread = 0;
    int count = 0;
    for (int t : around[std::size_t(v)])
      for (int u : triangles[std::size_t(t)])
        if (u != v) spread += std::hypot(pos[u][0] - pos[v][0], pos[u][1] - pos[v][1]), ++count;
    double step = 0.25 * spread / count;
    for (int evaluations = 0; evaluations < 96 && step > 1e-6 * spread / count;) {
      const Vec2 old = pos[v];
      Vec2 best_point = old;
      for (const auto& d : kDirections) {
        pos[v] = {old[0] + step * d[0], old[1] + step * d[1]};
        ++evaluations;
        const double q = star_quality(v);
        if (q > best * (1 + 1e-12)) best = q, best_point = pos[v];
      }
      pos[v] = best_point;
      if (best_point == old) step *= 0.5;
    }
  }
}

}  // namespace

void improve_compatible_triangulation(std::vector<Vec2>& source, std::vector<Vec2>& target,
                                      std::vector<std::array<int, 3>>& triangles,
                                      const std::vector<std::pair<int, int>>& fixed_edges, int first_steiner,
                                      const CompatibleImprovementOptions& options,
                                      CompatibleImprovementStats* stats) {
  CompatibleImprovementStats local;
  auto all_edges = [&] {
    std::vector<std::pair<int, int>> edges;
    for (const Triangle& t : triangles)
      for (int j = 0; j < 3; ++j) edges.emplace_back(t[j], t[(j + 1) % 3]);
    return edges;
  };
  for (int round = 0; round < options.rounds; ++round) {
    int flips = 0;
    {
      Mesh mesh(source, target, triangles, fixed_edges);
      flips = mesh.flip_from(all_edges());
      if (round == 0 && options.steiner_budget > 0)
        local.added = refine(mesh, options.goal_angle, options.steiner_budget);
      // After the first smoothing: the triangles still far below the goal
      // (a letter drawn into another, whose compatible triangulation must
      // bend far in one of them) may take more.
      if (round == 1 && options.rescue_budget > 0)
        local.added += refine(mesh, options.rescue_angle, options.rescue_budget);
    }
    local.flips += flips;
    // Smoothing (smoothing.h) on the glued triangulation: the moves of
    // Steiner vertices next to a face's boundary that the faces' own
    // smoothing could not see, and those the flips made worth it.
    CompatibleMesh mesh;
    mesh.corners = first_steiner;
    mesh.source = std::move(source);
    mesh.target = std::move(target);
    mesh.triangles = std::move(triangles);
    smooth(mesh, false, 2);
    smooth(mesh, true, 2);
    source = std::move(mesh.source);
    target = std::move(mesh.target);
    triangles = std::move(mesh.triangles);
    optimise_positions(source, triangles, first_steiner, options.goal_angle);
    optimise_positions(target, triangles, first_steiner, options.goal_angle);
    if (flips == 0 && round > 0) break;
  }
  if (stats) *stats = local;
}

}  // namespace stickmorph::internal
