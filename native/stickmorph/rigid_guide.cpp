// The as-rigid-as-possible trajectory of a stick figure; see rigid_guide.h.
#include "stickmorph/rigid_guide.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "stickmorph/errors.h"
#include "stickmorph/internal/edge_turns.h"
#include "stickmorph/internal/edge_vector_fit.h"
#include "stickmorph/internal/motion_timing.h"

namespace stickmorph {
namespace {

// Samples of the cumulative motion table: fine enough that the inverse,
// piecewise linear, is within a fraction of a percent of even for any frame
// count an animation uses, and cheap (one triangular solve per sample).
constexpr int kMotionSamples = 200;

double ease(double t, Easing easing) {
  if (easing == Easing::InOut) return t * t * (3 - 2 * t);
  return t;
}

}  // namespace

Easing parse_easing(const std::string& name) {
  if (name == "none") return Easing::None;
  if (name == "in-out") return Easing::InOut;
  throw InvalidArgumentError("unknown easing '" + name + "' (choose none or in-out)");
}

std::string easing_name(Easing easing) {
  switch (easing) {
    case Easing::None: return "none";
    case Easing::InOut: return "in-out";
  }
  throw InternalError("easing_name: unknown Easing");
}

struct RigidGuide::State {
  int n = 0;
  std::vector<Edge> edges;
  std::vector<double> angle0, turn, length0, length1;  // per edge
  std::vector<Vec2> center0, center1;                  // part -> centroid in source, target
  std::vector<Vec2> source, target;
  std::optional<internal::EdgeVectorFit> fit;
  std::optional<internal::MotionTiming> timing;  // of the cumulative RMS displacement at u = j / kMotionSamples
  std::optional<LocalClock> clock;               // local timing (issue 31); none for the plain guide
  /// The figure at u whose edge e points along directions[e] (a unit
  /// vector): the least-squares positions for the edges at their lengths
  /// at u (EdgeVectorFit), each part's centroid on its straight line.
  std::vector<Vec2> positions(double u, const std::vector<Vec2>& directions) const;
};

RigidGuide::RigidGuide(const StickFigure& source, const std::vector<Vec2>& target_vertices,
                       const SimilarityMotion& similarity, const std::optional<LocalTiming>& local_timing)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.n = int(source.vertices.size());
  if (int(target_vertices.size()) != s.n)
    throw InvalidArgumentError("RigidGuide: the source has " + std::to_string(s.n) + " vertices and the target " +
                               std::to_string(target_vertices.size()));
  s.source = source.vertices;
  s.target = target_vertices;
  s.edges = source.edges;
  const int m = int(s.edges.size());
  for (int e = 0; e < m; ++e) {
    const Edge& edge = s.edges[e];
    const Vec2 d0{s.source[edge[1]][0] - s.source[edge[0]][0], s.source[edge[1]][1] - s.source[edge[0]][1]};
    const Vec2 d1{s.target[edge[1]][0] - s.target[edge[0]][0], s.target[edge[1]][1] - s.target[edge[0]][1]};
    s.angle0.push_back(std::atan2(d0[1], d0[0]));
    s.length0.push_back(std::hypot(d0[0], d0[1]));
    s.length1.push_back(std::hypot(d1[0], d1[1]));
  }
  s.turn = internal::edge_turns(s.source, s.target, s.edges, similarity.angle);
  s.fit.emplace(s.n, s.edges);
  s.center0 = s.fit->part_centroids(s.source);
  s.center1 = s.fit->part_centroids(s.target);
  // The cumulative motion table for even speed. A figure that does not
  // move still shows rounding noise of the size's order times the unit
  // roundoff per sample; far below any motion an animation shows.
  double size = 0;
  for (int v = 0; v < s.n; ++v)
    size = std::max({size, std::abs(s.source[v][0]), std::abs(s.source[v][1]), std::abs(s.target[v][0]),
                     std::abs(s.target[v][1])});
  std::vector<double> motion(kMotionSamples + 1, 0.0), samples(kMotionSamples + 1, 0.0);
  // The edges' directions at the samples by a rotation of each per step
  // rather than a cosine and a sine each: those were 7% of a rigid morph
  // of 10^3 vertices (prepare_rigid_morph and 48 frames, thinned, perf;
  // prepare_rigid_morph went from 53 to 49 ms), and 200 rotations leave a
  // direction within about 1e-13 of at()'s, far below what the table's
  // timing resolves.
  std::vector<Vec2> directions(static_cast<std::size_t>(m)), step(static_cast<std::size_t>(m));
  for (int e = 0; e < m; ++e) {
    directions[e] = {std::cos(s.angle0[e]), std::sin(s.angle0[e])};
    const double a = s.turn[e] / kMotionSamples;
    step[e] = {std::cos(a), std::sin(a)};
  }
  std::vector<Vec2> previous = s.source;
  for (int j = 1; j <= kMotionSamples; ++j) {
    for (int e = 0; e < m; ++e) {
      const Vec2 d = directions[e];
      directions[e] = {d[0] * step[e][0] - d[1] * step[e][1], d[1] * step[e][0] + d[0] * step[e][1]};
    }
    const std::vector<Vec2> here = s.positions(double(j) / kMotionSamples, directions);
    long double sum = 0;
    for (int v = 0; v < s.n; ++v) {
      const long double dx = here[v][0] - previous[v][0], dy = here[v][1] - previous[v][1];
      sum += dx * dx + dy * dy;
    }
    motion[j] = motion[j - 1] + std::sqrt(double(sum / std::max(s.n, 1)));
    samples[j] = double(j) / kMotionSamples;
    previous = here;
  }
  samples.back() = 1;
  s.timing.emplace(std::move(samples), std::move(motion), 1e-10 * size, internal::kMostUnevenSpeed);
  // The table above is the plain guide's on purpose: local times are
  // delays on the morph's own clock.
  if (local_timing && !local_timing->is_plain()) {
    local_timing->check_vertex_count(std::size_t(s.n), "the guide's figure");
    s.clock.emplace(*local_timing, s.edges, s.fit->part(), s.fit->part_count(), s.source, s.target);
  }
}

