// The progress= argument of the long calls (morph, morph_key_poses,
// KeyPoseMorphSolver): a stickmorph.Progress (bind_progress.cpp) installed
// for the engine call, or None for whatever `with progress:` installed.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>

#include "stickmorph/cancellation.h"

namespace stickmorph::python {

/// The Progress behind a stickmorph.Progress, nullptr for None.
/// @throws InvalidArgumentError for anything else.
std::shared_ptr<stickmorph::Progress> to_progress(const pybind11::object& object);

/// Installs `progress` for one engine call on this thread, or, for
/// nullptr, keeps the thread's own (a `with progress:` block's). Made and
/// ended inside the call's GIL release: the same thread either way.
class CallProgress {
 public:
  explicit CallProgress(std::shared_ptr<stickmorph::Progress> progress)
      : progress_(std::move(progress)),
        scope_(progress_ ? progress_.get() : stickmorph::current_progress()) {}
  /// A call given its own Progress ends its last stage when it returns, so
  /// that summary() is the call's; a `with` block's ends at the block's end.
  void finished() {
    if (progress_) progress_->finish();
  }

 private:
  std::shared_ptr<stickmorph::Progress> progress_;
  stickmorph::ProgressScope scope_;
};

}  // namespace stickmorph::python
