// Cutting a deep polygon pair along a routed path; see routed_cut.h.
#include "stickmorph/internal/routed_cut.h"

#include <algorithm>
#include <limits>
#include <queue>
#include <set>
#include <utility>

#include "stickmorph/exact_predicates.h"
#include "stickmorph/internal/corner_router.h"
#include "stickmorph/polygon_triangulation.h"

namespace stickmorph::internal {
namespace {

// Corners tried as one end of the cut: each costs a breadth-first search of
// both dual graphs, which finds the best other end.
constexpr int kSampledCorners = 32;
// Cuts of each balance class handed on to be measured exactly.
constexpr int kCandidatesPerClass = 2;
// Longest run of sides a straight segment of a cut may skip (DualGraph::bends).
constexpr int kMaxSkip = 256;
// A straight segment of a cut crosses each side it skips no nearer than this
// fraction of the side's length to either end (DualGraph::bends).
constexpr double kMiddle = 0.25;

// One polygon's triangulation as a dual graph with the faces at each corner.
struct DualGraph {
  PolygonTriangulation pt;
  std::vector<std::vector<int>> fan;  // corner -> faces having it
  std::vector<int> came;              // scratch for the search

  DualGraph(const CornerPolygon& polygon, const std::vector<std::array<int, 3>>& base)
      : pt(dual_tree_depths(polygon, base)) {
    fan.resize(polygon.size());
    for (int t = 0; t < int(pt.triangles.size()); ++t)
      for (int c : pt.triangles[t]) fan[c].push_back(t);
    came.assign(pt.triangles.size(), -2);
  }

  // Faces of a shortest dual path from a face at corner a to a face at
  // corner b: only the first is at a, only the last at b.
  std::vector<int> path(int a, int b) {
    std::fill(came.begin(), came.end(), -2);
    std::queue<int> queue;
    for (int f : fan[a]) came[f] = -1, queue.push(f);
    auto has_b = [&](int f) {
      const auto& t = pt.triangles[f];
      return t[0] == b || t[1] == b || t[2] == b;
    };
    int goal = -1;
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop();
      if (has_b(f)) {
        goal = f;
        break;
      }
      for (int g : pt.neighbour[f])
        if (g >= 0 && came[g] == -2) came[g] = f, queue.push(g);
    }
    std::vector<int> faces;
    for (int f = goal; f >= 0; f = came[f]) faces.push_back(f);
    std::reverse(faces.begin(), faces.end());
    return faces;
  }

  // Dual distance from a face at corner a to a face at each corner: the
  // number of bends of a path between them (-1: unreachable).
  std::vector<int> corner_distances(int a) {
    std::vector<int> d(pt.triangles.size(), -1);
    std::queue<int> queue;
    for (int f : fan[a]) d[f] = 0, queue.push(f);
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop();
      for (int g : pt.neighbour[f])
        if (g >= 0 && d[g] < 0) d[g] = d[f] + 1, queue.push(g);
    }
    std::vector<int> out(fan.size(), -1);
    for (std::size_t c = 0; c < fan.size(); ++c)
      for (int f : fan[c])
        if (out[c] < 0 || d[f] < out[c]) out[c] = d[f];
    return out;
  }

