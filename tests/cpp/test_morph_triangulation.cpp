#include "catch.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include "figures.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/frame_verification.h"
#include "stickmorph/morph.h"

using namespace stickmorph;
using namespace stickmorph::test;
using stickmorph_test::Contains;

namespace {

constexpr double kPi = 3.14159265358979323846;
const WeightKind kAllKinds[] = {WeightKind::MeanValue, WeightKind::Uniform, WeightKind::Floater};

// A triangulation in its own node numbering, with the nodes that become the
// figure (in figure order) and the enclosure (counter-clockwise) named; the
// rest become Steiner vertices.
struct RawTriangulation {
  std::vector<Vec2> source, target;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> figure;
  std::vector<int> enclosure;
  std::vector<std::array<int, 2>> figure_edges;  ///< in raw numbering
};

struct Assembled {
  FigureTriangulation tri;
  StickFigure source;  ///< the figure on the first n nodes, source positions
  StickFigure target;  ///< the same edges at the target positions
};

// Relabels into the FigureTriangulation order: figure, enclosure, Steiner.
Assembled assemble(const RawTriangulation& raw) {
  const int total = int(raw.source.size());
  std::vector<int> label(total, -1);
  int next = 0;
  for (int v : raw.figure) label[v] = next++;
  for (int v : raw.enclosure) label[v] = next++;
  for (int v = 0; v < total; ++v)
    if (label[v] < 0) label[v] = next++;
  Assembled a;
  a.tri.figure_vertices = int(raw.figure.size());
  a.tri.enclosure_vertices = int(raw.enclosure.size());
  a.tri.steiner_vertices = total - a.tri.figure_vertices - a.tri.enclosure_vertices;
  a.tri.source.resize(total);
  a.tri.target.resize(total);
  for (int v = 0; v < total; ++v) {
    a.tri.source[label[v]] = raw.source[v];
    a.tri.target[label[v]] = raw.target[v];
  }
  for (const auto& t : raw.triangles) a.tri.triangles.push_back({label[t[0]], label[t[1]], label[t[2]]});
  RawEdges edges;
  for (const auto& e : raw.figure_edges) edges.push_back({label[e[0]], label[e[1]]});
  const int n = a.tri.figure_vertices;
  a.source = figure({a.tri.source.begin(), a.tri.source.begin() + n}, edges);
  a.target = figure({a.tri.target.begin(), a.tri.target.begin() + n}, edges);
  return a;
}

// A g by g grid of unit spacing centred at the origin, one diagonal per
// cell, inside a square enclosure of four corners with a margin of 2; each
// side of the grid is fanned to the corner where that side starts
// (counter-clockwise). Nodes: grid (i, j) is i*g + j (x = j, y = i), corners
// g*g .. g*g+3. Source and target equal; the figure is the whole grid (a
// triangulation is a stick figure).
RawTriangulation grid_in_square(int g) {
  RawTriangulation raw;
  const double c = (g - 1) / 2.0, L = c + 2;
  auto id = [g](int i, int j) { return i * g + j; };
  for (int i = 0; i < g; ++i)
    for (int j = 0; j < g; ++j) raw.source.push_back({j - c, i - c});
  const int C = g * g;
  raw.source.insert(raw.source.end(), {{-L, -L}, {L, -L}, {L, L}, {-L, L}});
  for (int i = 0; i + 1 < g; ++i)
    for (int j = 0; j + 1 < g; ++j) {
      raw.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      raw.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    }
  // The grid's boundary, side by side, counter-clockwise.
  std::vector<std::vector<int>> sides(4);
  for (int t = 0; t < g; ++t) {
    sides[0].push_back(id(0, t));
    sides[1].push_back(id(t, g - 1));
    sides[2].push_back(id(g - 1, g - 1 - t));
    sides[3].push_back(id(g - 1 - t, 0));
  }
  for (int s = 0; s < 4; ++s) {
    const int A = C + s, B = C + (s + 1) % 4;
    for (int t = 0; t + 1 < g; ++t) raw.triangles.push_back({A, sides[s][t + 1], sides[s][t]});
    raw.triangles.push_back({A, B, sides[s][g - 1]});
  }
  raw.target = raw.source;
  raw.enclosure = {C, C + 1, C + 2, C + 3};
  for (int v = 0; v < C; ++v) raw.figure.push_back(v);
  for (int i = 0; i < g; ++i)
    for (int j = 0; j < g; ++j) {
      if (j + 1 < g) raw.figure_edges.push_back({id(i, j), id(i, j + 1)});
      if (i + 1 < g) raw.figure_edges.push_back({id(i, j), id(i + 1, j)});
      if (i + 1 < g && j + 1 < g) raw.figure_edges.push_back({id(i, j), id(i + 1, j + 1)});
    }
  return raw;
}

// Rotates every grid node about the origin by twist * (1 - r/R)^2, r its
// distance from the origin, R the grid's half width: the centre turns by
// `twist`, the grid's boundary stays. A smooth twist, so a fine enough grid
// stays a valid triangulation.
void twist_target(RawTriangulation& raw, int g, double twist) {
  const double R = (g - 1) / 2.0;
  for (int v = 0; v < g * g; ++v) {
    const Vec2 p = raw.source[v];
    const double r = std::hypot(p[0], p[1]);
    const double a = twist * std::pow(std::max(0.0, 1 - r / R), 2);
    raw.target[v] = {std::cos(a) * p[0] - std::sin(a) * p[1], std::sin(a) * p[0] + std::cos(a) * p[1]};
  }
}

bool all_positive(const std::vector<std::array<int, 3>>& triangles, const std::vector<Vec2>& p) {
  for (const auto& t : triangles)
    if (orientation(p[t[0]], p[t[1]], p[t[2]]) <= 0) return false;
  return true;
}

// Moves each non-enclosure node randomly, keeping every triangle positive.
void jitter(std::vector<Vec2>& p, const std::vector<std::array<int, 3>>& triangles, const std::set<int>& fixed,
            std::mt19937& rng, double step, int rounds) {
  std::vector<std::vector<int>> incident(p.size());
  for (int t = 0; t < int(triangles.size()); ++t)
    for (int v : triangles[t]) incident[v].push_back(t);
  std::uniform_real_distribution<double> d(-step, step);
  for (int round = 0; round < rounds; ++round)
    for (int v = 0; v < int(p.size()); ++v) {
      if (fixed.count(v)) continue;
      const Vec2 old = p[v];
      p[v] = {old[0] + d(rng), old[1] + d(rng)};
      for (int t : incident[v]) {
        const auto& tr = triangles[t];
        if (orientation(p[tr[0]], p[tr[1]], p[tr[2]]) <= 0) {
          p[v] = old;
          break;
        }
      }
    }
}

// Flips random edges whose quadrilateral has no enclosure corner and is
// strictly convex in `p`: varies degrees and connectivity.
void flip_edges(RawTriangulation& raw, const std::vector<Vec2>& p, const std::set<int>& fixed, std::mt19937& rng,
                int attempts) {
  for (int attempt = 0; attempt < attempts; ++attempt) {
    std::map<std::pair<int, int>, int> side;
    for (int t = 0; t < int(raw.triangles.size()); ++t)
      for (int c = 0; c < 3; ++c) side[{raw.triangles[t][c], raw.triangles[t][(c + 1) % 3]}] = t;
    const int t = std::uniform_int_distribution<int>(0, int(raw.triangles.size()) - 1)(rng);
    const int c = std::uniform_int_distribution<int>(0, 2)(rng);
    const auto tr = raw.triangles[t];
    const int a = tr[c], b = tr[(c + 1) % 3], x = tr[(c + 2) % 3];
    auto it = side.find({b, a});
    if (it == side.end()) continue;
    const auto& other = raw.triangles[it->second];
    int y = -1;
    for (int v : other)
      if (v != a && v != b) y = v;
    if (fixed.count(a) || fixed.count(b) || fixed.count(x) || fixed.count(y)) continue;
    if (orientation(p[x], p[a], p[y]) <= 0 || orientation(p[y], p[b], p[x]) <= 0) continue;
    const int u = it->second;
    raw.triangles[t] = {x, a, y};
    raw.triangles[u] = {y, b, x};
  }
}

// A random valid triangulation of n = g*g figure nodes in a square: a
// jittered, flipped grid; the target a further jitter of the source. The
// figure is every edge between two non-enclosure nodes.
RawTriangulation random_triangulation(std::mt19937& rng, int g) {
  RawTriangulation raw = grid_in_square(g);
  const std::set<int> fixed(raw.enclosure.begin(), raw.enclosure.end());
  jitter(raw.source, raw.triangles, fixed, rng, 0.45, 4);
  flip_edges(raw, raw.source, fixed, rng, 3 * g * g);
  raw.target = raw.source;
  jitter(raw.target, raw.triangles, fixed, rng, 0.8, 12);
  std::set<std::pair<int, int>> edges;
  for (const auto& t : raw.triangles)
    for (int c = 0; c < 3; ++c) {
      const int a = t[c], b = t[(c + 1) % 3];
      if (!fixed.count(a) && !fixed.count(b)) edges.insert({std::min(a, b), std::max(a, b)});
    }
  raw.figure_edges.clear();
  for (const auto& [a, b] : edges) raw.figure_edges.push_back({a, b});
  return raw;
}

Vec2 on_ring(double r, double angle) { return {r * std::cos(angle), r * std::sin(angle)}; }

double scale_of(const std::vector<Vec2>& p) {
  double s = 0;
  for (const Vec2& q : p) s = std::max({s, std::abs(q[0]), std::abs(q[1])});
  return s;
}

double max_distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::hypot(a[i][0] - b[i][0], a[i][1] - b[i][1]));
  return d;
}

