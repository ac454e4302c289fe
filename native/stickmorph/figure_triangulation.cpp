#include "stickmorph/figure_triangulation.h"
#include "stickmorph/working_scale.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "stickmorph/argument_limits.h"
#include "stickmorph/cancellation.h"
#include "stickmorph/compatibility.h"
#include "stickmorph/decomposition.h"
#include "stickmorph/exact_predicates.h"
#include "stickmorph/internal/annulus_cut.h"
#include "stickmorph/internal/compatible_improvement.h"
#include "stickmorph/internal/geometry.h"
#include "stickmorph/internal/part_bridges.h"
#include "stickmorph/internal/stopwatch.h"
#include "stickmorph/internal/triangle_adjacency.h"
#include "stickmorph/verification.h"

namespace stickmorph {
namespace {

using internal::kPi;

// ---------------------------------------------------------------------------
// The enclosure (Algorithm 3, step 3): one regular k-gon for both figures.

std::vector<Vec2> enclosure_polygon(const StickFigure& source, const StickFigure& target, int sides,
                                    const std::vector<Vec2>& enclosed_points) {
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  const std::vector<Vec2>* point_sets[] = {&source.vertices, &target.vertices, &enclosed_points};
  for (const std::vector<Vec2>* points : point_sets)
    for (const Vec2& p : *points)
      if (std::isfinite(p[0]) && std::isfinite(p[1]))
        for (int c = 0; c < 2; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
  const Vec2 center{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
  double reach = 0;
  for (const std::vector<Vec2>* points : point_sets)
    for (const Vec2& p : *points)
      if (std::isfinite(p[0]) && std::isfinite(p[1]))
        reach = std::max(reach, std::hypot(p[0] - center[0], p[1] - center[1]));
  // A margin of half the figures' reach keeps the annulus roomy; a lone
  // point still gets a unit-sized enclosure, scaled to its coordinates.
  if (reach == 0) reach = std::max(1.0, 1e-6 * std::max(std::abs(center[0]), std::abs(center[1])));
  const double inscribed = 1.5 * reach;
  const double circumradius = inscribed / std::cos(kPi / sides);
  std::vector<Vec2> polygon;
  for (int j = 0; j < sides; ++j) {
    const double a = 2 * kPi * j / sides - kPi / 2 + kPi / sides;
    polygon.push_back({center[0] + circumradius * std::cos(a), center[1] + circumradius * std::sin(a)});
  }
  return polygon;
}

std::string face_label(int face) { return "face " + std::to_string(face); }


using internal::Clock;
using internal::ms_since;

}  // namespace

namespace {

// Algorithm 3, steps 1-3, at the scale the figures are given in.
FigureTriangulation triangulate_at_scale(const CompatiblePair& pair, const FigureTriangulationOptions& options,
                                         FigureTriangulationStats* stats) {
  // Algorithm 3, step 1 is the pair's: decomposed and checked once.
  const StickFigure& source = pair.source();
  const StickFigure& target = pair.target();
  const Decomposition& source_dec = pair.source_decomposition();
  const Decomposition& target_dec = pair.target_decomposition();
  FigureTriangulationStats measured;
  auto stage_start = Clock::now();

  // Issue 14: a figure of several parts is bridged into one (part_bridges.h)
  // and triangulated as such; the bridges' bends then become Steiner
  // vertices, so that the result's first n nodes are the figure's.
  if (source_dec.exterior_of_part.size() > 1) {
    stage_start = Clock::now();
    const internal::BridgedFigures bridged = internal::bridge_parts(pair);
    const double bridge_ms = ms_since(stage_start);
    FigureTriangulation joined = triangulate_at_scale(*bridged.pair, options, stats);
    const int n = int(source.vertices.size()), bends = bridged.bends, k = joined.enclosure_vertices;
    // Node order of the bridged triangulation: n figure vertices, the bends,
    // the enclosure, the Steiner vertices. Wanted: the figure, the
    // enclosure, the bends, the Steiner vertices.
    auto renumbered = [&](int v) {
      if (v < n) return v;
      if (v < n + bends) return v + k;
      if (v < n + bends + k) return v - bends;
      return v;
    };
    FigureTriangulation result;
    result.figure_vertices = n;
    result.enclosure_vertices = k;
    result.steiner_vertices = joined.steiner_vertices + bends;
    result.source.resize(joined.source.size());
    result.target.resize(joined.target.size());
    for (std::size_t v = 0; v < joined.source.size(); ++v) {
      result.source[std::size_t(renumbered(int(v)))] = joined.source[v];
      result.target[std::size_t(renumbered(int(v)))] = joined.target[v];
    }
    for (const auto& t : joined.triangles)
      result.triangles.push_back({renumbered(t[0]), renumbered(t[1]), renumbered(t[2])});
    verify_figure_triangulation(result, source);
    if (stats) {
      stats->decompose_ms += measured.decompose_ms;
      stats->parts = int(source_dec.exterior_of_part.size());
      stats->bridges = bridged.bridges;
      stats->bridge_bends = bends;
      stats->bridge_ms = bridge_ms;
    }
    return result;
  }
  stage_start = Clock::now();

  const int n = int(source.vertices.size());
  const int k = options.enclosure_sides;
  const std::vector<Vec2> enclosure = enclosure_polygon(source, target, k, options.enclosed_points);
  const internal::AnnulusCut cut =
      internal::choose_annulus_cut(source, source_dec, target, target_dec, enclosure);
  const int bends = int(cut.source_bends.size());
  measured.cut_ms = ms_since(stage_start);

  FigureTriangulation result;
  result.figure_vertices = n;
  result.enclosure_vertices = k;
  result.source = source.vertices;
  result.target = target.vertices;
  for (const Vec2& q : enclosure) result.source.push_back(q), result.target.push_back(q);
  for (int b = 0; b < bends; ++b) {
    result.source.push_back(cut.source_bends[b]);
    result.target.push_back(cut.target_bends[b]);
  }

  CompatibleTriangulationOptions face_options;
  face_options.method = options.method;
  face_options.smoothing_rounds = options.smoothing_rounds;

  // Adds one face's compatible triangulation: corners are global nodes,
  // Steiner vertices get new nodes.
  auto glue = [&](const PolygonPair& pair, const std::string& label) {
    face_options.label = label;
    CompatibleTriangulation tri;
    try {
      tri = compatible_triangulation(pair, face_options);
    } catch (const InvalidFigureError& error) {
      // The face polygons are the engine's own, built from valid figures;
      // one that fails the polygon check (a spike folded back to within
      // rounding of an edge, found by fuzz_correspond_pair) is a face this
      // triangulation cannot do, refused as promised, so that callers with
      // another triangulation to try (the rigid method) can.
      throw VerificationError(error.what());
    }
    const int c = tri.corner_count;
    const int offset = int(result.source.size());
    for (int s = 0; s < tri.steiner_count(); ++s) {
      result.source.push_back(tri.source_steiner[s]);
      result.target.push_back(tri.target_steiner[s]);
    }
    for (const auto& t : tri.triangles) {
      std::array<int, 3> global;
      for (int j = 0; j < 3; ++j) global[j] = t[j] < c ? pair.corners[t[j]] : offset + (t[j] - c);
      result.triangles.push_back(global);
    }
  };

  // Step 2: every interior face. Algorithm 1 lists each face's corners with
  // the face on the left, counter-clockwise, as section 4 expects.
  stage_start = Clock::now();
  int face = 0, interior = 0;
  long interior_total = 0;
  for (const CyclicSequence& seq : source_dec.sequences) interior_total += seq.exterior ? 0 : 1;
  for (const CyclicSequence& seq : source_dec.sequences) {
    ++face;
    if (seq.exterior) continue;
    // A figure of many faces (a triangulation of 10^5 vertices): counted
    // and cancellable face by face. (A large face counts its own corners
    // instead, piecewise_triangulation.cpp.)
    report_progress(interior, interior_total);
    ++interior;
    PolygonPair pair;
    pair.corners = seq.vertices;
    pair.source_positions = source.vertices;
    pair.target_positions = target.vertices;
    glue(pair, face_label(face - 1));
  }
  const int interior_steiner = int(result.source.size()) - n - k - bends;
  measured.interior_faces_ms = ms_since(stage_start);
  stage_start = Clock::now();

  // Step 3: the exterior, cut open into one weakly simple polygon:
  // the exterior walk from the cut corner round to itself, out along the
  // cut, counter-clockwise round the enclosure, and back along the cut.
  {
    const CyclicSequence& ext = source_dec.sequences[source_dec.exterior];
    const int m = int(ext.vertices.size());
    const int c = cut.corner.index;
    PolygonPair pair;
    auto bend_node = [&](int b) { return n + k + b; };
    pair.corners.push_back(ext.vertices[c]);
    for (int b = 0; b < bends; ++b) pair.corners.push_back(bend_node(b));
    for (int j = 0; j <= k; ++j) pair.corners.push_back(n + (cut.enclosure_index + j) % k);
    for (int b = bends - 1; b >= 0; --b) pair.corners.push_back(bend_node(b));
    if (!ext.darts.empty()) {
      pair.corners.push_back(ext.vertices[c]);
      for (int i = 1; i < m; ++i) pair.corners.push_back(ext.vertices[(c + i) % m]);
    }
    pair.source_positions = result.source;
    pair.target_positions = result.target;
    glue(pair, "exterior face (" + face_label(source_dec.exterior) + ", cut at vertex " +
                   std::to_string(ext.vertices[c]) + ")");
  }

  measured.exterior_face_ms = ms_since(stage_start);

  // Steiner vertices follow the figure and the enclosure.
  result.steiner_vertices = int(result.source.size()) - n - k;
  poll_cancellation();
  if (options.improvement_rounds > 0) {
    // Issue 30: flips legal in both embeddings and smoothing, across the
    // faces' seams too; the figure's edges are never flipped, the
    // enclosure and the figure's vertices never move.
    stage_start = Clock::now();
    std::vector<std::pair<int, int>> figure_edges;
    for (const Edge& e : source.edges) figure_edges.emplace_back(e[0], e[1]);
    internal::CompatibleImprovementStats improvement;
    internal::CompatibleImprovementOptions improvement_options;
    improvement_options.rounds = options.improvement_rounds;
    // Refinement's budget: no more than refinement_share of the figure's
    // vertex count in all, the faces' own Steiner vertices included, and
    // as much again for triangles still below 2 degrees after a round.
    const int steiner_now = int(result.source.size()) - n - k;
    improvement_options.steiner_budget = std::max(0, int(options.refinement_share * n) - steiner_now);
    improvement_options.rescue_budget = int(options.refinement_share * n);
    internal::improve_compatible_triangulation(result.source, result.target, result.triangles, figure_edges, n + k,
                                               improvement_options, &improvement);
    result.steiner_vertices = int(result.source.size()) - n - k;
    measured.improve_ms = ms_since(stage_start);
    measured.flips = improvement.flips;
    measured.refinement_steiner = improvement.added;
  }
  stage_start = Clock::now();
  verify_figure_triangulation(result, source);
  measured.verify_ms = ms_since(stage_start);
  if (stats) {
    *stats = measured;
    stats->interior_faces = interior;
    stats->cut_bends = bends;
    stats->interior_steiner = interior_steiner;
    double least = kPi;
    for (const auto& t : result.triangles)
      for (const std::vector<Vec2>* pos : {&result.source, &result.target})
        for (int j = 0; j < 3; ++j) {
          const Vec2& a = (*pos)[t[j]];
          const Vec2& b = (*pos)[t[(j + 1) % 3]];
          const Vec2& c = (*pos)[t[(j + 2) % 3]];
          const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
          least = std::min(least, internal::angle_between(ux, uy, vx, vy));
        }
    stats->min_angle = least;
  }
  return result;
}

}  // namespace

FigureTriangulation triangulate_figures(const CompatiblePair& pair, const FigureTriangulationOptions& options,
                                        FigureTriangulationStats* stats) {
  // The interfaces check it first (morph_stick_figures, the CLI, the
  // module); this is the same check for direct callers, in the same words.
  check_enclosure_sides(options.enclosure_sides, OptionSpelling::Keyword);
  // In the working scale (working_scale.h): a pair beyond the numeric
  // stages' comfortable magnitudes is triangulated multiplied by an exact
  // power of two (the same plane graphs), and the nodes multiplied back.
  const int exponent = working_scale_exponent(pair.source(), pair.target());
  if (exponent == 0) return triangulate_at_scale(pair, options, stats);
  FigureTriangulationOptions scaled_options = options;
  // Only to be enclosed: rounding of these near 0 is harmless.
  scale_points(scaled_options.enclosed_points, exponent);
  FigureTriangulation triangulation = triangulate_at_scale(scaled_pair(pair, exponent), scaled_options, stats);
  scale_triangulation_back(triangulation, pair.source(), exponent);
  return triangulation;
}

FigureTriangulation triangulate_figures(const StickFigure& source, const StickFigure& target,
                                        const FigureTriangulationOptions& options, FigureTriangulationStats* stats) {
  check_enclosure_sides(options.enclosure_sides, OptionSpelling::Keyword);
  const auto start = Clock::now();
  const CompatiblePair pair = CompatiblePair::check(source, target);
  const double decompose_ms = ms_since(start);
  FigureTriangulation triangulation = triangulate_figures(pair, options, stats);
  if (stats) stats->decompose_ms = decompose_ms;
  return triangulation;
}

void verify_figure_triangulation(const FigureTriangulation& tri, const StickFigure& source) {
  const int n = tri.figure_vertices, k = tri.enclosure_vertices;
  const int total = tri.node_count();
  if (int(tri.source.size()) != total || int(tri.target.size()) != total)
    throw VerificationError("triangulation: it lists " + std::to_string(tri.source.size()) + " source and " +
                            std::to_string(tri.target.size()) + " target positions for " + std::to_string(total) +
                            " nodes");
  // As a compatible triangulation of the enclosure: its k vertices are the
  // polygon's corners, every other node is interior (a full turn around it).
  PolygonPair pair;
  for (int j = 0; j < k; ++j) pair.corners.push_back(n + j);
  pair.source_positions = tri.source;
  pair.target_positions = tri.target;
  std::vector<int> renumber(total, -1);
  CompatibleTriangulation as_polygon;
  as_polygon.corner_count = k;
  for (int j = 0; j < k; ++j) renumber[n + j] = j;
  for (int v = 0; v < total; ++v)
    if (renumber[v] < 0) {
      renumber[v] = k + int(as_polygon.source_steiner.size());
      as_polygon.source_steiner.push_back(tri.source[v]);
      as_polygon.target_steiner.push_back(tri.target[v]);
    }
  for (const auto& t : tri.triangles) {
    for (int v : t)
      if (v < 0 || v >= total) throw VerificationError("triangulation: a triangle names node " + std::to_string(v));
    as_polygon.triangles.push_back({renumber[t[0]], renumber[t[1]], renumber[t[2]]});
  }
  verify_compatible_triangulation(pair, as_polygon, "triangulation");
  // The figure is embedded: each of its edges is a triangulation edge.
  const internal::TriangleAdjacency adjacency(total, tri.triangles);
  for (std::size_t e = 0; e < source.edges.size(); ++e) {
    const Edge& edge = source.edges[e];
    if (adjacency.left_of(edge[0], edge[1]) < 0 && adjacency.left_of(edge[1], edge[0]) < 0)
      throw VerificationError("triangulation: figure edge " + describe_edge(source, int(e)) +
                              " is not an edge of the triangulation");
  }
}

}  // namespace stickmorph
