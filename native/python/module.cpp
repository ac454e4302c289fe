// The `stickmorph` Python module: a thin shell over the C++ engine.
//
// Everything the module does is conversion: NumPy arrays and Python objects
// in, engine calls, NumPy arrays and Python objects out, and engine
// exceptions onto Python exception classes. Validation, limits, geometry and
// compatibility decisions all live in the engine, so that the module, the
// CLI and the C++ tests agree. The bindings are grouped by subject
// (bindings.h); this file only assembles them.
#include <pybind11/pybind11.h>

#include "bindings.h"

namespace py = pybind11;

namespace {

const char* const kModuleDoc = R"doc(Morphing of stick figures (connected straight-line plane graphs).

Surazhsky & Gotsman, "Morphing Stick Figures Using Optimized Compatible
Triangulations", Pacific Graphics 2001. A figure is given as

  vertices  #V by 2 array-like of float64 coordinates
  edges     #E by 2 array-like of integer vertex indices (0-based, undirected)

Every function validates its figures first and raises InvalidFigureError
naming the offending vertex and edge indices. Exception messages are the
engine's, the same text the `stickmorph` command prints after "error: ".

The engine's rules are module attributes, so that callers (the Blender
add-on, help texts) read them instead of keeping copies:

  limits        dict: the numeric bounds by name ("max_frames", ...)
  OPTION_NAMES  dict: morph()'s keyword -> the CLI's flag ("" if none)
  option_rules  dict: for each keyword option of morph() ("frames",
                "method", "steiner", "weights", "enclosure_sides",
                "verify", "frame_check", "rotation", "turns", "easing",
                "correspond", "pins") a dict with "methods", the tuple of
                method names it applies to (given with another method, it
                is refused with InvalidArgumentError), and where the option
                has them "min" and "max" (counts, inclusive), "choices"
                (the accepted names) and "default". pins have no default
                and need correspond="auto"; frame_check is refused with
                verify=False.)doc";


}  // namespace

PYBIND11_MODULE(stickmorph, m) {
  m.doc() = kModuleDoc;
  // Keep in step with project(VERSION) in the top-level CMakeLists.txt.
  m.attr("__version__") = STICKMORPH_VERSION;  // from CMake
  stickmorph::python::bind_errors(m);
  stickmorph::python::bind_figures(m);
  stickmorph::python::bind_drawings(m);
  stickmorph::python::bind_triangulation(m);
  stickmorph::python::bind_options(m);
  stickmorph::python::bind_progress(m);  // before the calls that take progress=
  stickmorph::python::bind_morph(m);
  stickmorph::python::bind_key_poses(m);
}