// Independent exact check of every frame: all triangles counter-clockwise
// and the figure a stick figure compatible with the source.
void require_valid_frames(const Assembled& a, const MorphResult& result) {
  const int n = a.tri.figure_vertices;
  for (std::size_t f = 0; f < result.frames.size(); ++f) {
    const auto& frame = result.frames[f];
    INFO("frame " << f << " t = " << result.times[f]);
    REQUIRE(int(frame.size()) == a.tri.node_count());
    REQUIRE(all_positive(a.tri.triangles, frame));
    REQUIRE_NOTHROW(verify_frame(a.source, {frame.begin(), frame.begin() + n}, int(f), result.times[f]));
  }
}

void require_exact_endpoints(const Assembled& a, const MorphResult& result) {
  REQUIRE(result.frames.front() == a.tri.source);
  REQUIRE(result.frames.back() == a.tri.target);
  REQUIRE(result.times.front() == 0.0);
  REQUIRE(result.times.back() == 1.0);
}

// Figure 3 of the paper in spirit: a polar web (a centre node, `rings`
// concentric regular `spokes`-gons of radius 1, 2, ..., cells split by one
// diagonal) whose outermost ring is the fixed convex boundary. The target
// twists the inside: ring r turns by twist * (rings - r) / (rings - 1), so
// the innermost ring turns by `twist` and the boundary not at all. Ring 1
// turned by exactly half a turn is set to -p exactly. The figure is
// everything inside the boundary: centre, rings 1..rings-1 and their edges.
RawTriangulation twisted_web(int spokes, int rings, double twist) {
  RawTriangulation raw;
  auto id = [spokes](int r, int j) { return r == 0 ? 0 : 1 + (r - 1) * spokes + (j % spokes + spokes) % spokes; };
  raw.source.push_back({0, 0});
  raw.target.push_back({0, 0});
  for (int r = 1; r <= rings; ++r) {
    const double turn = twist * double(rings - r) / double(rings - 1);
    for (int j = 0; j < spokes; ++j) {
      const Vec2 p = on_ring(r, 2 * kPi * j / spokes);
      raw.source.push_back(p);
      if (turn == kPi) raw.target.push_back({-p[0], -p[1]});
      else raw.target.push_back({std::cos(turn) * p[0] - std::sin(turn) * p[1],
                                 std::sin(turn) * p[0] + std::cos(turn) * p[1]});
    }
  }
  for (int j = 0; j < spokes; ++j) raw.triangles.push_back({0, id(1, j), id(1, j + 1)});
  for (int r = 1; r < rings; ++r)
    for (int j = 0; j < spokes; ++j) {
      raw.triangles.push_back({id(r, j), id(r + 1, j), id(r + 1, j + 1)});
      raw.triangles.push_back({id(r, j), id(r + 1, j + 1), id(r, j + 1)});
    }
  for (int j = 0; j < spokes; ++j) raw.enclosure.push_back(id(rings, j));
  for (int v = 0; v < 1 + (rings - 1) * spokes; ++v) raw.figure.push_back(v);
  for (const auto& t : raw.triangles)
    for (int c = 0; c < 3; ++c) {
      const int a = t[c], b = t[(c + 1) % 3];
      if (a < b && b < 1 + (rings - 1) * spokes) raw.figure_edges.push_back({a, b});
    }
  return raw;
}

