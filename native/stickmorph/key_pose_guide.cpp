// The as-rigid-as-possible trajectory through key poses; see key_pose_guide.h.
#include "stickmorph/key_pose_guide.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "stickmorph/errors.h"
#include "stickmorph/internal/edge_turns.h"
#include "stickmorph/internal/edge_vector_fit.h"

namespace stickmorph {
namespace {

std::string key_name(std::size_t k) { return "key " + std::to_string(k + 1); }

void check_inputs(const std::vector<std::vector<Vec2>>& keys, const std::vector<Edge>& edges,
                  const std::vector<double>& key_times, const KeyPoseGuideOptions& options) {
  const std::size_t count = keys.size();
  if (count < 2)
    throw InvalidArgumentError("a key-pose sequence needs at least two keys, got " + std::to_string(count));
  const std::size_t n = keys[0].size();
  for (std::size_t k = 1; k < count; ++k)
    if (keys[k].size() != n)
      throw InvalidArgumentError(key_name(k) + " has " + std::to_string(keys[k].size()) + " vertices, key 1 has " +
                                 std::to_string(n));
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const Edge& edge = edges[e];
    if (edge[0] < 0 || edge[1] < 0 || std::size_t(edge[0]) >= n || std::size_t(edge[1]) >= n)
      throw InvalidArgumentError("edge " + std::to_string(e) + " (" + std::to_string(edge[0]) + ", " +
                                 std::to_string(edge[1]) + ") names a vertex outside 0.." + std::to_string(n - 1));
    for (std::size_t k = 0; k < count; ++k)
      if (keys[k][edge[0]] == keys[k][edge[1]])
        throw InvalidArgumentError("edge " + std::to_string(e) + " (" + std::to_string(edge[0]) + ", " +
                                   std::to_string(edge[1]) + ") has length zero in " + key_name(k));
  }
  if (key_times.size() != count)
    throw InvalidArgumentError("a key time per key: " + std::to_string(count) + " keys, " +
                               std::to_string(key_times.size()) + " times");
  if (key_times[0] != 0) throw InvalidArgumentError("the first key's time must be 0");
  for (std::size_t k = 1; k < count; ++k)
    if (!(key_times[k] > key_times[k - 1]))
      throw InvalidArgumentError("the key times must increase strictly: " + key_name(k) + "'s is not after " +
                                 key_name(k - 1) + "'s");
  if (options.loop ? !(key_times.back() < 1) : key_times.back() != 1)
    throw InvalidArgumentError(options.loop ? "with loop, every key's time must be below 1 (the first key returns at 1)"
                                            : "the last key's time must be 1");
  const std::size_t segments = options.loop ? count : count - 1;
  if (!options.hold.empty() && options.hold.size() != count)
    throw InvalidArgumentError("hold: one entry per key: " + std::to_string(count) + " keys, " +
                               std::to_string(options.hold.size()) + " entries");
  if (!options.rotation.empty() && options.rotation.size() != segments)
    throw InvalidArgumentError("rotation: one entry per segment: " + std::to_string(segments) + " segments, " +
                               std::to_string(options.rotation.size()) + " entries");
  if (!options.turns.empty() && options.turns.size() != segments)
    throw InvalidArgumentError("turns: one entry per segment: " + std::to_string(segments) + " segments, " +
                               std::to_string(options.turns.size()) + " entries");
}

}  // namespace

// The part of a segment, from either end, over which an edge's log-length
// turns from the segment's straight line into the tangent at the knot.
constexpr double kLengthBlend = 0.25;

struct KeyPoseGuide::State {
  int n = 0;
  int edge_count = 0;
  std::vector<double> knots;                  // the key times, then 1 with loop
  std::vector<std::vector<double>> value;     // per knot: the channels below
  std::vector<std::vector<double>> tangent;   // per knot: d(channel)/dt there
  std::optional<internal::EdgeVectorFit> fit;
  /// The figure on `segment` with edge e at segment parameter edge_u(e)
  /// and every part's centroid at part_u (the Hermite channels and the
  /// log-lengths' blends, then the least-squares fit).
  template <class EdgeParameter>
  std::vector<Vec2> positions(int segment, const EdgeParameter& edge_u, double part_u) const;
  // Channels: edge angles [0, m), edge log-lengths [m, 2m), part centroids
  // x [2m, 2m + P) and y [2m + P, 2m + 2P).
};