  // Bends of a path from corner `a` (of faces.front()) to corner `b` (of
  // faces.back()) through the sleeve of `faces`: midpoints of the sides
  // shared by consecutive faces, but only those where the path must turn.
  // A bend is skipped when the straight segment from the last kept point to
  // a later one crosses every side in between strictly inside it (exact
  // orientations): that segment then runs through the faces in between, so
  // it stays inside the polygon and meets no corner, as the unsimplified
  // path does. In a fan (one far corner facing many), the dual path from a
  // middle corner out crosses half the fan, but a straight segment does it:
  // the cut's bends, which both pieces get as corners and the spiderweb as
  // Steiner vertices, then no longer grow with the fan.
  std::vector<Vec2> bends(const CornerPolygon& polygon, const std::vector<int>& faces, int a, int b) const {
    const int sides = int(faces.size()) - 1;
    std::vector<Vec2> ends[2], mid;
    for (int i = 0; i < sides; ++i) {
      const int f = faces[std::size_t(i)], g = faces[std::size_t(i) + 1];
      int j = 0;
      while (pt.neighbour[f][j] != g) ++j;
      const Vec2 p = polygon.at(pt.triangles[f][(j + 1) % 3]), q = polygon.at(pt.triangles[f][(j + 2) % 3]);
      ends[0].push_back(p);
      ends[1].push_back(q);
      mid.push_back({0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])});
    }
    // Point t of the path: corner a (t = 0), the midpoint of side t - 1, or
    // corner b (t = sides + 1).
    auto point = [&](int t) { return t == 0 ? polygon.at(a) : t > sides ? polygon.at(b) : mid[std::size_t(t) - 1]; };
    // The crossing must also lie in the middle part of the side (kMiddle,
    // in floating point; it only tightens the exact test): a segment that
    // grazes a corner leaves triangles too thin for the morph's frames.
    auto crosses = [&](const Vec2& from, const Vec2& to, int side) {
      const Vec2& p = ends[0][std::size_t(side)];
      const Vec2& q = ends[1][std::size_t(side)];
      if (!(orientation(from, to, p) * orientation(from, to, q) < 0 &&
            orientation(p, q, from) * orientation(p, q, to) < 0))
        return false;
      const double dx = to[0] - from[0], dy = to[1] - from[1];
      const double along = (p[0] - from[0]) * dy - (p[1] - from[1]) * dx;  // distance of p from the line, scaled
      const double whole = (p[0] - q[0]) * dy - (p[1] - q[1]) * dx;        // of p - q, same scale
      const double s = along / whole;                                       // crossing point: p + s (q - p)
      return s >= kMiddle && s <= 1 - kMiddle;
    };
    std::vector<Vec2> out;
    for (int from = 0; from <= sides;) {
      // The farthest point reachable straight, trying points in order and
      // stopping at the first that is not (kMaxSkip bounds the quadratic
      // cost of the test on a long straight sleeve).
      int reach = from + 1;
      for (int to = from + 2; to <= sides + 1 && to - from <= kMaxSkip; ++to) {
        bool straight = true;
        for (int side = from; side < to - 1 && straight; ++side) straight = crosses(point(from), point(to), side);
        if (!straight) break;
        reach = to;
      }
      if (reach <= sides) out.push_back(mid[std::size_t(reach) - 1]);
      from = reach;
    }
    return out;
  }
};

}  // namespace

long spiderweb_depth_total(const PolygonPair& pair, const std::vector<std::array<int, 3>>& source_base,
                           const std::vector<std::array<int, 3>>& target_base) {
  const int n = int(pair.corners.size());
  const CornerPolygon polygons[2] = {pair.source(), pair.target()};
  PolygonTriangulation pts[2][2];
  for (int c = 0; c < 2; ++c) {
    pts[0][c] = dual_tree_depths(polygons[0], source_base, c);
    pts[1][c] = dual_tree_depths(polygons[1], target_base, c);
  }
  long best = std::numeric_limits<long>::max();
  for (int cs = 0; cs < 2; ++cs)
    for (int ct = 0; ct < 2; ++ct) {
      if ((cs && pts[0][cs].center_faces.size() < 2) || (ct && pts[1][ct].center_faces.size() < 2)) continue;
      long total = 0;
      for (int k = 0; k < n; ++k) total += std::max(pts[0][cs].milestone[k], pts[1][ct].milestone[k]);
      best = std::min(best, total);
    }
  return best;
}