// The twisted web of the main tests: 16 spokes, 8 rings, the innermost ring
// turned half a turn.
Assembled twisted_web(double twist = kPi) { return assemble(twisted_web(16, 8, twist)); }

}  // namespace

TEST_CASE("weight kinds parse and print", "[morph_triangulation]") {
  for (WeightKind kind : kAllKinds) CHECK(parse_weight_kind(weight_kind_name(kind)) == kind);
  CHECK(parse_weight_kind("mvc") == WeightKind::MeanValue);
  CHECK_THROWS_AS(parse_weight_kind("cotan"), InvalidArgumentError);
  CHECK_THROWS_WITH(parse_weight_kind("MVC"), Contains("mvc") && Contains("uniform") && Contains("floater"));
}

TEST_CASE("the twisted web fixture is a valid pair whose linear morph collapses", "[morph_triangulation]") {
  const Assembled a = twisted_web();
  REQUIRE(all_positive(a.tri.triangles, a.tri.source));
  REQUIRE(all_positive(a.tri.triangles, a.tri.target));
  REQUIRE(is_frame_valid(a.source, a.target.vertices));
  // Straight lines carry the half-turned innermost ring through the centre:
  // at t = 1/2 it collapses onto it (the paper's Figure 8d failure).
  std::vector<int> invalid;
  linear_morph(a.source, a.target, 21, &invalid);
  CHECK_FALSE(invalid.empty());
  CHECK(std::find(invalid.begin(), invalid.end(), 10) != invalid.end());  // t = 0.5
  // The same straight lines applied to all nodes flip triangles too.
  std::vector<Vec2> halfway(a.tri.node_count());
  for (int v = 0; v < a.tri.node_count(); ++v)
    halfway[v] = {(a.tri.source[v][0] + a.tri.target[v][0]) / 2, (a.tri.source[v][1] + a.tri.target[v][1]) / 2};
  CHECK_FALSE(all_positive(a.tri.triangles, halfway));
}