RigidGuide::~RigidGuide() = default;
RigidGuide::RigidGuide(RigidGuide&&) noexcept = default;
RigidGuide& RigidGuide::operator=(RigidGuide&&) noexcept = default;

std::vector<Vec2> RigidGuide::at(double u) const {
  const State& s = *state_;
  if (s.clock) {
    // Every edge at its own local time; the parts then placed by their
    // leading vertices (LocalClock::place_parts), so the centroids given to
    // the fit only need to be some consistent placement.
    const std::vector<double> times = s.clock->edge_times(u);
    std::vector<Vec2> edge_vectors(s.edges.size());
    for (std::size_t e = 0; e < s.edges.size(); ++e) {
      const double tau = times[e];
      const double a = s.angle0[e] + tau * s.turn[e];
      const double length = (1 - tau) * s.length0[e] + tau * s.length1[e];
      edge_vectors[e] = {length * std::cos(a), length * std::sin(a)};
    }
    std::vector<Vec2> positions = s.fit->positions(edge_vectors, s.center0);
    s.clock->place_parts(u, positions);
    return positions;
  }
  std::vector<Vec2> directions(s.edges.size());
  for (std::size_t e = 0; e < s.edges.size(); ++e) {
    const double a = s.angle0[e] + u * s.turn[e];
    directions[e] = {std::cos(a), std::sin(a)};
  }
  return s.positions(u, directions);
}

std::vector<Vec2> RigidGuide::State::positions(double u, const std::vector<Vec2>& directions) const {
  std::vector<Vec2> edge_vectors(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const double length = (1 - u) * length0[e] + u * length1[e];
    edge_vectors[e] = {length * directions[e][0], length * directions[e][1]};
  }
  // Each part's centroid moves on a straight line.
  std::vector<Vec2> centroids(center0.size());
  for (std::size_t q = 0; q < center0.size(); ++q)
    for (int c = 0; c < 2; ++c) centroids[q][c] = (1 - u) * center0[q][c] + u * center1[q][c];
  return fit->positions(edge_vectors, centroids);
}

bool RigidGuide::retimed_by_morph() const { return !state_->clock; }

std::vector<double> RigidGuide::vertex_times(double u) const {
  return state_->clock ? state_->clock->vertex_times(u) : std::vector<double>{};
}

double RigidGuide::parameter_at(double t, Easing easing) const {
  if (!(t >= 0 && t <= 1)) throw InvalidArgumentError("the morph time must be in [0, 1]");
  if (t == 0 || t == 1) return t;
  return state_->timing->at(ease(t, easing));
}

}  // namespace stickmorph
