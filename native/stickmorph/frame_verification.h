// Exact verification of morph frames.
//
// Surazhsky & Gotsman 2001, section 2.1: a morph between compatible stick
// figures is valid when every intermediate shape is again a stick figure
// compatible with the source (same cyclic sequences, same exterior
// sequence). This is the library's one check of that property: the morph
// stage runs it on every frame it returns, and the linear-morph baseline
// (the paper's Figure 8d) uses it to report the frames that break.
//
// Both halves are the existing exact machinery: make_stick_figure decides
// planarity (crossings, touchings, overlaps, coincident vertices) with exact
// predicates, and check_compatibility compares the rotation system and the
// exterior sequence of Algorithm 1 against the source.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "stickmorph/decomposition.h"
#include "stickmorph/stick_figure.h"

namespace stickmorph {

/// Checks exactly that `positions` (#V by 2, #V = source.vertices.size())
/// joined by the source's edges is a valid stick figure whose cyclic
/// sequences are those of `source`: the same rotation at every vertex and
/// the same exterior sequence, i.e. a plane graph with the source's topology.
///
/// @param frame_index  named in the message ("frame 12 ...")
/// @param time         the frame's time, named in the message when finite
///                     ("frame 12 (t = 0.2449): ...")
/// @throws VerificationError naming the frame and the defect, e.g.
///         "frame 12 (t = 0.2449): edges 3 (1-2) and 7 (4-5) cross";
///         InvalidArgumentError if positions has the wrong length.
void verify_frame(const StickFigure& source, const std::vector<Vec2>& positions, int frame_index,
                  double time = std::numeric_limits<double>::quiet_NaN());

/// As above, reusing the source's decomposition (decompose(source)) so that
/// checking many frames decomposes the source once.
void verify_frame(const StickFigure& source, const Decomposition& source_decomposition,
                  const std::vector<Vec2>& positions, int frame_index,
                  double time = std::numeric_limits<double>::quiet_NaN());

/// True iff verify_frame would pass. Throws InvalidArgumentError only for a
/// positions array of the wrong length.
bool is_frame_valid(const StickFigure& source, const std::vector<Vec2>& positions);
bool is_frame_valid(const StickFigure& source, const Decomposition& source_decomposition,
                    const std::vector<Vec2>& positions);

/// "frame 12 (t = 0.2449)", or "frame 12" when time is not finite: the
/// prefix of every message about a frame. A negative index names a frame
/// by its time alone, "t = 0.2449" (a frame scrubbed at any t has no index).
std::string frame_label(int frame_index, double time);

}  // namespace stickmorph
