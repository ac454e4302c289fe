// Putting the CLI's output files on disk (docs/CLI.md, "Output files").
// Their contents (docs/FORMAT.md) are written by the IO library:
// stickmorph/io/result_files.h.
//
// Every output is resolved and checked before the command does any work,
// and nothing that exists is changed until every output is complete:
// - a regular file, new or existing, is written through a temporary file
//   in its own folder, renamed over it only at the end (an existing file
//   keeps its permission bits); a symbolic link is written through to the
//   file it names, so the link stays a link;
// - a character device (/dev/null, a terminal) or a FIFO, and the names of
//   open descriptors (/dev/stdout, /dev/fd/N, /proc/self/fd/N), are
//   written into directly: renaming over them would replace a device node
//   or a pipe with a regular file;
// - a directory, a block device or a socket is refused;
// - two outputs that are the same file, or an output that is one of the
//   inputs, are refused naming both.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace stickmorph::cli {

/// A file argument and the name it goes by in messages: an option
/// ("--output", "--svg") or a positional argument ("SOURCE.json").
struct NamedPath {
  std::string name;
  std::string path;
};

/// The output files of one command, resolved and checked at construction,
/// before any work; `commit` writes them all. Temporary files that were
/// not committed are removed by the destructor, so a command that fails
/// between the two leaves no trace.
class OutputFiles {
 public:
  /// Resolves and checks every output, and each against the others and
  /// against `inputs` (the files the command will read). Creates the
  /// temporary file of every regular output, so that a folder where no
  /// file can be made (read-only, /proc) fails now rather than after the
  /// work. `command` prefixes the messages that name two arguments.
  /// @throws InvalidArgumentError naming the option and the path.
  OutputFiles(const std::string& command, const std::vector<NamedPath>& outputs,
              const std::vector<NamedPath>& inputs);
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  /// Writes `texts[k]` to output k (the constructor's order). All regular
  /// files are first written to their temporaries, then the devices and
  /// FIFOs, and only then are the temporaries renamed into place, so a
  /// failure before the renames (a full disk, /dev/full, a FIFO nobody
  /// reads) changes no existing file.
  /// @throws Error naming the path that failed.
  void commit(const std::vector<std::string>& texts);

  struct Destination;

 private:
  std::vector<std::unique_ptr<Destination>> destinations_;
};

/// How long writing into a FIFO waits for a process to open it for reading
/// before the command fails instead of hanging.
constexpr int kFifoReaderWaitMilliseconds = 10000;

}  // namespace stickmorph::cli