KeyPoseGuide::KeyPoseGuide(const std::vector<std::vector<Vec2>>& keys, const std::vector<Edge>& edges,
                           const std::vector<double>& key_times, const KeyPoseGuideOptions& options)
    : state_(std::make_unique<State>()) {
  check_inputs(keys, edges, key_times, options);
  State& s = *state_;
  const std::size_t count = keys.size();
  const std::size_t segments = options.loop ? count : count - 1;
  const std::size_t m = edges.size();
  s.n = int(keys[0].size());
  s.edge_count = int(m);
  s.fit.emplace(s.n, edges);
  const std::size_t parts = std::size_t(s.fit->part_count());
  s.knots = key_times;
  if (options.loop) s.knots.push_back(1.0);
  const std::size_t knots = s.knots.size();
  auto key_at = [&](std::size_t knot) -> const std::vector<Vec2>& { return keys[knot % count]; };

  // The channels at every knot; the angles accumulate the turns segment by
  // segment, so that a figure turning on through several keys keeps
  // turning (with loop, the last knot's angles are the first's plus the
  // whole turns made on the way round).
  s.value.assign(knots, std::vector<double>(2 * m + 2 * parts, 0.0));
  for (std::size_t knot = 0; knot < knots; ++knot) {
    const std::vector<Vec2>& key = key_at(knot);
    std::vector<double>& v = s.value[knot];
    for (std::size_t e = 0; e < m; ++e) {
      const Vec2 d{key[edges[e][1]][0] - key[edges[e][0]][0], key[edges[e][1]][1] - key[edges[e][0]][1]};
      if (knot == 0) v[e] = std::atan2(d[1], d[0]);
      v[m + e] = std::log(std::hypot(d[0], d[1]));
    }
    const std::vector<Vec2> centroids = s.fit->part_centroids(key);
    for (std::size_t p = 0; p < parts; ++p) {
      v[2 * m + p] = centroids[p][0];
      v[2 * m + parts + p] = centroids[p][1];
    }
  }
  for (std::size_t segment = 0; segment < segments; ++segment) {
    const std::vector<Vec2>& from = key_at(segment);
    const std::vector<Vec2>& to = key_at(segment + 1);
    const RotationDirection direction =
        options.rotation.empty() ? RotationDirection::Short : options.rotation[segment];
    const int extra_turns = options.turns.empty() ? 0 : options.turns[segment];
    const double whole = fit_similarity(from, to, direction, extra_turns).angle;
    const std::vector<double> turn = internal::edge_turns(from, to, edges, whole);
    for (std::size_t e = 0; e < m; ++e) s.value[segment + 1][e] = s.value[segment][e] + turn[e];
  }

  // The tangents: the Bessel tangent at interior knots (the derivative of
  // the parabola through the knot and its neighbours, shared by the two
  // segments meeting there: C1), the end parabola's at the ends, periodic
  // with loop, zero where the motion holds.
  const std::size_t channels = s.value[0].size();
  std::vector<double> width(segments);
  for (std::size_t segment = 0; segment < segments; ++segment)
    width[segment] = s.knots[segment + 1] - s.knots[segment];
  auto slope = [&](std::size_t segment, std::size_t c) {
    return (s.value[segment + 1][c] - s.value[segment][c]) / width[segment];
  };
  // The parabola through knots a - 1, a, a + 1 (segments a - 1 and a), its
  // derivative at the middle knot.
  auto bessel = [&](std::size_t before, std::size_t after, std::size_t c) {
    return (width[after] * slope(before, c) + width[before] * slope(after, c)) / (width[before] + width[after]);
  };
  s.tangent.assign(knots, std::vector<double>(channels, 0.0));
  for (std::size_t c = 0; c < channels; ++c) {
    for (std::size_t knot = 1; knot + 1 < knots; ++knot) s.tangent[knot][c] = bessel(knot - 1, knot, c);
    if (options.loop) {
      s.tangent[0][c] = s.tangent[knots - 1][c] = bessel(segments - 1, 0, c);
    } else if (segments == 1) {
      s.tangent[0][c] = s.tangent[1][c] = slope(0, c);
    } else {
      // The end parabola's derivative at its first or last knot.
      const double h0 = width[0], h1 = width[1];
      s.tangent[0][c] = ((2 * h0 + h1) * slope(0, c) - h0 * slope(1, c)) / (h0 + h1);
      const double g0 = width[segments - 2], g1 = width[segments - 1];
      s.tangent[knots - 1][c] =
          ((2 * g1 + g0) * slope(segments - 1, c) - g1 * slope(segments - 2, c)) / (g0 + g1);
    }
  }
  for (std::size_t k = 0; k < options.hold.size(); ++k)
    if (options.hold[k]) {
      std::fill(s.tangent[k].begin(), s.tangent[k].end(), 0.0);
      if (options.loop && k == 0) std::fill(s.tangent[knots - 1].begin(), s.tangent[knots - 1].end(), 0.0);
    }
}

KeyPoseGuide::~KeyPoseGuide() = default;
KeyPoseGuide::KeyPoseGuide(KeyPoseGuide&&) noexcept = default;
KeyPoseGuide& KeyPoseGuide::operator=(KeyPoseGuide&&) noexcept = default;

