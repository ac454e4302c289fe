#include "stickmorph/io/result_files.h"

namespace stickmorph {
namespace {

void write_point(JsonWriter& out, const Vec2& p) {
  out.begin_array();
  out.value(p[0]);
  out.value(p[1]);
  out.end_array();
}

void write_points(JsonWriter& out, const std::vector<Vec2>& points) {
  out.begin_array();
  for (const Vec2& p : points) write_point(out, p);
  out.end_array();
}

void write_places(JsonWriter& out, const std::vector<MatchedPlace>& places, int MatchedPlace::*field) {
  out.begin_array();
  for (const MatchedPlace& place : places) out.value(place.*field);
  out.end_array();
}

void write_fractions(JsonWriter& out, const std::vector<MatchedPlace>& places) {
  out.begin_array();
  for (const MatchedPlace& place : places) out.value(place.fraction);
  out.end_array();
}

// "edges": [[i, j], ...].
void write_edges(JsonWriter& out, const std::vector<Edge>& edges) {
  out.key("edges");
  out.begin_array();
  for (const Edge& e : edges) {
    out.begin_array();
    out.value(e[0]);
    out.value(e[1]);
    out.end_array();
  }
  out.end_array();
}

void write_figure_object(JsonWriter& out, const StickFigure& figure) {
  out.begin_object();
  out.key("name");
  out.value(figure.name);
  out.key("vertices");
  write_points(out, figure.vertices);
  write_edges(out, figure.edges);
  out.end_object();
}

int dummy_count(const std::vector<MatchedPlace>& places) {
  int count = 0;
  for (const MatchedPlace& place : places) count += place.vertex < 0;
  return count;
}

// How the matching was found (stats.correspondence).
void write_matching_stats(JsonWriter& out, const FigureCorrespondence& c) {
  out.begin_object();
  out.key("matched_vertices");
  out.value(int(c.source.vertices.size()));
  out.key("source_dummies");
  out.value(dummy_count(c.source_places));
  out.key("target_dummies");
  out.value(dummy_count(c.target_places));
  out.key("skeleton_nodes");
  out.value(c.skeleton_nodes);
  out.key("skeleton_chains");
  out.value(c.skeleton_chains);
  out.key("candidates");
  out.value(c.candidates);
  out.key("residual");
  out.value(c.residual);
  out.key("rotation_degrees");
  out.value(c.rotation_degrees);
  out.end_object();
}

// The motion's part of a morph file: the figure's edges, the times and the
// first n positions of every frame (frames may hold all triangulation
// nodes; the enclosure and Steiner nodes are in the triangulation, and
// moving them is the morph's business).
void write_motion(JsonWriter& out, const StickFigure& figure, const std::vector<double>& times,
                  const std::vector<std::vector<Vec2>>& frames) {
  const std::size_t n = figure.vertices.size();
  write_edges(out, figure.edges);
  out.key("times");
  out.begin_array();
  for (double t : times) out.value(t);
  out.end_array();
  out.key("frames");
  out.begin_array();
  for (const auto& frame : frames) {
    out.begin_array();
    for (std::size_t v = 0; v < n; ++v) write_point(out, frame[v]);
    out.end_array();
  }
  out.end_array();
}

// How the rigid method made its frames (GuideFit).
void write_guide_frames(JsonWriter& out, int exact, int blended, int barycentric) {
  out.key("guide_frames");
  out.begin_object();
  out.key("exact");
  out.value(exact);
  out.key("blended");
  out.value(blended);
  out.key("barycentric");
  out.value(barycentric);
  out.end_object();
}

}  // namespace

void write_correspondence(JsonWriter& out, const FigureCorrespondence& c) {
  out.begin_object();
  out.key("source");
  write_places(out, c.source_places, &MatchedPlace::vertex);
  out.key("target");
  write_places(out, c.target_places, &MatchedPlace::vertex);
  out.key("source_edge");
  write_places(out, c.source_places, &MatchedPlace::edge);
  out.key("source_fraction");
  write_fractions(out, c.source_places);
  out.key("target_edge");
  write_places(out, c.target_places, &MatchedPlace::edge);
  out.key("target_fraction");
  write_fractions(out, c.target_places);
  out.end_object();
}

std::string correspondence_file_json(const FigureCorrespondence& c) {
  JsonWriter out(true);
  out.begin_object();
  out.key("source");
  write_figure_object(out, c.source);
  out.key("target");
  write_figure_object(out, c.target);
  out.key("correspondence");
  write_correspondence(out, c);
  out.key("stats");
  out.begin_object();
  out.key("correspondence");
  write_matching_stats(out, c);
  out.key("milliseconds");
  out.begin_object();
  out.key("correspond");
  out.value(c.milliseconds);
  out.end_object();
  out.end_object();
  out.end_object();
  return out.finish();
}

void write_triangulation(JsonWriter& out, const FigureTriangulation& tri) {
  out.begin_object();
  out.key("figure_vertices");
  out.value(tri.figure_vertices);
  out.key("enclosure_vertices");
  out.value(tri.enclosure_vertices);
  out.key("steiner_vertices");
  out.value(tri.steiner_vertices);
  out.key("source");
  write_points(out, tri.source);
  out.key("target");
  write_points(out, tri.target);
  out.key("triangles");
  out.begin_array();
  for (const auto& t : tri.triangles) {
    out.begin_array();
    for (int v : t) out.value(v);
    out.end_array();
  }
  out.end_array();
  out.end_object();
}

std::string triangulation_file_json(const FigureTriangulation& triangulation) {
  JsonWriter out(true);
  write_triangulation(out, triangulation);
  return out.finish();
}

std::string morph_file_json(const StickFigure& source, const std::vector<double>& times,
                            const std::vector<std::vector<Vec2>>& frames, const MorphProvenance& how) {
  const FigureTriangulation* triangulation = how.triangulation;
  JsonWriter out(true);
  out.begin_object();
  write_motion(out, source, times, frames);
  if (how.correspondence) {
    out.key("correspondence");
    write_correspondence(out, *how.correspondence);
  }
  out.key("triangulation");
  if (triangulation) write_triangulation(out, *triangulation);
  else out.null();
  out.key("stats");
  out.begin_object();
  out.key("steiner_vertices");
  out.value(triangulation ? triangulation->steiner_vertices : 0);
  out.key("triangles");
  out.value(triangulation ? int(triangulation->triangles.size()) : 0);
  out.key("parts");
  out.value(how.parts);
  out.key("bridge_vertices");
  out.value(how.bridge_vertices);
  out.key("milliseconds");
  out.begin_object();
  out.key("triangulate");
  out.value(how.triangulate_ms);
  out.key("morph");
  out.value(how.morph_ms);
  if (how.stats) {
    out.key("factorize");
    out.value(how.stats->factorize_ms);
    out.key("solve");
    out.value(how.stats->solve_ms);
    out.key("verify");
    out.value(how.stats->verify_ms);
  }
  if (how.correspondence) {
    out.key("correspond");
    out.value(how.correspond_ms);
  }
  out.end_object();
  out.key("method");
  out.value(how.method);
  if (triangulation) {
    out.key("steiner_method");
    out.value(steiner_method_name(how.triangulation_options.method));
    out.key("enclosure_sides");
    out.value(how.triangulation_options.enclosure_sides);
    out.key("weights");
    out.value(weight_kind_name(how.options.weights));
    out.key("verified");
    out.value(how.options.verify);
  }
  if (how.stats) {
    out.key("refined_frames");
    out.value(how.stats->refined_frames);
    out.key("factorizations");
    out.value(how.stats->factorizations);
  }
  if (how.rigid) {
    const RigidMotionReport& rigid = *how.rigid;
    out.key("rigid");
    out.begin_object();
    out.key("rotation");
    out.value(rigid.rotation);
    out.key("turns");
    out.value(rigid.turns);
    out.key("easing");
    out.value(rigid.easing);
    out.key("similarity_factored");
    out.value(rigid.similarity_factored);
    out.key("similarity");
    out.begin_object();
    out.key("angle_degrees");
    out.value(rigid.similarity.angle * 180.0 / 3.14159265358979323846);
    out.key("scale");
    out.value(rigid.similarity.scale);
    out.key("source_center");
    write_point(out, rigid.similarity.source_center);
    out.key("target_center");
    write_point(out, rigid.similarity.target_center);
    out.end_object();
    write_guide_frames(out, rigid.exact_frames, rigid.blended_frames, rigid.barycentric_frames);
    out.key("refinement_steiner_vertices");
    out.value(rigid.refinement_steiner);
    out.end_object();
  }
  if (how.correspondence) {
    out.key("correspondence");
    write_matching_stats(out, *how.correspondence);
  }
  if (how.invalid_frames) {
    out.key("invalid_frames");
    out.begin_array();
    for (int f : *how.invalid_frames) out.value(f);
    out.end_array();
  }
  out.end_object();
  out.end_object();
  return out.finish();
}

std::string key_pose_file_json(const StickFigure& first_key, const KeyPoseMorphResult& result, bool verified) {
  JsonWriter out(true);
  out.begin_object();
  // Matched keys: the frames are the common figure's, on its edges.
  write_motion(out, result.correspondence ? result.correspondence->keys[0] : first_key, result.times, result.frames);
  out.key("keys");
  out.begin_array();
  for (std::size_t k = 0; k < result.key_frames.size(); ++k) {
    out.begin_object();
    out.key("frame");
    out.value(result.key_frames[k]);
    if (result.correspondence) {
      // Where each matched vertex is on this key's own drawing, as the
      // pair's "correspondence" says it for the source and the target.
      const std::vector<MatchedPlace>& places = result.correspondence->places[k];
      out.key("vertex");
      write_places(out, places, &MatchedPlace::vertex);
      out.key("edge");
      write_places(out, places, &MatchedPlace::edge);
      out.key("fraction");
      write_fractions(out, places);
    }
    out.end_object();
  }
  out.end_array();
  out.key("triangulations");
  out.begin_array();
  for (const KeyPoseSegment& segment : result.segments) write_triangulation(out, segment.triangulation);
  out.end_array();
  int steiner = 0, triangles = 0;
  double triangulate_ms = 0, morph_ms = 0;
  for (const KeyPoseSegment& segment : result.segments) {
    steiner += segment.triangulation.steiner_vertices;
    triangles += int(segment.triangulation.triangles.size());
    triangulate_ms += segment.stats.triangulate_ms;
    morph_ms += segment.stats.morph_ms;
  }
  out.key("stats");
  out.begin_object();
  out.key("steiner_vertices");
  out.value(steiner);
  out.key("triangles");
  out.value(triangles);
  out.key("milliseconds");
  out.begin_object();
  out.key("triangulate");
  out.value(triangulate_ms);
  out.key("morph");
  out.value(morph_ms);
  out.end_object();
  out.key("method");
  out.value("rigid");
  out.key("verified");
  out.value(verified);
  if (result.correspondence) {
    out.key("correspondence");
    out.begin_object();
    out.key("matched_vertices");
    out.value(int(result.correspondence->keys[0].vertices.size()));
    out.key("milliseconds");
    out.value(result.correspondence->milliseconds);
    out.key("pairs");
    out.begin_array();
    for (const FigureCorrespondence& match : result.correspondence->matches) write_matching_stats(out, match);
    out.end_array();
    out.end_object();
  }
  out.key("segments");
  out.begin_array();
  for (const KeyPoseSegment& segment : result.segments) {
    const MorphStickFiguresStats& stats = segment.stats;
    out.begin_object();
    out.key("keys");
    out.begin_array();
    out.value(segment.from_key + 1);
    out.value(segment.to_key + 1);
    out.end_array();
    out.key("frames");
    out.begin_array();
    out.value(segment.first_frame);
    out.value(segment.last_frame);
    out.end_array();
    out.key("steiner_vertices");
    out.value(segment.triangulation.steiner_vertices);
    out.key("triangles");
    out.value(int(segment.triangulation.triangles.size()));
    out.key("milliseconds");
    out.begin_object();
    out.key("triangulate");
    out.value(stats.triangulate_ms);
    out.key("morph");
    out.value(stats.morph_ms);
    out.end_object();
    out.key("similarity_factored");
    out.value(stats.similarity_factored);
    write_guide_frames(out, stats.guide_exact_frames, stats.guide_blended_frames, stats.guide_barycentric_frames);
    out.key("refined_frames");
    out.value(stats.refined_frames);
    out.end_object();
  }
  out.end_array();
  out.end_object();
  out.end_object();
  return out.finish();
}

}  // namespace stickmorph
