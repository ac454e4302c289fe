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
engine's, the same text the `stickmorph` command prints after "error: ".)doc";


}  // namespace

PYBIND11_MODULE(stickmorph, m) {
  m.doc() = kModuleDoc;
  // Keep in step with project(VERSION) in the top-level CMakeLists.txt.
  m.attr("__version__") = STICKMORPH_VERSION;  // from CMake
  stickmorph::python::bind_errors(m);
  stickmorph::python::bind_figures(m);
  stickmorph::python::bind_triangulation(m);
  stickmorph::python::bind_morph(m);
}