TEST_CASE("Figure 3: a twisted web with a fixed convex boundary morphs validly", "[morph_triangulation]") {
  const Assembled a = twisted_web();
  for (WeightKind kind : kAllKinds) {
    INFO("weights " << weight_kind_name(kind));
    MorphOptions options;
    options.frames = 25;
    options.weights = kind;
    // Unverified by the morph, checked here frame by frame: the method
    // itself, not the refinement, keeps the frames valid.
    options.verify = false;
    const MorphResult plain = morph_triangulation(a.tri, a.source, options);
    REQUIRE(plain.frames.size() == 25);
    REQUIRE(plain.times.size() == 25);
    for (int f = 0; f < 25; ++f) CHECK(plain.times[f] == Approx(f / 24.0).epsilon(1e-15));
    require_exact_endpoints(a, plain);
    require_valid_frames(a, plain);
    // The enclosure never moves.
    for (const auto& frame : plain.frames)
      for (int i = 0; i < a.tri.enclosure_vertices; ++i)
        CHECK(frame[a.tri.figure_vertices + i] == a.tri.source[a.tri.figure_vertices + i]);

    options.verify = true;
    const MorphResult verified = morph_triangulation(a.tri, a.source, options);
    CHECK(verified.frames == plain.frames);
    CHECK(verified.stats.refined_frames == 0);
  }
}

TEST_CASE("the solve alone reproduces source and target", "[morph_triangulation]") {
  const Assembled twisted = twisted_web();
  std::mt19937 rng(7);
  const Assembled random = assemble(random_triangulation(rng, 7));
  for (const Assembled* a : {&twisted, &random})
    for (WeightKind kind : kAllKinds) {
      INFO("weights " << weight_kind_name(kind));
      const double scale = scale_of(a->tri.source);
      CHECK(max_distance(solve_morph_frame(a->tri, 0.0, kind), a->tri.source) <= 1e-9 * scale);
      CHECK(max_distance(solve_morph_frame(a->tri, 1.0, kind), a->tri.target) <= 1e-9 * scale);
      // A middle frame is a genuinely different drawing.
      CHECK(max_distance(solve_morph_frame(a->tri, 0.5, kind), a->tri.source) > 1e-3 * scale);
    }
}

