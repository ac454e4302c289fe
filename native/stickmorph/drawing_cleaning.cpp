// Cleaning a drawing into a stick figure: see drawing_cleaning.h.
//
// The working drawing is a set of vertices and, per stroke, a path of them.
// Edges are the consecutive pairs of the paths, so splitting an edge at a
// junction is inserting a vertex into a path, and the strokes never lose
// track of their vertices (the Grease Pencil output draws each stroke along
// its path). The stages run in rounds until a round changes nothing:
//
//   merge   points (then vertices) within the merge distance become one;
//   join    crossings and touchings become shared vertices (exact predicates);
//   snap    free ends within the tolerance move onto the nearest stroke.
//
// Rounds are needed because new points are rounded: a crossing vertex is the
// double nearest the exact crossing, so its new edges can in principle cross
// an edge passing within an ulp, and a snapped end's edge has turned a
// little. A last round with no change is what makes the result clean to
// itself (a cleaned figure cleans to itself).
#include "stickmorph/drawing_cleaning.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "stickmorph/errors.h"
#include "stickmorph/exact_predicates.h"

namespace stickmorph {
namespace {

// Rounds of merge, join and snap before giving up. Each round after the first
// only repairs what the rounding of the previous one did; real drawings
// settle in two or three.
constexpr int kMaxRounds = 12;
// Snapping skips what lies within this many tolerances along the drawing
// from the free end: the stroke's own last points (always within the
// tolerance of its end, since tablets sample densely) and a stroke the end
// has just crossed (an overshoot, whose crossing already made the junction).
constexpr double kSnapExclusionTolerances = 3.0;

std::string point_text(const Vec2& p) { return "(" + format_double(p[0]) + ", " + format_double(p[1]) + ")"; }

double distance(const Vec2& a, const Vec2& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

// The nearest point of segment ab to p (in doubles: a snap target is a
// rounded point anyway, and the exact check comes at the end).
Vec2 nearest_on_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const long double dx = (long double)b[0] - a[0], dy = (long double)b[1] - a[1];
  const long double length2 = dx * dx + dy * dy;
  if (length2 == 0) return a;
  long double t = (((long double)p[0] - a[0]) * dx + ((long double)p[1] - a[1]) * dy) / length2;
  t = std::clamp(t, (long double)0, (long double)1);
  return {double(a[0] + t * dx), double(a[1] + t * dy)};
}

// The crossing point of segments ab and cd, known to cross at a point
// interior to both, rounded to doubles.
Vec2 crossing_point(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const long double rx = (long double)b[0] - a[0], ry = (long double)b[1] - a[1];
  const long double sx = (long double)d[0] - c[0], sy = (long double)d[1] - c[1];
  const long double denominator = rx * sy - ry * sx;
  const long double t = (((long double)c[0] - a[0]) * sy - ((long double)c[1] - a[1]) * sx) / denominator;
  return {double(a[0] + t * rx), double(a[1] + t * ry)};
}

// Where along segment ab a point lies, for ordering junctions on it.
long double along(const Vec2& p, const Vec2& a, const Vec2& b) {
  return ((long double)p[0] - a[0]) * ((long double)b[0] - a[0]) +
         ((long double)p[1] - a[1]) * ((long double)b[1] - a[1]);
}

struct PathEntry {
  int vertex;
  int point;  // the input point this entry was drawn as, or -1 for an inserted junction
};

// One edge occurrence: entry k of stroke s to the next entry (cyclically).
struct SegmentRef {
  int stroke;
  int entry;
};

class Cleaner {
 public:
  Cleaner(const Drawing& drawing, double tolerance)
      : in_(drawing), tolerance_(tolerance), merge_distance_(tolerance * kMergeDistanceFraction) {}

  CleanedDrawing run();

 private:
  // -- naming -----------------------------------------------------------------
  std::string stroke_name(int s) const {
    if (!in_.from_figure) return "stroke " + std::to_string(s);
    const auto& path = in_.strokes[std::size_t(s)];
    return "edge " + std::to_string(s) + " (" + std::to_string(path[0]) + "-" + std::to_string(path[1]) + ")";
  }
  std::string point_name(int p) const {
    if (in_.from_figure) return "vertex " + std::to_string(p);
    return "point " + std::to_string(point_index_[std::size_t(p)]) + " of stroke " +
           std::to_string(point_stroke_[std::size_t(p)]);
  }
  // The point index reported for input point p: its index within its stroke
  // (a drawing) or the vertex itself (a figure).
  int reported_point(int p) const { return in_.from_figure ? p : point_index_[std::size_t(p)]; }
  int reported_stroke(int p) const { return point_stroke_[std::size_t(p)]; }

  // The input point nearest before entry k of stroke s along its path, for
  // messages; -1 if none.
  int drawn_point_near(int s, int k) const {
    const auto& path = paths_[std::size_t(s)];
    for (int i = k; i >= 0; --i)
      if (path[std::size_t(i)].point >= 0) return path[std::size_t(i)].point;
    for (const PathEntry& e : path)
      if (e.point >= 0) return e.point;
    return -1;
  }

  // -- vertices ---------------------------------------------------------------
  int new_vertex(const Vec2& at) {
    position_.push_back(at);
    parent_.push_back(int(parent_.size()));
    return int(position_.size()) - 1;
  }
  int find(int v) {
    while (parent_[std::size_t(v)] != v) {
      parent_[std::size_t(v)] = parent_[std::size_t(parent_[std::size_t(v)])];
      v = parent_[std::size_t(v)];
    }
    return v;
  }

  void check_input();
  void merge_points();
  bool merge_vertices();
  void normalize_paths();
  std::vector<SegmentRef> segments() const;
  std::pair<int, int> segment_vertices(const SegmentRef& r) const {
    const auto& path = paths_[std::size_t(r.stroke)];
    const std::size_t next = (std::size_t(r.entry) + 1) % path.size();
    return {path[std::size_t(r.entry)].vertex, path[next].vertex};
  }
  std::vector<bool> repeated_segments(const std::vector<SegmentRef>& refs);
  std::unordered_map<int, std::vector<int>> points_by_vertex();
  void record_move(int vertex, DrawingChangeKind kind, int other_stroke, int lands,
                   const std::unordered_map<int, std::vector<int>>& points_of);
  bool remove_spikes();
  bool join();
  bool snap();
  [[noreturn]] void fail_overlap(const SegmentRef& a, const SegmentRef& b, const Vec2& from, const Vec2& to);
  CleanedDrawing assemble();

