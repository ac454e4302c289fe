// SVG pictures of results, in the style of the paper's figures.
//
// Surazhsky & Gotsman 2001: Figures 5-7 show compatible triangulations side
// by side with Steiner vertices in black; Figure 8 shows a morph as a row of
// snapshots. These writers produce the same kinds of pictures.
#pragma once

#include <string>
#include <vector>

#include "stickmorph/figure_triangulation.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// Source and target embeddings of `triangulation` side by side: triangles in
/// grey, the figure's edges in colour, the enclosure, Steiner vertices as
/// black dots, figure vertices coloured by index so that correspondence can
/// be followed (Figures 5-7).
std::string triangulation_svg(const FigureTriangulation& triangulation, const StickFigure& source,
                              const std::string& title);

/// A filmstrip of about `snapshots` frames (Figure 8): frames[f] holds at
/// least the figure's vertices (#V by 2). The first snapshot is drawn in the
/// source colour, the last in the target colour, the others in between.
/// If `triangulation` is given, frames[f] must hold all its nodes and the
/// triangles are drawn under the figure.
std::string filmstrip_svg(const StickFigure& source, const std::vector<std::vector<Vec2>>& frames,
                          const std::vector<double>& times, int snapshots, const FigureTriangulation* triangulation,
                          const std::string& title);

/// A filmstrip of a morph through key poses: every key (captioned "key k,
/// frame F") and `between` frames inside every segment, the last frame
/// too; frames[f] holds at least the figure's vertices (#V by 2).
std::string key_pose_filmstrip_svg(const StickFigure& figure, const std::vector<std::vector<Vec2>>& frames,
                                   const std::vector<double>& times, const std::vector<int>& key_frames,
                                   int between, const std::string& title);

/// Our morph (top row) against the straight-line morph (bottom row, the
/// paper's Figure 8d) at the same snapshots and one scale. Both hold the
/// figure's vertices per frame (#V by 2 at least); snapshots of frames listed
/// in `linear_invalid` are captioned as self-intersecting.
std::string comparison_filmstrip_svg(const StickFigure& source, const std::vector<std::vector<Vec2>>& ours,
                                     const std::vector<std::vector<Vec2>>& linear, const std::vector<double>& times,
                                     int snapshots, const std::vector<int>& linear_invalid, const std::string& title);

}  // namespace stickmorph