TEST_CASE("frames move continuously", "[morph_triangulation]") {
  const Assembled a = twisted_web();
  MorphOptions options;
  options.frames = 41;
  const MorphResult r = morph_triangulation(a.tri, a.source, options);
  // No frame jumps: the endpoints substituted for the solve sit where the
  // solve would have put them, and every step is a small fraction of the
  // total displacement.
  const double total = max_distance(a.tri.source, a.tri.target);
  for (std::size_t f = 1; f < r.frames.size(); ++f)
    CHECK(max_distance(r.frames[f - 1], r.frames[f]) < 0.25 * total);
}

TEST_CASE("random valid triangulations morph validly with every weight kind", "[morph_triangulation]") {
  for (unsigned seed : {1u, 2u, 3u}) {
    std::mt19937 rng(seed);
    const Assembled a = assemble(random_triangulation(rng, 6));
    REQUIRE(all_positive(a.tri.triangles, a.tri.target));
    for (WeightKind kind : kAllKinds) {
      INFO("seed " << seed << " weights " << weight_kind_name(kind));
      MorphOptions options;
      options.frames = 12;
      options.weights = kind;
      options.verify = false;
      const MorphResult r = morph_triangulation(a.tri, a.source, options);
      require_exact_endpoints(a, r);
      require_valid_frames(a, r);
    }
  }
}

TEST_CASE("a polygon embedded with Steiner vertices morphs validly", "[morph_triangulation]") {
  // Figure 4 style: the grid's boundary ring is the figure (a polygon), the
  // grid's inside nodes are Steiner vertices.
  const int g = 9;
  RawTriangulation raw = grid_in_square(g);
  twist_target(raw, g, 0.75 * kPi);
  // The ring is fixed by the twist; move it by a shear that keeps it inside
  // the enclosure and the annulus fans positive.
  for (int v = 0; v < g * g; ++v) raw.target[v][0] += 0.15 * raw.target[v][1];
  raw.figure.clear();
  raw.figure_edges.clear();
  for (int t = 0; t < g; ++t) raw.figure.push_back(t);                          // bottom, left to right
  for (int t = 1; t < g; ++t) raw.figure.push_back(t * g + g - 1);              // right, upwards
  for (int t = g - 2; t >= 0; --t) raw.figure.push_back((g - 1) * g + t);       // top, leftwards
  for (int t = g - 2; t >= 1; --t) raw.figure.push_back(t * g);                 // left, downwards
  for (std::size_t i = 0; i < raw.figure.size(); ++i)
    raw.figure_edges.push_back({raw.figure[i], raw.figure[(i + 1) % raw.figure.size()]});
  const Assembled a = assemble(raw);
  REQUIRE(a.tri.figure_vertices == 4 * (g - 1));
  REQUIRE(a.tri.steiner_vertices == (g - 2) * (g - 2));
  REQUIRE(all_positive(a.tri.triangles, a.tri.target));
  for (WeightKind kind : kAllKinds) {
    INFO("weights " << weight_kind_name(kind));
    MorphOptions options;
    options.frames = 15;
    options.weights = kind;
    options.verify = false;
    const MorphResult r = morph_triangulation(a.tri, a.source, options);
    require_exact_endpoints(a, r);
    require_valid_frames(a, r);
  }
}

