// Upper bounds on numeric options, shared by the CLI and the Python module.
//
// These options scale work, not input: a count the engine would accept but
// spend minutes or all memory on is refused at the interface with an
// InvalidArgumentError instead of hanging the caller.
#pragma once

namespace stickmorph {

/// The largest number of sides of the common enclosure (--enclosure-sides,
/// enclosure_sides=). The annulus between figure and enclosure is
/// triangulated in time quadratic in the sides: 0.1 s for 1000 on the letter
/// A, 6 s for 10000, over a minute for 30000. The paper uses a hexagon.
constexpr int kMaxEnclosureSides = 1000;

/// The largest number of Laplacian smoothing rounds of compatible_triangulation.
/// Each round moves every Steiner vertex once; the default is 10.
constexpr int kMaxSmoothingRounds = 1000;

}  // namespace stickmorph
