// stickmorph.Progress: the engine's Progress (cancellation.h) for Python,
// so that a long morph() or morph_key_poses() running in one thread (with
// the GIL released) can be watched and cancelled from another: the Blender
// add-on's modal bake (issue 29).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "conversions.h"
#include "progress_argument.h"
#include "stickmorph/cancellation.h"
#include "stickmorph/errors.h"

namespace stickmorph::python {
namespace {

// What `with progress:` installed on this thread, innermost last. The
// shared_ptr keeps the Progress alive while it is installed, whatever
// Python does with its own reference; the scope restores the outer one.
struct Installed {
  std::shared_ptr<sm::Progress> progress;
  std::unique_ptr<sm::ProgressScope> scope;
};
thread_local std::vector<Installed> t_installed;

py::object optional_stage(const std::string& stage) {
  return stage.empty() ? py::object(py::none()) : py::object(py::str(stage));
}

long to_step_count(const py::object& value, const char* name) {
  if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value))
    throw sm::InvalidArgumentError(std::string(name) + " must be an int, got " +
                                   py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  const long long count = value.cast<long long>();
  if (count < 0) throw sm::InvalidArgumentError(std::string(name) + " must not be negative, got " + std::to_string(count));
  return long(count);
}

}  // namespace

std::shared_ptr<sm::Progress> to_progress(const py::object& object) {
  if (object.is_none()) return nullptr;
  if (!py::isinstance<sm::Progress>(object))
    throw sm::InvalidArgumentError("progress must be a stickmorph.Progress or None, got " +
                                   py::str(py::type::of(object).attr("__name__")).cast<std::string>());
  return object.cast<std::shared_ptr<sm::Progress>>();
}

void bind_progress(py::module_& m) {
  py::class_<sm::Progress, std::shared_ptr<sm::Progress>>(m, "Progress", R"doc(Progress and cancellation of a long engine call (issue 29).

A 10^5-vertex morph takes minutes, most of it the compatible
triangulation. Run it in a worker thread (the engine releases the GIL) with
a Progress, and read or cancel the Progress from any other thread:

  progress = stickmorph.Progress()
  worker = threading.Thread(target=lambda: stickmorph.morph(..., progress=progress))
  worker.start()
  ...                       # progress.stage, progress.fraction, progress.summary()
  progress.cancel()         # the call raises CancelledError within a fraction of a second

morph() and morph_key_poses() (and KeyPoseMorphSolver) take progress=;
`with progress:` installs it for every engine call the current thread makes
inside the block (correspond(), check_compatibility(), ...), for callers
whose engine calls are not their own. Not cancelled, a Progress changes
nothing: the results are bit for bit those without one.

The engine's stages, in the order they run: "check" (validation,
Algorithm 1, compatibility), "correspond" (correspond="auto"),
"triangulate" (the compatible triangulation, one per key-pose segment, and
for the rigid method the solver's set-up on it; counted where the engine
can count: the interior faces of a figure of many faces, the corners of a
face of 1000 corners or more, restarting with each), "frames" (counted in
frames). fraction is real progress of the current count, not a time
estimate. Callers may time stages of their
own with begin_stage(). A cancelled call raises CancelledError at the
engine's next check: between two frames, and in the triangulation's long
loops.)doc")
      .def(py::init([] { return std::make_shared<sm::Progress>(); }))
      .def("cancel", &sm::Progress::cancel,
           "Asks the running call to stop: it raises CancelledError at its next check. Any thread may call "
           "it, any number of times; it cannot be undone, and later calls with this Progress are cancelled "
           "before any work.")
      .def_property_readonly("cancelled", &sm::Progress::cancelled, "Whether cancel() was called.")
      .def_property_readonly(
          "stage", [](const sm::Progress& self) { return optional_stage(self.stage()); },
          "The current stage's name (\"check\", \"correspond\", \"triangulate\", \"frames\", or a "
          "caller's), None before the first and after the call.")
      .def_property_readonly("done", &sm::Progress::done, "Steps of the current stage done (int).")
      .def_property_readonly("total", &sm::Progress::total,
                             "Steps of the current stage (int), 0 when the stage is not counted.")
      .def_property_readonly(
          "fraction",
          [](const sm::Progress& self) -> py::object {
            const double fraction = self.fraction();
            return fraction < 0 ? py::object(py::none()) : py::object(py::float_(fraction));
          },
          "done / total of the current stage's count, a float in [0, 1], or None while nothing is "
          "counted.")
      .def_property_readonly(
          "stages",
          [](const sm::Progress& self) {
            py::list list;
            for (const sm::Progress::StageTime& t : self.stage_times())
              list.append(py::make_tuple(t.name, t.milliseconds));
            return list;
          },
          "[(name, milliseconds), ...]: every stage so far, the current one up to now; a stage that ran "
          "more than once (one triangulation per key-pose segment) is one entry, its times added.")
      .def("summary", &sm::Progress::summary,
           "The stages as text: \"check 30 ms, triangulate 3100 ms, frames 900 ms\".")
      .def(
          "begin_stage",
          [](sm::Progress& self, const std::string& name, const py::object& total) {
            if (name.empty()) throw sm::InvalidArgumentError("a stage needs a name");
            self.begin_stage(name, to_step_count(total, "total"));
          },
          py::arg("name"), py::arg("total") = 0,
          "Ends the current stage and starts `name` with `total` steps (0: not counted), for a caller's "
          "own stages around the engine's (reading input, writing the result).")
      .def(
          "set_progress",
          [](sm::Progress& self, const py::object& done, const py::object& total) {
            self.set_progress(to_step_count(done, "done"), to_step_count(total, "total"));
          },
          py::arg("done"), py::arg("total"), "Sets `done` of `total` steps of the current stage.")
      .def("finish", &sm::Progress::finish, "Ends the current stage; stage becomes None.")
      .def("__enter__",
           [](const std::shared_ptr<sm::Progress>& self) {
             Installed installed;
             installed.progress = self;
             installed.scope = std::make_unique<sm::ProgressScope>(self.get());
             t_installed.push_back(std::move(installed));
             return self;
           })
      .def("__exit__", [](const std::shared_ptr<sm::Progress>& self, const py::args&) {
        // `with` blocks nest per thread: the innermost is this one.
        if (t_installed.empty() || t_installed.back().progress != self)
          throw sm::InvalidArgumentError("Progress.__exit__ without its __enter__ on this thread");
        t_installed.pop_back();
        self->finish();
        return false;
      });
}

}  // namespace stickmorph::python