TEST_CASE("weights: positive convex combinations that reproduce the embedding", "[barycentric_weights]") {
  for (unsigned seed : {11u, 12u, 13u, 14u}) {
    std::mt19937 rng(seed);
    const Assembled a = assemble(random_triangulation(rng, 7));
    for (int side = 0; side < 2; ++side) {
      const std::vector<Vec2>& p = side ? a.tri.target : a.tri.source;
      for (WeightKind kind : kAllKinds) {
        INFO("seed " << seed << " side " << side << " weights " << weight_kind_name(kind));
        const auto W = barycentric_weights(a.tri, p, kind);
        REQUIRE(W.rows() == a.tri.node_count());
        const int n = a.tri.figure_vertices, k = a.tri.enclosure_vertices;
        for (int v = 0; v < a.tri.node_count(); ++v) {
          const bool enclosure = v >= n && v < n + k;
          double sum = 0, x = 0, y = 0;
          int entries = 0;
          for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(W, v); it; ++it) {
            CHECK(it.value() > 0);
            CHECK(it.col() != v);
            sum += it.value();
            x += it.value() * p[it.col()][0];
            y += it.value() * p[it.col()][1];
            ++entries;
          }
          if (enclosure) {
            CHECK(entries == 0);
            continue;
          }
          CHECK(entries >= 3);
          CHECK(sum == Approx(1.0).epsilon(1e-13));
          // Linear precision: sum_j w_ij p_j = p_i, hence every affine
          // function is reproduced.
          CHECK(std::abs(x - p[v][0]) <= 1e-12 * scale_of(p));
          CHECK(std::abs(y - p[v][1]) <= 1e-12 * scale_of(p));
        }
      }
    }
  }
}

TEST_CASE("weights: known values", "[barycentric_weights]") {
  // On the regular grid every inside node is the centroid of its six
  // neighbours: uniform weights are Tutte's 1/6 there.
  const Assembled a = assemble(grid_in_square(5));
  const auto U = barycentric_weights(a.tri, a.tri.source, WeightKind::Uniform);
  const int centre = 12;  // grid (2, 2), figure vertex 12
  int entries = 0;
  for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(U, centre); it; ++it, ++entries)
    CHECK(it.value() == Approx(1.0 / 6).epsilon(1e-14));
  CHECK(entries == 6);

  // Mean value coordinates of the centre of a regular hexagon are 1/6; of
  // an off-centre node they follow Floater's formula.
  FigureTriangulation hex;
  hex.figure_vertices = 1;
  hex.enclosure_vertices = 6;
  hex.source = {{0, 0}};
  const auto corners = regular(6, 2.0);
  hex.source.insert(hex.source.end(), corners.begin(), corners.end());
  for (int i = 0; i < 6; ++i) hex.triangles.push_back({0, 1 + i, 1 + (i + 1) % 6});
  hex.target = hex.source;
  const auto M = barycentric_weights(hex, hex.source, WeightKind::MeanValue);
  for (int i = 1; i <= 6; ++i) CHECK(M.coeff(0, i) == Approx(1.0 / 6).epsilon(1e-14));
  hex.source[0] = {0.5, 0.25};
  const auto M2 = barycentric_weights(hex, hex.source, WeightKind::MeanValue);
  std::vector<double> expected(6);
  double sum = 0;
  for (int i = 0; i < 6; ++i) {
    auto angle = [&](int a, int b) {
      const Vec2 u{corners[a][0] - 0.5, corners[a][1] - 0.25}, w{corners[b][0] - 0.5, corners[b][1] - 0.25};
      return std::acos((u[0] * w[0] + u[1] * w[1]) / (std::hypot(u[0], u[1]) * std::hypot(w[0], w[1])));
    };
    const double before = angle((i + 5) % 6, i), after = angle(i, (i + 1) % 6);
    expected[i] = (std::tan(before / 2) + std::tan(after / 2)) /
                  std::hypot(corners[i][0] - 0.5, corners[i][1] - 0.25);
    sum += expected[i];
  }
  for (int i = 0; i < 6; ++i) CHECK(M2.coeff(0, 1 + i) == Approx(expected[i] / sum).epsilon(1e-12));
  // Floater's weights at the hexagon's centre: each ray exits through the
  // opposite corner, so each neighbour's own triangle gives it 1/2 and its
  // opposite gets the other 1/2: 1/6 each.
  hex.source[0] = {0, 0};
  const auto F = barycentric_weights(hex, hex.source, WeightKind::Floater);
  for (int i = 1; i <= 6; ++i) CHECK(F.coeff(0, i) == Approx(1.0 / 6).epsilon(1e-12));
}

