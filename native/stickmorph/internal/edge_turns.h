// How far every edge of a stick figure turns from one drawing to another,
// the turns of adjacent edges kept consistent: the rotations the
// as-rigid-as-possible guides interpolate (rigid_guide.h between two
// figures, key_pose_guide.h from key to key).
#pragma once

#include <vector>

#include "stickmorph/stick_figure.h"

namespace stickmorph {
namespace internal {

/// Into (-pi, pi].
double wrap_angle(double a);

/// Every edge's turn (radians, counter-clockwise) from `source` to `target`
/// (#V by 2 each, the same vertices) along `edges`: each edge's own change
/// of direction, made consistent round every vertex (the counter-clockwise
/// angle between consecutive edges interpolates within (0, 360 degrees)),
/// each connected part shifted by the whole number of full turns that
/// brings its mean turn nearest `whole` (the figure's rotation, extra
/// turns included).
std::vector<double> edge_turns(const std::vector<Vec2>& source, const std::vector<Vec2>& target,
                               const std::vector<Edge>& edges, double whole);

}  // namespace internal
}  // namespace stickmorph