std::vector<RoutedCut> routed_cut_candidates(const PolygonPair& pair,
                                             const std::vector<std::array<int, 3>>& source_base,
                                             const std::vector<std::array<int, 3>>& target_base) {
  const int n = int(pair.corners.size());
  std::vector<RoutedCut> out;
  if (n < 8) return out;
  const CornerPolygon polygons[2] = {pair.source(), pair.target()};
  DualGraph graphs[2] = {{polygons[0], source_base}, {polygons[1], target_base}};
  auto piece_sizes = [&](int a, int b) { return std::make_pair(b - a + 1, n - (b - a) + 1); };

  // For a sample of corners a, the distance in each dual graph from a's
  // faces to every corner b; for each balance class (the smaller piece
  // holding at least 2/5, 1/4 or 1/8 of the corners) the b with the
  // smallest larger piece, bends included.
  // Two more classes: straight in the source, straight in the target (a
  // diagonal of that polygon, which cuts a corridor there across).
  constexpr int kClasses = 5;
  const int least[kClasses] = {2 * n / 5, n / 4, n / 8, n / 4, n / 4};
  const int straight[kClasses] = {-1, -1, -1, 0, 1};
  struct Scored {
    long score;
    int a, b;
  };
  std::vector<Scored> best[kClasses];
  std::vector<int> distance[2];
  const int samples = std::min(n, kSampledCorners);
  for (int i = 0; i < samples; ++i) {
    const int a = int((long(i) * n) / samples);
    for (int s = 0; s < 2; ++s) distance[s] = graphs[s].corner_distances(a);
    Scored found[kClasses];
    for (auto& f : found) f = {std::numeric_limits<long>::max(), -1, -1};
    for (int b = 0; b < n; ++b) {
      const int lo = std::min(a, b), hi = std::max(a, b);
      if (hi - lo <= 1 || (lo == 0 && hi == n - 1)) continue;
      if (pair.corners[lo] == pair.corners[hi]) continue;
      if (distance[0][b] < 0 || distance[1][b] < 0) continue;
      const auto [first, second] = piece_sizes(lo, hi);
      const long bends = std::max(distance[0][b], distance[1][b]);
      const long score = std::max(first, second) + bends;
      for (int c = 0; c < kClasses; ++c)
        if (std::min(first, second) >= std::max(3, least[c]) && score < found[c].score &&
            (straight[c] < 0 || distance[straight[c]][b] == 0))
          found[c] = {score, lo, hi};
    }
    for (int c = 0; c < kClasses; ++c)
      if (found[c].a >= 0) best[c].push_back(found[c]);
  }
  // The best few of each class, without repeats.
  std::set<std::pair<int, int>> taken;
  for (int c = 0; c < kClasses; ++c) {
    std::sort(best[c].begin(), best[c].end(), [](const Scored& x, const Scored& y) { return x.score < y.score; });
    int kept = 0;
    for (const Scored& x : best[c]) {
      if (kept == kCandidatesPerClass) break;
      if (x.score >= 2 * long(n)) break;  // no smaller than the pair
      if (!taken.insert({x.a, x.b}).second) continue;
      ++kept;
      RoutedCut cut;
      cut.a = x.a;
      cut.b = x.b;
      cut.source_bends = graphs[0].bends(polygons[0], graphs[0].path(x.a, x.b), x.a, x.b);
      cut.target_bends = graphs[1].bends(polygons[1], graphs[1].path(x.a, x.b), x.a, x.b);
      const int count = int(std::max(cut.source_bends.size(), cut.target_bends.size()));
      pad_bends(polygons[0].at(cut.a), polygons[0].at(cut.b), cut.source_bends, count);
      pad_bends(polygons[1].at(cut.a), polygons[1].at(cut.b), cut.target_bends, count);
      out.push_back(std::move(cut));
    }
  }
  return out;
}

std::array<std::vector<int>, 2> routed_pieces(int corners, const RoutedCut& cut) {
  const int m = int(cut.source_bends.size());
  std::array<std::vector<int>, 2> pieces;
  for (int k = cut.a; k <= cut.b; ++k) pieces[0].push_back(k);
  for (int i = m - 1; i >= 0; --i) pieces[0].push_back(corners + i);
  for (int k = cut.b; k != cut.a; k = (k + 1) % corners) pieces[1].push_back(k);
  pieces[1].push_back(cut.a);
  for (int i = 0; i < m; ++i) pieces[1].push_back(corners + i);
  return pieces;
}


RoutedPiece routed_piece(const PolygonPair& pair, const RoutedCut& cut, std::vector<int> nodes) {
  const int n = int(pair.corners.size());
  RoutedPiece piece;
  piece.nodes = std::move(nodes);
  PolygonPair& sub = piece.pair;
  std::vector<int> id_of_vertex;  // pair vertex id -> piece vertex id
  for (int node : piece.nodes) {
    int id;
    if (node < n) {
      const int vertex = pair.corners[std::size_t(node)];
      if (int(id_of_vertex.size()) <= vertex) id_of_vertex.resize(std::size_t(vertex) + 1, -1);
      if (id_of_vertex[std::size_t(vertex)] < 0) {
        id_of_vertex[std::size_t(vertex)] = int(sub.source_positions.size());
        sub.source_positions.push_back(pair.source_positions[std::size_t(vertex)]);
        sub.target_positions.push_back(pair.target_positions[std::size_t(vertex)]);
      }
      id = id_of_vertex[std::size_t(vertex)];
    } else {
      id = int(sub.source_positions.size());
      sub.source_positions.push_back(cut.source_bends[std::size_t(node - n)]);
      sub.target_positions.push_back(cut.target_bends[std::size_t(node - n)]);
    }
    sub.corners.push_back(id);
  }
  if (piece.nodes.size() > 3) {
    piece.source_base = triangulate_polygon(sub.source());
    piece.target_base = triangulate_polygon(sub.target());
  }
  return piece;
}

}  // namespace stickmorph::internal