TEST_CASE("a figure edge off the triangulation is refused before any frame", "[morph_triangulation]") {
  // Square enclosure, figure path 0-1-2. Node 2 drops onto the segment 0-1
  // in the target; the triangulation stays valid because 0-1 is not one of
  // its edges. The frame certificate (frame_certificate.h) needs every
  // figure edge to be a triangulation edge, so the setup refuses it.
  FigureTriangulation tri;
  tri.figure_vertices = 3;
  tri.enclosure_vertices = 4;
  tri.source = {{-2, 0}, {2, 0}, {0, 1}, {-10, -10}, {10, -10}, {10, 10}, {-10, 10}};
  tri.target = tri.source;
  tri.target[2] = {0, 0};
  tri.triangles = {{3, 1, 2}, {3, 2, 0}, {3, 4, 1}, {4, 5, 1}, {5, 2, 1}, {5, 6, 2}, {6, 0, 2}, {6, 3, 0}};
  const StickFigure source = figure({tri.source.begin(), tri.source.begin() + 3}, {{0, 1}, {1, 2}});
  MorphOptions options;
  options.frames = 5;
  CHECK_THROWS_AS(morph_triangulation(tri, source, options), InvalidArgumentError);
  CHECK_THROWS_WITH(morph_triangulation(tri, source, options),
                    Contains("figure edge 0 (0-1) is not an edge of the triangulation"));
  options.frame_check = FrameCheck::Full;
  CHECK_THROWS_AS(morph_triangulation(tri, source, options), InvalidArgumentError);
  options.verify = false;
  CHECK_THROWS_AS(morph_triangulation(tri, source, options), InvalidArgumentError);
  // What the certificate could not have seen: the last frame's figure
  // overlaps itself, though every triangle is positive.
  CHECK_FALSE(is_frame_valid(source, {tri.target.begin(), tri.target.begin() + 3}));
  // With 0-1 an edge of the figure's own triangulation it morphs.
  tri.target[2] = {0.5, 0.5};
  const StickFigure path = figure({tri.source.begin(), tri.source.begin() + 3}, {{1, 2}, {2, 0}});
  options.verify = true;
  CHECK_NOTHROW(morph_triangulation(tri, path, options));
}

TEST_CASE("malformed morph inputs are refused with a reason", "[morph_triangulation]") {
  const Assembled a = assemble(grid_in_square(4));
  MorphOptions options;
  options.frames = 1;
  CHECK_THROWS_AS(morph_triangulation(a.tri, a.source, options), InvalidArgumentError);
  options.frames = kMaxMorphFrames + 1;
  CHECK_THROWS_AS(morph_triangulation(a.tri, a.source, options), InvalidArgumentError);
  options.frames = 3;
  CHECK_NOTHROW(morph_triangulation(a.tri, a.source, options));

  SECTION("a moving enclosure") {
    FigureTriangulation t = a.tri;
    t.target[16][0] -= 1;
    CHECK_THROWS_WITH(morph_triangulation(t, a.source, options), Contains("enclosure vertex 0") && Contains("moves"));
  }
  SECTION("a clockwise triangle in the target") {
    FigureTriangulation t = a.tri;
    t.target[5] = {3, 3};  // far outside its neighbourhood
    CHECK_THROWS_WITH(morph_triangulation(t, a.source, options),
                      Contains("not counter-clockwise in the target"));
  }
  SECTION("a missing triangle leaves a hole") {
    FigureTriangulation t = a.tri;
    t.triangles.erase(t.triangles.begin());
    CHECK_THROWS_WITH(morph_triangulation(t, a.source, options), Contains("borders only"));
  }
  SECTION("a duplicated triangle overlaps") {
    FigureTriangulation t = a.tri;
    t.triangles.push_back(t.triangles.front());
    CHECK_THROWS_WITH(morph_triangulation(t, a.source, options), Contains("overlap"));
  }
  SECTION("a non-convex enclosure") {
    FigureTriangulation t = a.tri;
    t.source[17] = t.target[17] = {0.5, -2.5};  // pulls a corner inward
    CHECK_THROWS_AS(morph_triangulation(t, a.source, options), InvalidArgumentError);
  }
  SECTION("a figure that does not sit on the triangulation") {
    StickFigure moved = a.source;
    moved.vertices[0][0] += 0.25;
    CHECK_THROWS_WITH(morph_triangulation(a.tri, moved, options), Contains("vertex 0"));
  }
  SECTION("wrong position counts") {
    FigureTriangulation t = a.tri;
    t.target.pop_back();
    CHECK_THROWS_AS(morph_triangulation(t, a.source, options), InvalidArgumentError);
  }
}