  const Drawing& in_;
  double tolerance_;
  double merge_distance_;
  std::vector<int> point_stroke_;  // per input point: the first stroke it is on (-1 none)
  std::vector<int> point_index_;   // per input point: its index in that stroke
  std::vector<Vec2> position_;     // working vertices
  std::vector<int> parent_;        // union-find over merged vertices
  std::vector<int> point_vertex_;  // per input point: its working vertex (before find)
  std::vector<std::vector<PathEntry>> paths_;
  struct Record {
    DrawingChange change;
    int vertex;  // where `at` is read at the end
    int point;   // the input point that moved (-1 none): `distance` is read at the end
  };
  std::vector<Record> records_;
  std::vector<bool> recorded_;  // per input point: a merge or snap names it already
  int crossings_ = 0, touches_ = 0, snaps_ = 0, merges_ = 0;
};

void Cleaner::check_input() {
  const std::size_t point_count = in_.points.size();
  point_stroke_.assign(point_count, -1);
  point_index_.assign(point_count, -1);
  if (in_.strokes.empty() && (!in_.from_figure || point_count == 0))
    throw InvalidDrawingError(DrawingDefect::NoStrokes,
                              in_.from_figure ? "the figure has no vertices" : "the drawing has no strokes");
  for (std::size_t s = 0; s < in_.strokes.size(); ++s) {
    const auto& stroke = in_.strokes[s];
    if (stroke.size() < 2) {
      std::string what = stroke_name(int(s)) + (stroke.empty() ? " has no points" : " has a single point");
      if (stroke.size() == 1 && stroke[0] >= 0 && std::size_t(stroke[0]) < point_count)
        what += ", at " + point_text(in_.points[std::size_t(stroke[0])]);
      throw InvalidDrawingError(DrawingDefect::TooFewPoints, what + ": a stroke needs two points", int(s),
                                stroke.size() == 1 ? 0 : -1);
    }
    for (std::size_t j = 0; j < stroke.size(); ++j) {
      const int p = stroke[j];
      if (p < 0 || std::size_t(p) >= point_count)
        throw InvalidDrawingError(DrawingDefect::IndexOutOfRange,
                                  stroke_name(int(s)) + ": " + (in_.from_figure ? "vertex " : "point ") +
                                      std::to_string(p) + " does not exist (there are " +
                                      std::to_string(point_count) + ")",
                                  int(s), int(j));
      if (point_stroke_[std::size_t(p)] < 0) {
        point_stroke_[std::size_t(p)] = int(s);
        point_index_[std::size_t(p)] = int(j);
      }
    }
  }
  for (std::size_t p = 0; p < point_count; ++p) {
    const Vec2& at = in_.points[p];
    const int stroke = point_stroke_[p];
    if (!std::isfinite(at[0]) || !std::isfinite(at[1]))
      throw InvalidDrawingError(DrawingDefect::NonFiniteCoordinate, point_name(int(p)) + " is not finite: " + point_text(at),
                                stroke, reported_point(int(p)));
    if (std::abs(at[0]) > kMaxCoordinateMagnitude || std::abs(at[1]) > kMaxCoordinateMagnitude)
      throw InvalidDrawingError(DrawingDefect::CoordinateTooLarge,
                                point_name(int(p)) + " is at " + point_text(at) + ", outside +-" +
                                    format_double(kMaxCoordinateMagnitude),
                                stroke, reported_point(int(p)));
  }
}

// Points in input order: each becomes the nearest vertex already made within
// the merge distance, or a vertex of its own. Exact duplicates always merge.
void Cleaner::merge_points() {
  const std::size_t point_count = in_.points.size();
  const double h = merge_distance_;
  std::vector<Segment> boxes(point_count);
  for (std::size_t p = 0; p < point_count; ++p) {
    const Vec2& at = in_.points[p];
    boxes[p] = {Vec2{at[0] - h, at[1] - h}, Vec2{at[0] + h, at[1] + h}};
  }
  std::vector<std::vector<int>> earlier(point_count);
  for_each_overlapping_box(boxes, boxes, [&](int i, int j) {
    if (j < i) earlier[std::size_t(i)].push_back(j);
  });
  point_vertex_.assign(point_count, -1);
  recorded_.assign(point_count, false);
  std::vector<bool> represents(point_count, false);  // the point made a vertex of its own
  for (std::size_t p = 0; p < point_count; ++p) {
    const Vec2& at = in_.points[p];
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity();
    std::sort(earlier[p].begin(), earlier[p].end());
    for (int q : earlier[p]) {
      if (!represents[std::size_t(q)]) continue;
      const double d = distance(at, in_.points[std::size_t(q)]);
      if (d <= h && d < best_distance) best = q, best_distance = d;
    }
    if (best < 0) {
      represents[p] = true;
      point_vertex_[p] = new_vertex(at);
      continue;
    }
    point_vertex_[p] = point_vertex_[std::size_t(best)];
    ++merges_;
    DrawingChange change{DrawingChangeKind::Merge};
    change.stroke = point_stroke_[p];
    change.point = reported_point(int(p));
    change.other_stroke = point_stroke_[std::size_t(best)];
    records_.push_back({change, point_vertex_[p], int(p)});
    recorded_[p] = true;
  }
  paths_.resize(in_.strokes.size());
  for (std::size_t s = 0; s < in_.strokes.size(); ++s)
    for (int p : in_.strokes[s]) paths_[s].push_back({point_vertex_[std::size_t(p)], p});
  normalize_paths();
  for (std::size_t s = 0; s < paths_.size(); ++s) {
    // A cyclic stroke left with two vertices goes there and back: join()
    // names that retrace.
    if (paths_[s].size() >= 2) continue;
    const Vec2 at = position_[std::size_t(paths_[s][0].vertex)];
    const std::string how = in_.from_figure
                                ? " joins two vertices at one position " + point_text(at)
                                : " collapses to a single point at " + point_text(at) + ": its " +
                                      std::to_string(in_.strokes[s].size()) + " points lie within " +
                                      format_double(h) + " (the merge distance) of one another";
    throw InvalidDrawingError(DrawingDefect::CollapsedStroke, stroke_name(int(s)) + how, int(s), 0);
  }
}

// Replaces merged vertices by their representatives and drops the
// zero-length steps that leaves (a cyclic path also its closing repeat).
void Cleaner::normalize_paths() {
  for (std::size_t s = 0; s < paths_.size(); ++s) {
    std::vector<PathEntry> out;
    for (PathEntry e : paths_[s]) {
      e.vertex = find(e.vertex);
      if (!out.empty() && out.back().vertex == e.vertex) {
        if (out.back().point < 0) out.back().point = e.point;
        continue;
      }
      out.push_back(e);
    }
    if (in_.cyclic[s])
      while (out.size() > 1 && out.back().vertex == out.front().vertex) out.pop_back();
    paths_[s] = std::move(out);
  }
}

// Vertices made by joins and snaps that came within the merge distance of
// another merge into the one made first. Returns whether any did.
bool Cleaner::merge_vertices() {
  std::vector<int> live;
  for (std::size_t s = 0; s < paths_.size(); ++s)
    for (const PathEntry& e : paths_[s]) live.push_back(find(e.vertex));
  std::sort(live.begin(), live.end());
  live.erase(std::unique(live.begin(), live.end()), live.end());
  const double h = merge_distance_;
  std::vector<Segment> boxes(live.size());
  for (std::size_t i = 0; i < live.size(); ++i) {
    const Vec2& at = position_[std::size_t(live[i])];
    boxes[i] = {Vec2{at[0] - h, at[1] - h}, Vec2{at[0] + h, at[1] + h}};
  }
  std::vector<std::pair<int, int>> close;
  for_each_overlapping_box(boxes, boxes, [&](int i, int j) {
    if (j < i && distance(position_[std::size_t(live[std::size_t(i)])], position_[std::size_t(live[std::size_t(j)])]) <= h)
      close.emplace_back(live[std::size_t(j)], live[std::size_t(i)]);
  });
  if (close.empty()) return false;
  std::sort(close.begin(), close.end());
  const auto points_of = points_by_vertex();
  bool merged = false;
  for (const auto& [kept, gone] : close) {
    const int a = find(kept), b = find(gone);
    if (a == b) continue;
    const int keep = std::min(a, b), drop = std::max(a, b);
    const auto kept_points = points_of.find(keep);
    const int other = kept_points == points_of.end() ? -1 : reported_stroke(kept_points->second.front());
    record_move(drop, DrawingChangeKind::Merge, other, keep, points_of);
    parent_[std::size_t(drop)] = keep;
    merged = true;
  }
  if (merged) normalize_paths();
  return merged;
}

std::vector<SegmentRef> Cleaner::segments() const {
  std::vector<SegmentRef> out;
  for (std::size_t s = 0; s < paths_.size(); ++s) {
    const std::size_t n = paths_[s].size();
    if (n < 2) continue;
    const std::size_t count = in_.cyclic[s] ? n : n - 1;
    for (std::size_t k = 0; k < count; ++k) out.push_back({int(s), int(k)});
  }
  return out;
}

void Cleaner::fail_overlap(const SegmentRef& a, const SegmentRef& b, const Vec2& from, const Vec2& to) {
  const int pa = drawn_point_near(a.stroke, a.entry), pb = drawn_point_near(b.stroke, b.entry);
  const std::string span = "from " + point_text(from) + " to " + point_text(to);
  if (a.stroke == b.stroke) {
    std::string near;
    if (pa >= 0 && pb >= 0 && !in_.from_figure)
      near = ", near its points " + std::to_string(std::min(reported_point(pa), reported_point(pb))) + " and " +
             std::to_string(std::max(reported_point(pa), reported_point(pb)));
    throw InvalidDrawingError(DrawingDefect::Retrace,
                              stroke_name(a.stroke) + " retraces itself " + span + near +
                                  ": a stroke may not run back along itself",
                              a.stroke, pa >= 0 ? reported_point(pa) : -1, a.stroke);
  }
  const int first = std::min(a.stroke, b.stroke), second = std::max(a.stroke, b.stroke);
  const int p_first = first == a.stroke ? pa : pb, p_second = first == a.stroke ? pb : pa;
  std::string near;
  if (!in_.from_figure && p_first >= 0 && p_second >= 0)
    near = ", near point " + std::to_string(reported_point(p_first)) + " of stroke " + std::to_string(first) +
           " and point " + std::to_string(reported_point(p_second)) + " of stroke " + std::to_string(second);
  const std::string names = in_.from_figure ? "edges " + stroke_name(first).substr(5) + " and " + stroke_name(second).substr(5)
                                            : "strokes " + std::to_string(first) + " and " + std::to_string(second);
  throw InvalidDrawingError(DrawingDefect::Overlap,
                            names + " overlap along a length " + span + near +
                                ": draw one stroke there, or keep them apart",
                            first, p_first >= 0 ? reported_point(p_first) : -1, second);
}

// The part two collinear segments share, for the overlap message.
std::pair<Vec2, Vec2> shared_span(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (compare_xy(b, a) < 0) std::swap(a, b);
  if (compare_xy(d, c) < 0) std::swap(c, d);
  const Vec2 lo = compare_xy(a, c) > 0 ? a : c;
  const Vec2 hi = compare_xy(b, d) < 0 ? b : d;
  return {lo, hi};
}

// Crossings and touchings become shared vertices. Returns whether any did.
// The segments whose two vertices an earlier segment already joins (an
// edge two paths share), after refusing the ones that are an overlap along
// a length (see inside). Called before any snapping too, so that a snap
// cannot split an overlap the artist drew into something that passes.
std::vector<bool> Cleaner::repeated_segments(const std::vector<SegmentRef>& refs) {
  std::vector<Segment> geometry(refs.size());
  std::vector<std::pair<int, int>> ends(refs.size());
  std::map<std::pair<int, int>, int> by_vertices;
  std::vector<bool> repeated(refs.size(), false);  // an edge another path already has
  std::vector<int> first_of(refs.size(), -1);      // ... and the segment that has it first
  for (std::size_t i = 0; i < refs.size(); ++i) {
    ends[i] = segment_vertices(refs[i]);
    geometry[i] = {position_[std::size_t(ends[i].first)], position_[std::size_t(ends[i].second)]};
    const auto key = std::minmax(ends[i].first, ends[i].second);
    const auto [it, fresh] = by_vertices.emplace(key, int(i));
    if (fresh) continue;
    repeated[i] = true;
    first_of[i] = it->second;
  }
  // The same two vertices joined twice: the strokes run along each other
  // for that edge (or a stroke goes there and back). One such edge alone,
  // within the tolerance, is what snapping and merging make of two strokes
  // that meet at a shallow angle (a crossing a hair from a junction merges
  // into it): they share it, and the figure has it once. A longer one, or a
  // chain of them (a stroke drawn over another, point on point), was drawn
  // so: an overlap along a length.
  {
    std::unordered_map<int, std::vector<std::size_t>> at_vertex;
    for (std::size_t i = 0; i < refs.size(); ++i)
      if (repeated[i]) {
        at_vertex[ends[i].first].push_back(i);
        at_vertex[ends[i].second].push_back(i);
      }
    for (std::size_t i = 0; i < refs.size(); ++i) {
      if (!repeated[i]) continue;
      const bool chained = at_vertex[ends[i].first].size() > 1 || at_vertex[ends[i].second].size() > 1;
      if (!chained && distance(geometry[i][0], geometry[i][1]) <= tolerance_) continue;
      // Name the whole run: walk the chain of repeated edges both ways.
      std::set<std::size_t> chain{i};
      std::vector<int> frontier{ends[i].first, ends[i].second};
      std::map<int, int> count;
      while (!frontier.empty()) {
        const int v = frontier.back();
        frontier.pop_back();
        for (std::size_t e : at_vertex[v])
          if (chain.insert(e).second) {
            frontier.push_back(ends[e].first);
            frontier.push_back(ends[e].second);
          }
      }
      for (std::size_t e : chain) ++count[ends[e].first], ++count[ends[e].second];
      std::vector<int> tips;
      for (const auto& [v, n] : count)
        if (n == 1) tips.push_back(v);
      const Vec2 from = tips.size() == 2 ? position_[std::size_t(tips[0])] : geometry[i][0];
      const Vec2 to = tips.size() == 2 ? position_[std::size_t(tips[1])] : geometry[i][1];
      fail_overlap(refs[std::size_t(first_of[i])], refs[i], from, to);
    }
  }
  return repeated;
}

// The input points of each vertex, as the union-find has them now.
std::unordered_map<int, std::vector<int>> Cleaner::points_by_vertex() {
  std::unordered_map<int, std::vector<int>> points_of;
  for (std::size_t p = 0; p < point_vertex_.size(); ++p) points_of[find(point_vertex_[p])].push_back(int(p));
  return points_of;
}

// `vertex` moves or merges into `lands`: each of its input points that no
// change names yet gets one (the first `kind`, the rest merges), so that
// every point not where it was drawn is named. A point keeps its first
// record: its distance is read at the end, from where it finally is.
// `points_of` is taken before the stage moved anything.
void Cleaner::record_move(int vertex, DrawingChangeKind kind, int other_stroke, int lands,
                          const std::unordered_map<int, std::vector<int>>& points_of) {
  const auto it = points_of.find(vertex);
  if (it == points_of.end()) return;  // a junction vertex: its record reads the final place
  for (int p : it->second) {
    if (recorded_[std::size_t(p)]) continue;
    recorded_[std::size_t(p)] = true;
    DrawingChange change{kind};
    change.stroke = reported_stroke(p);
    change.point = reported_point(p);
    change.other_stroke = other_stroke;
    records_.push_back({change, lands, p});
    if (kind == DrawingChangeKind::Merge) ++merges_;
    kind = DrawingChangeKind::Merge;
  }
}

// A spike: a stroke that steps out to a vertex nothing else reaches and
// straight back (x, v, x), within the tolerance. It has no width to draw, it
// would leave v dangling inside the stroke (a free end that is no stroke's
// end), and a longer one is a retrace (repeated_segments). v merges into x.
bool Cleaner::remove_spikes() {
  std::unordered_map<int, std::set<int>> neighbours;
  for (const SegmentRef& r : segments()) {
    const auto [a, b] = segment_vertices(r);
    neighbours[a].insert(b);
    neighbours[b].insert(a);
  }
  const auto points_of = points_by_vertex();
  bool any = false;
  for (std::size_t s = 0; s < paths_.size(); ++s) {
    auto& path = paths_[s];
    const std::size_t n = path.size();
    if (n < 3) {
      // A cyclic stroke of two vertices goes there and back: a retrace if
      // longer than the tolerance (repeated_segments), else a dot.
      if (n == 2 && in_.cyclic[s] &&
          distance(position_[std::size_t(path[0].vertex)], position_[std::size_t(path[1].vertex)]) <= tolerance_)
        throw InvalidDrawingError(DrawingDefect::CollapsedStroke,
                                  stroke_name(int(s)) + " goes out and back within the tolerance " +
                                      format_double(tolerance_) + " from " +
                                      point_text(position_[std::size_t(path[0].vertex)]) + ": nothing to draw",
                                  int(s), 0);
      continue;
    }
    for (std::size_t k = 0; k < n; ++k) {
      if (!in_.cyclic[s] && (k == 0 || k + 1 == n)) continue;
      const int before = path[(k + n - 1) % n].vertex, v = path[k].vertex, after = path[(k + 1) % n].vertex;
      if (before != after || neighbours[v].size() != 1 || find(v) != v) continue;
      if (distance(position_[std::size_t(v)], position_[std::size_t(before)]) > tolerance_) continue;
      if (!in_.cyclic[s] && n == 3)
        throw InvalidDrawingError(DrawingDefect::CollapsedStroke,
                                  stroke_name(int(s)) + " goes out and back within the tolerance " +
                                      format_double(tolerance_) + " from " +
                                      point_text(position_[std::size_t(before)]) + ": nothing to draw",
                                  int(s), 0);
      record_move(v, DrawingChangeKind::Merge, int(s), before, points_of);
      parent_[std::size_t(v)] = before;
      any = true;
    }
  }
  if (any) normalize_paths();
  return any;
}

bool Cleaner::join() {
  const std::vector<SegmentRef> refs = segments();
  std::vector<Segment> geometry(refs.size());
  std::vector<std::pair<int, int>> ends(refs.size());
  for (std::size_t i = 0; i < refs.size(); ++i) {
    ends[i] = segment_vertices(refs[i]);
    geometry[i] = {position_[std::size_t(ends[i].first)], position_[std::size_t(ends[i].second)]};
  }
  const std::vector<bool> repeated = repeated_segments(refs);
  // Per segment, the vertices to insert into it; per pair of segments one
  // crossing at most (two segments meet in one point unless collinear).
  std::vector<std::vector<int>> inserts(refs.size());
  std::vector<std::pair<int, int>> pairs;
  for_each_overlapping_box(geometry, geometry, [&](int i, int j) {
    if (i < j && !repeated[std::size_t(i)] && !repeated[std::size_t(j)]) pairs.emplace_back(i, j);
  });
  std::sort(pairs.begin(), pairs.end());
  std::set<std::pair<int, int>> touched;  // (segment, vertex) already recorded
  const auto touch = [&](std::size_t segment, int vertex, std::size_t by) {
    if (!touched.insert({int(segment), vertex}).second) return;
    inserts[segment].push_back(vertex);
    ++touches_;
    // The touching vertex's own drawn point, if it has one.
    int point = -1;
    const SegmentRef& r = refs[by];
    const auto& path = paths_[std::size_t(r.stroke)];
    for (const PathEntry& e : path)
      if (e.vertex == vertex && e.point >= 0) point = e.point;
    DrawingChange change{DrawingChangeKind::Touch};
    change.stroke = point >= 0 ? reported_stroke(point) : r.stroke;
    change.point = point >= 0 ? reported_point(point) : -1;
    change.other_stroke = refs[segment].stroke;
    records_.push_back({change, vertex, point});
  };
  for (const auto& [i, j] : pairs) {
    const auto [a, b] = ends[std::size_t(i)];
    const auto [c, d] = ends[std::size_t(j)];
    const Vec2 &pa = position_[std::size_t(a)], &pb = position_[std::size_t(b)];
    const Vec2 &pc = position_[std::size_t(c)], &pd = position_[std::size_t(d)];
    const int shared = (a == c || a == d) ? a : (b == c || b == d) ? b : -1;
    if (shared >= 0) {
      // Adjacent segments meet at their shared vertex; they overlap only if
      // they leave it in the same direction.
      const int x = shared == a ? b : a, y = shared == c ? d : c;
      const Vec2 &ps = position_[std::size_t(shared)], &px = position_[std::size_t(x)], &py = position_[std::size_t(y)];
      if (orientation(ps, px, py) == 0 &&
          ((px[0] - ps[0]) * (py[0] - ps[0]) + (px[1] - ps[1]) * (py[1] - ps[1])) > 0) {
        const Vec2 to = distance(ps, px) < distance(ps, py) ? px : py;
        fail_overlap(refs[std::size_t(i)], refs[std::size_t(j)], ps, to);
      }
      continue;
    }
    switch (segment_contact(pa, pb, pc, pd)) {
      case SegmentContact::Disjoint: break;
      case SegmentContact::Overlapping: {
        const auto [from, to] = shared_span(pa, pb, pc, pd);
        fail_overlap(refs[std::size_t(i)], refs[std::size_t(j)], from, to);
      }
      case SegmentContact::Touching:
        // An end of one lies on the other (ends never coincide: equal
        // positions merged). That stroke now passes through it.
        if (on_segment(pc, pa, pb)) touch(std::size_t(i), c, std::size_t(j));
        if (on_segment(pd, pa, pb)) touch(std::size_t(i), d, std::size_t(j));
        if (on_segment(pa, pc, pd)) touch(std::size_t(j), a, std::size_t(i));
        if (on_segment(pb, pc, pd)) touch(std::size_t(j), b, std::size_t(i));
        break;
      case SegmentContact::Crossing: {
        const int v = new_vertex(crossing_point(pa, pb, pc, pd));
        inserts[std::size_t(i)].push_back(v);
        inserts[std::size_t(j)].push_back(v);
        ++crossings_;
        DrawingChange change{DrawingChangeKind::Crossing};
        change.stroke = refs[std::size_t(i)].stroke;
        change.other_stroke = refs[std::size_t(j)].stroke;
        records_.push_back({change, v, -1});
        break;
      }
    }
  }
  bool any = false;
  // Insert per stroke, last segment first so that entry numbers stay put.
  std::vector<std::size_t> order(refs.size());
  for (std::size_t i = 0; i < refs.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return refs[x].stroke != refs[y].stroke ? refs[x].stroke < refs[y].stroke : refs[x].entry > refs[y].entry;
  });
  for (std::size_t i : order) {
    auto& vertices = inserts[i];
    if (vertices.empty()) continue;
    any = true;
    const Vec2 a = position_[std::size_t(ends[i].first)], b = position_[std::size_t(ends[i].second)];
    std::sort(vertices.begin(), vertices.end(), [&](int x, int y) {
      return along(position_[std::size_t(x)], a, b) < along(position_[std::size_t(y)], a, b);
    });
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    auto& path = paths_[std::size_t(refs[i].stroke)];
    std::vector<PathEntry> entries;
    for (int v : vertices) entries.push_back({v, -1});
    path.insert(path.begin() + refs[i].entry + 1, entries.begin(), entries.end());
  }
  if (any) normalize_paths();
  return any;
}

// Free ends within the tolerance of a stroke move onto it (an end that
// stopped short, or overshot by less than the tolerance). Returns whether
// any did.
//
// An end's *tail* is the run of its stroke's last vertices that all lie
// within the tolerance of other strokes (or of a far part of its own). Where
// the tail crosses what it runs along, or runs along it for
// kTrimTolerances or more (a ring closed past its start, a stroke drawn on
// over the end of another), the tail is an overlap the artist did not mean
// as a shape: its inner end snaps and the rest merges into that junction.
// Otherwise only the end itself snaps. Without this, the jitter of such an
// overlap makes little loops whose number differs from drawing to drawing,
// and two poses of one figure would not match (figure_correspondence.h).
bool Cleaner::snap() {
  if (tolerance_ <= 0) return false;
  const std::vector<SegmentRef> refs = segments();
  const double t = tolerance_;
  std::unordered_map<int, std::vector<int>> neighbours;
  std::vector<std::pair<int, int>> ends(refs.size());
  for (std::size_t i = 0; i < refs.size(); ++i) {
    ends[i] = segment_vertices(refs[i]);
    neighbours[ends[i].first].push_back(ends[i].second);
    neighbours[ends[i].second].push_back(ends[i].first);
  }
  // Two strokes may share an edge (join() keeps a short one): count it once.
  for (auto& [vertex, list] : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  struct FreeEnd {
    int stroke;
    bool back;  // the path's last entry (else its first)
  };
  std::vector<FreeEnd> free_ends;
  for (std::size_t s = 0; s < paths_.size(); ++s) {
    if (in_.cyclic[s] || paths_[s].size() < 2) continue;
    if (neighbours[paths_[s].front().vertex].size() == 1) free_ends.push_back({int(s), false});
    if (neighbours[paths_[s].back().vertex].size() == 1) free_ends.push_back({int(s), true});
  }
  if (free_ends.empty()) return false;
  // Where strokes begin and end, joined or not: where strokes meet. (Not
  // for a figure, whose every vertex ends an edge: there a junction is a
  // junction by its degree.)
  std::unordered_set<int> stroke_ends;
  for (std::size_t s = 0; s < paths_.size() && !in_.from_figure; ++s)
    if (!in_.cyclic[s] && !paths_[s].empty()) {
      stroke_ends.insert(paths_[s].front().vertex);
      stroke_ends.insert(paths_[s].back().vertex);
    }

  // A uniform grid of the segments, cells of the tolerance (at least a
  // millionth of the drawing, so that the grid stays small), for the
  // "what is within the tolerance of this point" queries of the tail walks.
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for (const auto& path : paths_)
    for (const PathEntry& e : path)
      for (int axis = 0; axis < 2; ++axis) {
        lo[axis] = std::min(lo[axis], position_[std::size_t(e.vertex)][std::size_t(axis)]);
        hi[axis] = std::max(hi[axis], position_[std::size_t(e.vertex)][std::size_t(axis)]);
      }
  const double cell = std::max({t, (hi[0] - lo[0]) * 1e-6, (hi[1] - lo[1]) * 1e-6});
  const auto cell_of = [&](double value, int axis) { return std::int64_t(std::floor((value - lo[axis]) / cell)); };
  std::unordered_map<std::int64_t, std::vector<int>> grid;
  const std::int64_t columns = cell_of(hi[0], 0) + 3;
  const auto key = [columns](std::int64_t x, std::int64_t y) { return (y + 1) * columns + (x + 1); };
  for (std::size_t i = 0; i < refs.size(); ++i) {
    const Vec2 &a = position_[std::size_t(ends[i].first)], &b = position_[std::size_t(ends[i].second)];
    for (std::int64_t y = cell_of(std::min(a[1], b[1]), 1); y <= cell_of(std::max(a[1], b[1]), 1); ++y)
      for (std::int64_t x = cell_of(std::min(a[0], b[0]), 0); x <= cell_of(std::max(a[0], b[0]), 0); ++x)
        grid[key(x, y)].push_back(int(i));
  }
  // The segments within the tolerance's box of p.
  const auto near = [&](const Vec2& p) {
    std::vector<int> found;
    for (std::int64_t y = cell_of(p[1] - t, 1); y <= cell_of(p[1] + t, 1); ++y)
      for (std::int64_t x = cell_of(p[0] - t, 0); x <= cell_of(p[0] + t, 0); ++x) {
        const auto it = grid.find(key(x, y));
        if (it != grid.end()) found.insert(found.end(), it->second.begin(), it->second.end());
      }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
  };
  // What lies within kSnapExclusionTolerances along the drawing from v: its
  // own stroke just behind it, or a stroke it already meets there.
  const auto reached_from = [&](int v, std::unordered_set<int>& reached) {
    const double reach = kSnapExclusionTolerances * t;
    std::unordered_map<int, double> best{{v, 0.0}};
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    queue.push({0.0, v});
    while (!queue.empty()) {
      const auto [d, u] = queue.top();
      queue.pop();
      if (d > best[u]) continue;
      reached.insert(u);
      for (int w : neighbours[u]) {
        const double dw = d + distance(position_[std::size_t(u)], position_[std::size_t(w)]);
        if (dw >= reach) continue;
        const auto it = best.find(w);
        if (it != best.end() && it->second <= dw) continue;
        best[w] = dw;
        queue.push({dw, w});
      }
    }
  };
  const auto points_of = points_by_vertex();

  struct Snap {
    FreeEnd end;
    int trimmed;   // how many tail entries merge into the snapping one (a zip: how many zip)
    int segment;   // the segment snapped onto (-1 for a zip)
    int vertex;    // onto this vertex of it, or -1: onto `at` inside it
    Vec2 at;
    std::vector<int> zip_onto;     // a zip: per run vertex, the branch vertex it merges into
    std::vector<int> zip_strokes;  // and that branch's stroke
  };
  std::vector<Snap> snaps;
  for (const FreeEnd& end : free_ends) {
    const auto& path = paths_[std::size_t(end.stroke)];
    const int m = int(path.size()) - 1;
    const auto entry = [&](int k) { return path[std::size_t(end.back ? m - k : k)].vertex; };
    // Walk the tail: e_0 (the end), e_1, ... while each lies within the
    // tolerance of something it is not attached to. Never the stroke's
    // other end, never through a junction.
    struct Near {
      int segment;
      Vec2 at;
      double distance;
      std::vector<int> others;  // the segments it was measured against
    };
    std::vector<Near> tail;
    std::unordered_set<int> tail_vertices;
    int along = -1;  // the stroke the tail runs along: the end's nearest
    for (int k = 0; k < m; ++k) {
      const int v = entry(k);
      if (k > 0 && neighbours[v].size() != 2) break;
      tail_vertices.insert(v);
      std::unordered_set<int> excluded = tail_vertices;
      reached_from(v, excluded);
      const Vec2 p = position_[std::size_t(v)];
      int best = -1;
      double best_distance = std::numeric_limits<double>::infinity();
      Vec2 best_at{};
      std::vector<int> others;
      for (int g : near(p)) {
        const auto [a, b] = ends[std::size_t(g)];
        if (excluded.count(a) || excluded.count(b)) continue;
        others.push_back(g);
        // Past the end itself, only the stroke the end is near: a tail runs
        // along one stroke (in a dense drawing something else is always
        // within the tolerance of some point).
        if (along >= 0 && refs[std::size_t(g)].stroke != along) continue;
        const Vec2 q = nearest_on_segment(p, position_[std::size_t(a)], position_[std::size_t(b)]);
        const double d = distance(p, q);
        if (d <= t && d < best_distance) best = g, best_distance = d, best_at = q;
      }
      if (best < 0) break;
      along = refs[std::size_t(best)].stroke;
      tail.push_back({best, best_at, best_distance, std::move(others)});
    }
    if (tail.empty()) continue;
    const int K = int(tail.size());
    // Zip: the tail and the rest of its run (up to a junction J) lie along
    // another branch of J, within the tolerance, vertex by vertex: a ring
    // closed past its start whose end already landed on one of its first
    // points leaves its start dangling along its end that way. The whole run
    // merges into J, and the stroke now starts (or ends) there.
    {
      std::vector<int> onto;
      std::vector<int> onto_stroke;
      std::unordered_set<int> run;
      int k = 0;
      bool zipped = false;
      for (; k < m; ++k) {
        const int v = entry(k);
        if (k > 0 && neighbours[v].size() >= 3) {
          zipped = true;
          break;
        }
        if (k > 0 && neighbours[v].size() != 2) break;
        run.insert(v);
        const Vec2 p = position_[std::size_t(v)];
        int best = -1, best_stroke = -1;
        double best_distance = std::numeric_limits<double>::infinity();
        for (int g : near(p)) {
          const auto [a, b] = ends[std::size_t(g)];
          // Along its own stroke only: the branch is the ring's other end,
          // and the run's points stay on their stroke's path.
          if (refs[std::size_t(g)].stroke != end.stroke) continue;
          if (run.count(a) || run.count(b) || a == entry(k + 1) || b == entry(k + 1)) continue;
          const double d = distance(p, nearest_on_segment(p, position_[std::size_t(a)], position_[std::size_t(b)]));
          if (d > t) continue;
          // Into a branch vertex within the tolerance: a zip moves points no
          // further than a snap.
          for (int w : {a, b}) {
            const double dw = distance(p, position_[std::size_t(w)]);
            if (dw <= t && dw < best_distance) best = w, best_stroke = refs[std::size_t(g)].stroke, best_distance = dw;
          }
        }
        if (best < 0) break;
        onto.push_back(best);
        onto_stroke.push_back(best_stroke);
      }
      // A run of the end alone next to J is a stub, not a zip: the snap
      // rules below take it.
      if (zipped && k >= 2) {
        // The branch must lead into J where the run does.
        const int junction = entry(k);
        const auto& around = neighbours[junction];
        const int last = onto.back();
        if (last == junction || std::find(around.begin(), around.end(), last) != around.end()) {
          Snap zip{end, k, -1, -1, Vec2{}, {}, {}};
          zip.zip_onto = onto;
          zip.zip_strokes = onto_stroke;
          snaps.push_back(std::move(zip));
          continue;
        }
      }
    }
    double length = 0;
    bool crosses = false;
    for (int i = 0; i + 1 < K; ++i) {
      const Vec2 &a = position_[std::size_t(entry(i))], &b = position_[std::size_t(entry(i + 1))];
      length += distance(a, b);
      for (int g : tail[std::size_t(i)].others) {
        if (refs[std::size_t(g)].stroke != along) continue;
        const auto [c, d] = ends[std::size_t(g)];
        if (segment_contact(a, b, position_[std::size_t(c)], position_[std::size_t(d)]) == SegmentContact::Crossing)
          crosses = true;
      }
    }
    constexpr double kTrimTolerances = 4.0;
    const bool overlap = crosses || length >= kTrimTolerances * t;
    if (overlap && K == m) {
      // Every point but the last runs along another stroke: not a tail but a
      // stroke drawn over another, which has no one right reading.
      const int other = refs[std::size_t(tail[0].segment)].stroke;
      if (length >= kTrimTolerances * t) {
        const Vec2 &from = position_[std::size_t(entry(0))], &to = position_[std::size_t(entry(K - 1))];
        if (other == end.stroke)
          throw InvalidDrawingError(DrawingDefect::Retrace,
                                    stroke_name(end.stroke) + " runs back along itself from " + point_text(from) +
                                        " to " + point_text(to) + ", within the tolerance " + format_double(t) +
                                        ": a stroke may not retrace itself",
                                    end.stroke, -1, end.stroke);
        const SegmentRef a{end.stroke, 0}, b = refs[std::size_t(tail[0].segment)];
        fail_overlap(a, b, from, to);
      }
    }
    // Two ends that nearly meet (a ring closed past its start, two legs at
    // the hip), or an end near a junction or where strokes already meet:
    // the tail joins that vertex, at its tail vertex nearest it. Rather than the strokes
    // beside them, so that the overlap of two ends leaves one junction and
    // no stub whatever its length, and three strokes drawn to one point
    // meet at one vertex, not in a tiny triangle of three.
    int meet = -1, meet_at = -1;
    double meet_distance = std::numeric_limits<double>::infinity();
    for (int k = 0; k < K; ++k) {
      const Vec2& p = position_[std::size_t(entry(k))];
      for (int g : tail[std::size_t(k)].others)
        for (int w : {ends[std::size_t(g)].first, ends[std::size_t(g)].second}) {
          if ((neighbours[w].size() == 2 && !stroke_ends.count(w)) || tail_vertices.count(w)) continue;
          // Never onto a vertex the next one already joins: that would
          // double the edge between them.
          if (k < m) {
            const auto& joined = neighbours[entry(k + 1)];
            if (std::find(joined.begin(), joined.end(), w) != joined.end()) continue;
          }
          const double d = distance(p, position_[std::size_t(w)]);
          if (d <= t && d < meet_distance) meet = w, meet_at = k, meet_distance = d;
        }
    }
    if (meet >= 0 && tail[0].distance > 0) {
      // The segment of `meet` among those measured, for the stale check.
      int segment = -1;
      for (int g : tail[std::size_t(meet_at)].others)
        if (ends[std::size_t(g)].first == meet || ends[std::size_t(g)].second == meet) segment = g;
      snaps.push_back({end, meet_at, segment, meet, position_[std::size_t(meet)], {}, {}});
      continue;
    }
    // An end drawn exactly onto a stroke made its contact where the artist
    // put it: that is the junction, whatever its tail does.
    // The tail's inner end if the tail is an overlap, else (or if that
    // snap is impossible) the end itself. Trying the end last keeps a
    // drawing that cleaned to a standstill standing still as a figure,
    // whose strokes are single edges (a cleaned figure cleans to itself).
    std::vector<int> choices;
    if (overlap && K < m && tail[0].distance > 0 && K > 1) choices.push_back(K - 1);
    choices.push_back(0);
    for (int j : choices) {
      const Near& target = tail[std::size_t(j)];
      const Vec2 p = position_[std::size_t(entry(j))];
      const auto [a, b] = ends[std::size_t(target.segment)];
      // Onto an end of the segment rather than a new vertex beside it: if
      // the foot is within a quarter tolerance of it (a new vertex that
      // close would leave a sliver edge, which the morph's triangulation
      // pays for), or if it is a free end within the tolerance (two ends
      // meet).
      int onto = -1;
      for (int w : {a, b}) {
        const Vec2& pw = position_[std::size_t(w)];
        const bool close = distance(target.at, pw) <= 0.25 * t || neighbours[w].size() == 1;
        if (close && distance(p, pw) <= t && (onto < 0 || distance(p, pw) < distance(p, position_[std::size_t(onto)])))
          onto = w;
      }
      // The vertex before the snapping one already joins the target: the
      // new edge would double an edge (or fold onto one). The end is a stub
      // along its neighbour's edges, as where a ring's end point landed on
      // its second point and its first dangles: it merges into that
      // neighbour if that is near, else this choice is no snap.
      if (j < m) {
        const int before = entry(j + 1);
        const auto& joined = neighbours[before];
        const bool doubles = onto >= 0 ? std::find(joined.begin(), joined.end(), onto) != joined.end()
                                       : (a == before || b == before);
        if (doubles) {
          if (distance(p, position_[std::size_t(before)]) > kSnapExclusionTolerances * t) continue;
          snaps.push_back({end, j, target.segment, before, position_[std::size_t(before)], {}, {}});
          break;
        }
      }
      snaps.push_back({end, j, target.segment, onto, onto >= 0 ? position_[std::size_t(onto)] : target.at, {}, {}});
      break;
    }
  }
  if (snaps.empty()) return false;
  // Apply in order; a snap whose vertices a previous snap of this round
  // changed waits for the next round, when it is measured again.
  std::unordered_set<int> moved;
  std::set<int> split;
  bool any = false;
  std::vector<std::pair<std::size_t, int>> segment_inserts;  // (segment, vertex)
  std::vector<std::pair<int, int>> trims;                    // (stroke, entries off the front or back, signed)
  for (const Snap& snap : snaps) {
    auto& path = paths_[std::size_t(snap.end.stroke)];
    const int m = int(path.size()) - 1;
    const auto entry = [&](int k) -> const PathEntry& { return path[std::size_t(snap.end.back ? m - k : k)]; };
    if (!snap.zip_onto.empty()) {
      bool stale = false;
      for (int k = 0; k <= snap.trimmed && !stale; ++k) stale = moved.count(entry(k).vertex) > 0;
      for (int w : snap.zip_onto) stale = stale || moved.count(w) > 0;
      if (stale) continue;
      // The run merges into J, where the stroke now starts (or ends): its
      // points then come first (or last) along the path, in drawing order.
      // (The branch vertices beside them are nearer, but the stroke passes
      // them again at its other end: a point mapped there would be out of
      // order along the path, which a Grease Pencil result walks.)
      const int junction = entry(snap.trimmed).vertex;
      for (int k = 0; k < snap.trimmed; ++k) {
        const int gone = entry(k).vertex;
        // The end itself is the snap; the run behind it merges.
        record_move(gone, k == 0 ? DrawingChangeKind::Snap : DrawingChangeKind::Merge,
                    snap.zip_strokes[std::size_t(k)], junction, points_of);
        parent_[std::size_t(gone)] = junction;
        moved.insert(gone);
        moved.insert(snap.zip_onto[std::size_t(k)]);
      }
      ++snaps_;
      moved.insert(entry(snap.trimmed).vertex);
      trims.emplace_back(snap.end.stroke, snap.end.back ? -snap.trimmed : snap.trimmed);
      any = true;
      continue;
    }
    if (snap.segment < 0) continue;
    const auto [a, b] = ends[std::size_t(snap.segment)];
    // The snapping vertex's next one too: two ends snapping onto each
    // other's neighbours in one round would join them twice.
    bool stale = moved.count(a) || moved.count(b) || split.count(snap.segment);
    for (int k = 0; k <= snap.trimmed + 1 && k <= m && !stale; ++k) stale = moved.count(entry(k).vertex) > 0;
    if (stale) continue;
    const PathEntry& snapping = entry(snap.trimmed);
    const int v = snapping.vertex;
    const int other_stroke = refs[std::size_t(snap.segment)].stroke;
    int lands = v;
    if (snap.vertex >= 0) {
      parent_[std::size_t(v)] = snap.vertex;  // the end becomes that vertex, which keeps its place
      lands = snap.vertex;
    } else {
      position_[std::size_t(v)] = snap.at;
      segment_inserts.emplace_back(std::size_t(snap.segment), v);
      split.insert(snap.segment);
    }
    // A stub folded onto its own neighbour merges; anything else snaps.
    const bool into_neighbour = snap.trimmed < m && snap.vertex == entry(snap.trimmed + 1).vertex;
    record_move(v, into_neighbour ? DrawingChangeKind::Merge : DrawingChangeKind::Snap,
                into_neighbour ? snap.end.stroke : other_stroke, lands, points_of);
    if (!into_neighbour) ++snaps_;
    // The tail beyond it merges into the junction.
    for (int k = 0; k < snap.trimmed; ++k) {
      const int gone = entry(k).vertex;
      record_move(gone, DrawingChangeKind::Merge, other_stroke, lands, points_of);
      parent_[std::size_t(gone)] = lands;
      moved.insert(gone);
    }
    if (snap.trimmed > 0) trims.emplace_back(snap.end.stroke, snap.end.back ? -snap.trimmed : snap.trimmed);
    if (snap.trimmed + 1 <= m) moved.insert(entry(snap.trimmed + 1).vertex);
    moved.insert(v);
    moved.insert(a);
    moved.insert(b);
    any = true;
  }
  // Insert the split points, last entry of a stroke first, then drop the
  // trimmed entries (their vertices now alias the junction, so
  // normalize_paths would merely collapse them; dropping them keeps a path
  // from stepping back and forth through the junction).
  std::sort(segment_inserts.begin(), segment_inserts.end(), [&](const auto& x, const auto& y) {
    const SegmentRef &rx = refs[x.first], &ry = refs[y.first];
    return rx.stroke != ry.stroke ? rx.stroke < ry.stroke : rx.entry > ry.entry;
  });
  for (const auto& [segment, vertex] : segment_inserts) {
    auto& path = paths_[std::size_t(refs[segment].stroke)];
    path.insert(path.begin() + refs[segment].entry + 1, PathEntry{vertex, -1});
  }
  for (const auto& [stroke, count] : trims) {
    auto& path = paths_[std::size_t(stroke)];
    if (count > 0)
      path.erase(path.begin(), path.begin() + count);
    else
      path.erase(path.end() + count, path.end());
  }
  if (any) normalize_paths();
  return any;
}

CleanedDrawing Cleaner::assemble() {
  CleanedDrawing out;
  out.tolerance = tolerance_;
  // Vertex order: by the first input point that became each, then the
  // junction vertices in the order made.
  const std::size_t point_count = in_.points.size();
  std::unordered_map<int, int> index;
  std::vector<int> order;
  for (std::size_t p = 0; p < point_count; ++p) {
    const int v = find(point_vertex_[p]);
    if (index.emplace(v, int(order.size())).second) order.push_back(v);
  }
  // Vertices made by crossings (no input point), by id: the order made.
  std::vector<int> made;
  for (const auto& path : paths_)
    for (const PathEntry& e : path)
      if (!index.count(e.vertex)) made.push_back(e.vertex);
  std::sort(made.begin(), made.end());
  made.erase(std::unique(made.begin(), made.end()), made.end());
  for (int v : made) {
    index.emplace(v, int(order.size()));
    order.push_back(v);
  }
  std::vector<Vec2> vertices;
  vertices.reserve(order.size());
  for (int v : order) vertices.push_back(position_[std::size_t(v)]);
  std::vector<std::array<std::int64_t, 2>> edges;
  std::set<std::pair<int, int>> seen;
  for (std::size_t s = 0; s < paths_.size(); ++s) {
    std::vector<int> stroke;
    for (const PathEntry& e : paths_[s]) stroke.push_back(index.at(e.vertex));
    const std::size_t n = stroke.size();
    const std::size_t count = n < 2 ? 0 : in_.cyclic[s] ? n : n - 1;
    for (std::size_t k = 0; k < count; ++k) {
      const int a = stroke[k], b = stroke[(k + 1) % n];
      if (seen.insert(std::minmax(a, b)).second) edges.push_back({a, b});
    }
    out.stroke_vertices.push_back(std::move(stroke));
  }
  out.cyclic = in_.cyclic;
  out.point_vertex.resize(point_count);
  for (std::size_t p = 0; p < point_count; ++p) out.point_vertex[p] = index.at(find(point_vertex_[p]));
  for (Record& record : records_) {
    DrawingChange change = record.change;
    const int v = index.at(find(record.vertex));
    change.at = vertices[std::size_t(v)];
    if (record.point >= 0) change.distance = distance(in_.points[std::size_t(record.point)], change.at);
    out.changes.push_back(change);
  }
  out.junctions_made = crossings_ + touches_;
  out.ends_snapped = snaps_;
  out.points_merged = merges_;
  try {
    out.figure = make_stick_figure(std::move(vertices), edges, in_.name);
  } catch (const InvalidFigureError& error) {
    // Name the strokes of the edges the figure check names.
    std::string where;
    int first_stroke = -1;
    for (int e : error.edges()) {
      const auto& edge = edges[std::size_t(e)];
      for (std::size_t s = 0; s < out.stroke_vertices.size() && where.size() < 400; ++s) {
        const auto& path = out.stroke_vertices[s];
        bool on = false;
        for (std::size_t k = 0; k + 1 < path.size() + (out.cyclic[s] ? 1 : 0) && !on; ++k) {
          const int a = path[k], b = path[(k + 1) % path.size()];
          on = std::minmax(a, b) == std::minmax<int>(int(edge[0]), int(edge[1]));
        }
        if (on) {
          if (first_stroke < 0) first_stroke = int(s);
          where += (where.empty() ? "" : ", ") + stroke_name(int(s));
          break;
        }
      }
    }
    throw InvalidDrawingError(DrawingDefect::Unresolved,
                              "the drawing could not be cleaned into a valid stick figure" +
                                  (where.empty() ? std::string() : " at " + where) + ": " + error.what(),
                              first_stroke);
  }
  return out;
}

CleanedDrawing Cleaner::run() {
  check_input();
  merge_points();
  repeated_segments(segments());  // an overlap as drawn is refused before anything moves
  for (int round = 0; round < kMaxRounds; ++round) {
    // Merging first: a rounded crossing may land within the merge distance
    // of a vertex, which join() would otherwise see as a touch.
    bool changed = merge_vertices();
    changed = remove_spikes() || changed;
    // Snapping before joining: an end that overshot a stroke by less than
    // the tolerance is pulled back onto it (a T, as meant), rather than
    // crossing it and leaving a stub that the junction then shields.
    // Snaps that wait for a neighbour's (stale in their round) go before
    // any join, or a crossing made meanwhile would shield them.
    for (int again = 0; again < kMaxRounds && snap(); ++again) changed = true;
    changed = join() || changed;
    if (!changed) break;
  }
  return assemble();
}

// The diagonal of the bounding box of the points on strokes (or of every
// point of a figure): the size the default tolerance is a fraction of.
double drawing_size(const Drawing& drawing) {
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for (const Vec2& p : drawing.points)
    for (int axis = 0; axis < 2; ++axis) {
      if (!std::isfinite(p[std::size_t(axis)])) continue;
      lo[axis] = std::min(lo[axis], p[std::size_t(axis)]);
      hi[axis] = std::max(hi[axis], p[std::size_t(axis)]);
    }
  if (!(hi[0] >= lo[0]) || !(hi[1] >= lo[1])) return 0;
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
}

}  // namespace

Drawing drawing_from_strokes(const std::vector<std::vector<Vec2>>& strokes, std::vector<bool> cyclic,
                             std::string name) {
  Drawing drawing;
  drawing.name = std::move(name);
  for (const auto& stroke : strokes) {
    std::vector<int> path;
    for (const Vec2& p : stroke) {
      path.push_back(int(drawing.points.size()));
      drawing.points.push_back(p);
    }
    drawing.strokes.push_back(std::move(path));
  }
  if (cyclic.empty()) cyclic.assign(strokes.size(), false);
  if (cyclic.size() != strokes.size())
    throw InvalidArgumentError("cyclic has " + std::to_string(cyclic.size()) + " entries for " +
                               std::to_string(strokes.size()) + " strokes");
  drawing.cyclic = std::move(cyclic);
  return drawing;
}

Drawing drawing_from_figure(std::vector<Vec2> vertices, const std::vector<std::array<std::int64_t, 2>>& edges,
                            std::string name) {
  Drawing drawing;
  drawing.from_figure = true;
  drawing.name = std::move(name);
  const std::int64_t count = std::int64_t(vertices.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    for (std::size_t end = 0; end < 2; ++end)
      if (edges[e][end] < 0 || edges[e][end] >= count)
        throw InvalidDrawingError(DrawingDefect::IndexOutOfRange,
                                  "edge " + std::to_string(e) + " (" + std::to_string(edges[e][0]) + "-" +
                                      std::to_string(edges[e][1]) + "): vertex " + std::to_string(edges[e][end]) +
                                      " does not exist (the figure has " + std::to_string(count) + " vertices)",
                                  int(e));
    drawing.strokes.push_back({int(edges[e][0]), int(edges[e][1])});
  }
  drawing.cyclic.assign(edges.size(), false);
  drawing.points = std::move(vertices);
  return drawing;
}

const char* drawing_change_name(DrawingChangeKind kind) {
  switch (kind) {
    case DrawingChangeKind::Merge: return "merge";
    case DrawingChangeKind::Snap: return "snap";
    case DrawingChangeKind::Crossing: return "crossing";
    case DrawingChangeKind::Touch: return "touch";
  }
  return "?";
}

std::string CleanedDrawing::summary() const {
  std::vector<std::string> parts;
  const auto count = [&parts](int n, const char* one, const char* many) {
    if (n > 0) parts.push_back(std::to_string(n) + " " + (n == 1 ? one : many));
  };
  count(junctions_made, "junction made", "junctions made");
  count(ends_snapped, "end snapped", "ends snapped");
  count(points_merged, "point merged", "points merged");
  if (parts.empty()) return "no changes";
  std::string text;
  for (std::size_t i = 0; i < parts.size(); ++i) text += (i ? ", " : "") + parts[i];
  return text;
}

CleanedDrawing clean_drawing(const Drawing& drawing, const DrawingCleaningOptions& options) {
  if (drawing.cyclic.size() != drawing.strokes.size())
    throw InvalidArgumentError("cyclic has " + std::to_string(drawing.cyclic.size()) + " entries for " +
                               std::to_string(drawing.strokes.size()) + " strokes");
  double tolerance = 0;
  if (options.tolerance) {
    tolerance = *options.tolerance;
    if (!std::isfinite(tolerance) || tolerance < 0)
      throw InvalidArgumentError("tolerance is " + format_double(tolerance) + ", not a finite number >= 0");
  } else {
    tolerance = kDefaultToleranceFraction * drawing_size(drawing);
    if (!std::isfinite(tolerance)) tolerance = 0;
  }
  Cleaner cleaner(drawing, tolerance);
  CleanedDrawing cleaned = cleaner.run();
  return cleaned;
}

void validate_cleaning(const CleanedDrawing& cleaned, const Drawing& drawing) {
  const auto fail = [](const std::string& what) { throw InternalError("clean_drawing: " + what); };
  try {
    validate(cleaned.figure);
  } catch (const InvalidFigureError& error) {
    fail(std::string("the cleaned figure is invalid: ") + error.what());
  }
  const StickFigure& figure = cleaned.figure;
  const int n = int(figure.vertices.size());
  if (cleaned.stroke_vertices.size() != drawing.strokes.size() || cleaned.cyclic != drawing.cyclic)
    fail("the strokes do not match the drawing's");
  if (cleaned.point_vertex.size() != drawing.points.size()) fail("point_vertex has the wrong length");
  std::set<std::pair<int, int>> edges, on_paths;
  for (const Edge& e : figure.edges) edges.insert(std::minmax(e[0], e[1]));
  for (std::size_t s = 0; s < cleaned.stroke_vertices.size(); ++s) {
    const auto& path = cleaned.stroke_vertices[s];
    const std::size_t count = path.size() < 2 ? 0 : cleaned.cyclic[s] ? path.size() : path.size() - 1;
    for (int v : path)
      if (v < 0 || v >= n) fail("stroke " + std::to_string(s) + " names vertex " + std::to_string(v));
    for (std::size_t k = 0; k < count; ++k) {
      const auto edge = std::minmax(path[k], path[(k + 1) % path.size()]);
      if (!edges.count(edge))
        fail("stroke " + std::to_string(s) + " steps from " + std::to_string(edge.first) + " to " +
             std::to_string(edge.second) + ", not an edge");
      on_paths.insert(edge);
    }
    // Every input point of the stroke is on its path, in drawing order (a
    // Grease Pencil result walks the path and finds each point's place on
    // it): each at or after the place of the one before; a cyclic stroke's
    // last points may be back at its first vertex (a closing repeat).
    std::size_t place = 0;
    bool wrapped = false;
    for (int p : drawing.strokes[s]) {
      const int v = cleaned.point_vertex[std::size_t(p)];
      if (std::find(path.begin(), path.end(), v) == path.end())
        fail("point " + std::to_string(p) + " of stroke " + std::to_string(s) + " is not on its path");
      if (wrapped) {
        if (v != path[0]) fail("stroke " + std::to_string(s) + " passes its points out of order");
        continue;
      }
      std::size_t at = place;
      while (at < path.size() && path[at] != v) ++at;
      if (at < path.size()) {
        place = at;
      } else if (cleaned.cyclic[s] && v == path[0]) {
        wrapped = true;
      } else {
        fail("stroke " + std::to_string(s) + " passes its points out of order (point " + std::to_string(p) + ")");
      }
    }
  }
  if (on_paths != edges) fail("an edge lies on no stroke");
  // Points not where they were drawn are named by a change.
  std::map<std::pair<int, int>, double> moved;  // (stroke, point) -> distance reported
  for (const DrawingChange& change : cleaned.changes)
    if ((change.kind == DrawingChangeKind::Merge || change.kind == DrawingChangeKind::Snap) && change.point >= 0)
      moved[{drawing.from_figure ? -1 : change.stroke, change.point}] = change.distance;
  // Where each point is reported: (stroke, index in it), or (-1, vertex) for a figure.
  std::vector<std::pair<int, int>> reported(drawing.points.size());
  for (std::size_t p = 0; p < drawing.points.size(); ++p) reported[p] = {-1, int(p)};
  if (!drawing.from_figure)
    for (std::size_t s = drawing.strokes.size(); s-- > 0;)
      for (std::size_t j = drawing.strokes[s].size(); j-- > 0;)
        reported[std::size_t(drawing.strokes[s][j])] = {int(s), int(j)};
  for (std::size_t p = 0; p < drawing.points.size(); ++p) {
    const int v = cleaned.point_vertex[p];
    if (v < 0 || v >= n) fail("point " + std::to_string(p) + " maps to no vertex");
    const Vec2& now = figure.vertices[std::size_t(v)];
    if (now == drawing.points[p]) continue;
    const auto it = moved.find(reported[p]);
    if (it == moved.end()) fail("point " + std::to_string(p) + " moved with no change naming it");
    const double d = std::hypot(now[0] - drawing.points[p][0], now[1] - drawing.points[p][1]);
    if (!(std::abs(it->second - d) <= 1e-12 * std::max(1.0, d)))
      fail("point " + std::to_string(p) + " moved " + format_double(d) + ", reported " + format_double(it->second));
  }
}

bool is_valid(const CleanedDrawing& cleaned, const Drawing& drawing) {
  try {
    validate_cleaning(cleaned, drawing);
    return true;
  } catch (const InternalError&) {
    return false;
  }
}

}  // namespace stickmorph
