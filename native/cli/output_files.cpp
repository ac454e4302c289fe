#include "output_files.h"

#include <cerrno>
#include <chrono>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <thread>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include "stickmorph/errors.h"

namespace stickmorph::cli {

struct OutputFiles::Destination {
  enum class Kind {
    File,        ///< a regular file, new or existing: temporary + rename
    Device,      ///< a character device, opened at construction
    Fifo,        ///< a FIFO, opened at commit once a reader has it open
    Descriptor,  ///< /dev/stdout, /dev/fd/N: a descriptor this process has
  };
  NamedPath given;
  Kind kind = Kind::File;
  std::string file;       ///< File: the path renamed over (symbolic links resolved); Fifo: the FIFO
  std::string identity;   ///< "dev:inode" of what exists, or the canonical path of a new file
  std::string temporary;  ///< File: until committed
  int descriptor = -1;    ///< File: the temporary; Device, Descriptor: where to write
};

namespace {

using Destination = OutputFiles::Destination;

std::string quoted(const std::string& text) { return "'" + text + "'"; }

[[noreturn]] void fail_output(const NamedPath& output, const std::string& what) {
  throw InvalidArgumentError("option " + output.name + ": " + what);
}

[[noreturn]] void fail_unwritable(const NamedPath& output, const std::string& reason) {
  fail_output(output, output.path + ": cannot write file: " + reason);
}

std::string folder_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string base_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string identity_of(const struct stat& info) {
  return std::to_string(info.st_dev) + ":" + std::to_string(info.st_ino);
}

bool all_digits(const std::string& text) {
  if (text.empty() || text.size() > 9) return false;
  for (char c : text)
    if (c < '0' || c > '9') return false;
  return true;
}

// The descriptor a path names without naming a file: /dev/stdout and
// /dev/stderr, /dev/fd/N and /proc/{self,thread-self,PID}/fd/N (PID this
// process). Such a path is a "magic" link to whatever the descriptor is
// open on, often a pipe with no name at all; renaming over it is
// impossible or wrong, so it is written into directly.
int named_descriptor(const std::string& path) {
  if (path == "/dev/stdout") return STDOUT_FILENO;
  if (path == "/dev/stderr") return STDERR_FILENO;
  const auto number_after = [&path](const std::string& prefix) {
    if (path.compare(0, prefix.size(), prefix) != 0) return -1;
    const std::string rest = path.substr(prefix.size());
    return all_digits(rest) ? std::atoi(rest.c_str()) : -1;
  };
  for (const std::string& prefix : {std::string("/dev/fd/"), std::string("/proc/self/fd/"), std::string("/proc/thread-self/fd/"),
                                   "/proc/" + std::to_string(::getpid()) + "/fd/"})
    if (const int fd = number_after(prefix); fd >= 0) return fd;
  return -1;
}

// Follows `path` through symbolic links in its last component, as open()
// would, to the name that a rename must replace: writing "through" a link
// keeps the link. Stops at a name that does not exist (a dangling link
// creates its target, as `echo > link` does) or at a descriptor name.
std::string final_name(const NamedPath& output, int& descriptor) {
  std::string current = output.path;
  for (int hops = 0; hops < 40; ++hops) {
    descriptor = named_descriptor(current);
    if (descriptor >= 0) return current;
    struct stat info {};
    if (::lstat(current.c_str(), &info) != 0) {
      // A missing file, or a folder on the way that is not one: the
      // folder check says which (existing_folder).
      if (errno == ENOENT || errno == ENOTDIR) return current;
      fail_unwritable(output, std::strerror(errno));
    }
    if (!S_ISLNK(info.st_mode)) return current;
    std::string target(PATH_MAX, '\0');
    const ssize_t length = ::readlink(current.c_str(), target.data(), target.size());
    if (length < 0) fail_unwritable(output, std::strerror(errno));
    target.resize(std::size_t(length));
    current = !target.empty() && target[0] == '/' ? target : folder_of(current) + "/" + target;
  }
  fail_unwritable(output, std::strerror(ELOOP));
}

// The folder a new file goes into must exist; creating it is the caller's
// decision, not ours. Returns its canonical path.
std::string existing_folder(const NamedPath& output, const std::string& file) {
  const std::string folder = folder_of(file);
  struct stat info {};
  if (::stat(folder.c_str(), &info) != 0)
    fail_unwritable(output, "folder " + folder + ": " + std::strerror(errno));
  if (!S_ISDIR(info.st_mode)) fail_unwritable(output, folder + " is not a directory");
  char* canonical = ::realpath(folder.c_str(), nullptr);
  if (canonical == nullptr) fail_unwritable(output, "folder " + folder + ": " + std::strerror(errno));
  std::string result(canonical);
  std::free(canonical);
  return result;
}

std::unique_ptr<Destination> resolve(const NamedPath& output) {
  if (output.path.empty()) throw InvalidArgumentError("option " + output.name + " needs a file name, got ''");
  auto destination = std::make_unique<Destination>();
  destination->given = output;
  int descriptor = -1;
  const std::string file = final_name(output, descriptor);
  struct stat info {};
  if (descriptor >= 0) {
    // Written into directly through a duplicate, so that closing it leaves
    // the process's own descriptor open.
    if (::fstat(descriptor, &info) != 0) fail_unwritable(output, std::strerror(errno));
    if (S_ISDIR(info.st_mode)) fail_output(output, output.path + " is a directory, not a file");
    destination->kind = Destination::Kind::Descriptor;
    destination->identity = identity_of(info);
    destination->descriptor = ::fcntl(descriptor, F_DUPFD_CLOEXEC, 3);
    if (destination->descriptor < 0) fail_unwritable(output, std::strerror(errno));
    return destination;
  }
  if (::stat(file.c_str(), &info) != 0) {
    if (errno != ENOENT && errno != ENOTDIR) fail_unwritable(output, std::strerror(errno));
    destination->kind = Destination::Kind::File;
    destination->file = file;
    destination->identity = existing_folder(output, file) + "/" + base_of(file);
    return destination;
  }
  destination->identity = identity_of(info);
  destination->file = file;
  if (S_ISDIR(info.st_mode)) fail_output(output, output.path + " is a directory, not a file");
  if (S_ISREG(info.st_mode)) {
    destination->kind = Destination::Kind::File;
    existing_folder(output, file);
    return destination;
  }
  if (S_ISCHR(info.st_mode)) {
    destination->kind = Destination::Kind::Device;
    // Opened now: a device the user may not write fails before the work,
    // and opening a character device has no effect of its own.
    destination->descriptor = ::open(file.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (destination->descriptor < 0) fail_unwritable(output, std::strerror(errno));
    return destination;
  }
  if (S_ISFIFO(info.st_mode)) {
    // Opened only at commit: opening a FIFO for writing waits for a
    // reader, and the reader should not wait for the whole morph.
    if (::access(file.c_str(), W_OK) != 0) fail_unwritable(output, std::strerror(errno));
    destination->kind = Destination::Kind::Fifo;
    return destination;
  }
  // A block device is a disk: writing a JSON document onto it is never
  // what was meant. A socket cannot be opened.
  fail_output(output, output.path + (S_ISBLK(info.st_mode) ? " is a block device" : " is a socket") +
                          ", not a file (outputs are regular files, character devices or FIFOs)");
}

// A temporary file beside the output, for the rename at the end. Made now
// so that a folder without write permission, on a read-only file system or
// under /proc, fails before the work. An existing file's permission bits
// carry over to its replacement.
void make_temporary(Destination& destination) {
  std::string name = folder_of(destination.file) + "/." + base_of(destination.file) + ".XXXXXX";
  const int fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd < 0) fail_unwritable(destination.given, std::strerror(errno));
  destination.descriptor = fd;
  destination.temporary = name;
  struct stat info {};
  if (::stat(destination.file.c_str(), &info) == 0 && S_ISREG(info.st_mode)) {
    ::fchmod(fd, info.st_mode & 07777);
  } else {
    // mkostemp makes the file 0600; a new output gets what open() would
    // give it, 0666 less the umask.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
  }
}

// Writes all of `text`, through partial writes and interrupted calls.
// Returns 0 or the errno of the failure.
int write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t count = ::write(fd, text.data() + done, text.size() - done);
    if (count < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (count == 0) return EIO;
    done += std::size_t(count);
  }
  return 0;
}

// Opens a FIFO for writing once some process has it open for reading,
// polling for at most kFifoReaderWaitMilliseconds: a plain open() would
// wait forever for a reader that never comes.
int open_fifo(const Destination& destination) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::milliseconds(kFifoReaderWaitMilliseconds);
  while (true) {
    const int fd = ::open(destination.file.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd >= 0) {
      // Blocking writes from here on: the reader sets the pace.
      ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
      return fd;
    }
    if (errno != ENXIO && errno != EINTR)
      throw Error(destination.given.path + ": cannot write file: " + std::strerror(errno));
    if (Clock::now() >= deadline)
      throw Error(destination.given.path + ": cannot write file: no process opened the FIFO for reading within " +
                  std::to_string(kFifoReaderWaitMilliseconds / 1000) + " s");
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

// SIGPIPE ignored while writing into pipes, so that a reader that goes
// away is an EPIPE error message, not a silent death of the process.
class IgnoredSigpipe {
 public:
  IgnoredSigpipe() {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    ::sigemptyset(&ignore.sa_mask);
    ::sigaction(SIGPIPE, &ignore, &previous_);
  }
  ~IgnoredSigpipe() { ::sigaction(SIGPIPE, &previous_, nullptr); }
  IgnoredSigpipe(const IgnoredSigpipe&) = delete;
  IgnoredSigpipe& operator=(const IgnoredSigpipe&) = delete;

 private:
  struct sigaction previous_ {};
};

}  // namespace

OutputFiles::OutputFiles(const std::string& command, const std::vector<NamedPath>& outputs,
                         const std::vector<NamedPath>& inputs) {
  for (const NamedPath& output : outputs) destinations_.push_back(resolve(output));
  const std::string prefix = command.empty() ? "" : command + ": ";
  for (std::size_t j = 0; j < destinations_.size(); ++j) {
    const Destination& later = *destinations_[j];
    for (std::size_t i = 0; i < j; ++i)
      if (destinations_[i]->identity == later.identity)
        throw InvalidArgumentError(prefix + later.given.name + " and " + destinations_[i]->given.name +
                                   " name the same file " + quoted(later.given.path));
    for (const NamedPath& input : inputs) {
      struct stat info {};
      // An input that cannot be read is the reader's to report.
      if (::stat(input.path.c_str(), &info) == 0 && identity_of(info) == later.identity)
        throw InvalidArgumentError(prefix + later.given.name + " and " + input.name + " name the same file " +
                                   quoted(later.given.path) + " (an output would overwrite an input)");
    }
  }
  for (const auto& destination : destinations_)
    if (destination->kind == Destination::Kind::File) make_temporary(*destination);
}

OutputFiles::~OutputFiles() {
  for (const auto& destination : destinations_) {
    if (destination->descriptor >= 0) ::close(destination->descriptor);
    if (!destination->temporary.empty()) ::unlink(destination->temporary.c_str());
  }
}

void OutputFiles::commit(const std::vector<std::string>& texts) {
  if (texts.size() != destinations_.size())
    throw InternalError("OutputFiles::commit: " + std::to_string(texts.size()) + " texts for " +
                        std::to_string(destinations_.size()) + " outputs");
  const auto fail = [](const Destination& destination, int error_number) {
    throw Error(destination.given.path + ": cannot write file: " + std::strerror(error_number));
  };
  // 1. Every regular file into its temporary.
  for (std::size_t k = 0; k < texts.size(); ++k) {
    Destination& destination = *destinations_[k];
    if (destination.kind != Destination::Kind::File) continue;
    if (const int error = write_all(destination.descriptor, texts[k])) fail(destination, error);
    const int fd = destination.descriptor;
    destination.descriptor = -1;
    if (::close(fd) != 0) fail(destination, errno);
  }
  // 2. Devices, FIFOs and descriptors, which cannot be undone: after every
  // temporary is complete, before any existing file changes.
  {
    const IgnoredSigpipe sigpipe;
    for (std::size_t k = 0; k < texts.size(); ++k) {
      Destination& destination = *destinations_[k];
      if (destination.kind == Destination::Kind::File) continue;
      if (destination.kind == Destination::Kind::Fifo) destination.descriptor = open_fifo(destination);
      if (const int error = write_all(destination.descriptor, texts[k])) fail(destination, error);
    }
  }
  // 3. The renames. Each replaces its file atomically; a rename within one
  // folder of a file made there fails only if the folder itself changed
  // meanwhile, and then the outputs renamed before it stay written.
  for (const auto& destination : destinations_) {
    if (destination->kind != Destination::Kind::File) continue;
    if (::rename(destination->temporary.c_str(), destination->file.c_str()) != 0) fail(*destination, errno);
    destination->temporary.clear();
  }
}

}  // namespace stickmorph::cli