const std::vector<double>& KeyPoseGuide::knot_times() const { return state_->knots; }
const std::vector<int>& KeyPoseGuide::part() const { return state_->fit->part(); }
int KeyPoseGuide::part_count() const { return state_->fit->part_count(); }

int KeyPoseGuide::segment_at(double t) const {
  const std::vector<double>& knots = state_->knots;
  const int last = int(knots.size()) - 2;
  const int after = int(std::upper_bound(knots.begin(), knots.end(), t) - knots.begin());
  return std::clamp(after - 1, 0, last);
}

std::vector<Vec2> KeyPoseGuide::at(double t) const {
  if (!(t >= 0 && t <= 1)) throw InvalidArgumentError("the sequence time must be in [0, 1]");
  const State& s = *state_;
  const int segment = segment_at(t);
  const double t0 = s.knots[std::size_t(segment)], width = s.knots[std::size_t(segment) + 1] - t0;
  const double u = (t - t0) / width;
  return s.positions(segment, [u](std::size_t) { return u; }, u);
}

std::vector<Vec2> KeyPoseGuide::in_segment(int segment, const std::vector<double>& edge_u, double u) const {
  const State& s = *state_;
  if (segment < 0 || std::size_t(segment) + 1 >= s.knots.size())
    throw InvalidArgumentError("segment " + std::to_string(segment) + " is outside 0.." +
                               std::to_string(s.knots.size() - 2));
  if (edge_u.size() != std::size_t(s.edge_count))
    throw InvalidArgumentError("a parameter per edge: " + std::to_string(s.edge_count) + " edges, " +
                               std::to_string(edge_u.size()) + " parameters");
  for (double x : edge_u)
    if (!(x >= 0 && x <= 1)) throw InvalidArgumentError("an edge's segment parameter must be in [0, 1]");
  if (!(u >= 0 && u <= 1)) throw InvalidArgumentError("the segment parameter must be in [0, 1]");
  return s.positions(segment, [&edge_u](std::size_t e) { return edge_u[e]; }, u);
}

template <class EdgeParameter>
std::vector<Vec2> KeyPoseGuide::State::positions(int segment, const EdgeParameter& edge_u, double part_u) const {
  const double t0 = knots[std::size_t(segment)], width = knots[std::size_t(segment) + 1] - t0;
  const std::vector<double>& y0 = value[std::size_t(segment)];
  const std::vector<double>& y1 = value[std::size_t(segment) + 1];
  const std::vector<double>& m0 = tangent[std::size_t(segment)];
  const std::vector<double>& m1 = tangent[std::size_t(segment) + 1];
  // Cubic Hermite basis: exactly the knot's values at u = 0 and u = 1.
  auto channel = [&](std::size_t c, double u) {
    const double u2 = u * u, u3 = u2 * u;
    const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    return h00 * y0[c] + h10 * width * m0[c] + h01 * y1[c] + h11 * width * m1[c];
  };
  // The log-lengths: the straight line of the segment, turned into the
  // knots' tangents only within kLengthBlend of either end (blend_in and
  // blend_out: value 0 and slope 1 at their knot, value and slope 0 from
  // kLengthBlend on). The same values and tangents at the knots as the
  // Hermite curve, so C1 as well, but an edge changes its length linearly
  // over most of the segment, as the pair morph's does (its rigidity
  // target, issue 28): a Hermite curve bends the whole segment, 4 times as
  // far from the line on average.
  auto log_length = [&](std::size_t c, double u) {
    if (u <= 0) return y0[c];  // the knots' own values, not rounded through the line
    if (u >= 1) return y1[c];
    const double in = u < kLengthBlend ? u * (1 - u / kLengthBlend) * (1 - u / kLengthBlend) : 0.0;
    const double v = 1 - u;
    const double out = v < kLengthBlend ? -v * (1 - v / kLengthBlend) * (1 - v / kLengthBlend) : 0.0;
    const double slope = (y1[c] - y0[c]) / width;
    return y0[c] + slope * width * u + width * ((m0[c] - slope) * in + (m1[c] - slope) * out);
  };
  const std::size_t m = std::size_t(edge_count);
  std::vector<Vec2> edge_vectors(m);
  for (std::size_t e = 0; e < m; ++e) {
    const double u = edge_u(e);
    const double angle = channel(e, u), length = std::exp(log_length(m + e, u));
    edge_vectors[e] = {length * std::cos(angle), length * std::sin(angle)};
  }
  const std::size_t parts = std::size_t(fit->part_count());
  std::vector<Vec2> centroids(parts);
  for (std::size_t p = 0; p < parts; ++p)
    centroids[p] = {channel(2 * m + p, part_u), channel(2 * m + parts + p, part_u)};
  return fit->positions(edge_vectors, centroids);
}

}  // namespace stickmorph
