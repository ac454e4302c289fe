#include "result_json.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <sys/stat.h>

#include "stickmorph/errors.h"

namespace stickmorph::cli {

void check_output_path(const std::string& option, const std::string& path) {
  if (path.empty()) throw InvalidArgumentError("option " + option + " needs a file name, got ''");
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    throw InvalidArgumentError("option " + option + ": " + path + " is a directory, not a file");
  // The folder the file goes into must exist; creating it is the caller's
  // decision, not ours.
  const std::size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  errno = 0;
  if (::stat(folder.c_str(), &info) != 0)
    throw InvalidArgumentError("option " + option + ": " + path + ": cannot write file: folder " + folder + ": " +
                               std::strerror(errno));
  if (!S_ISDIR(info.st_mode))
    throw InvalidArgumentError("option " + option + ": " + path + ": cannot write file: " + folder +
                               " is not a directory");
}

void write_files_atomically(const std::vector<OutputFile>& files) {
  std::vector<std::string> temporaries;
  const auto remove_temporaries = [&temporaries] {
    for (const std::string& temporary : temporaries) std::remove(temporary.c_str());
  };
  for (const OutputFile& file : files) {
    const std::string temporary = file.path + ".partial";
    std::ofstream stream(temporary, std::ios::binary | std::ios::trunc);
    if (!stream) {
      const std::string reason = std::strerror(errno);
      remove_temporaries();
      throw Error(file.path + ": cannot write file: " + reason);
    }
    temporaries.push_back(temporary);
    stream << file.text;
    stream.flush();
    if (!stream) {
      const std::string reason = errno != 0 ? std::strerror(errno) : "write failed";
      remove_temporaries();
      throw Error(file.path + ": cannot write file: " + reason);
    }
  }
  for (std::size_t k = 0; k < files.size(); ++k) {
    if (std::rename(temporaries[k].c_str(), files[k].path.c_str()) != 0) {
      const std::string reason = std::strerror(errno);
      for (std::size_t rest = k; rest < temporaries.size(); ++rest) std::remove(temporaries[rest].c_str());
      throw Error(files[k].path + ": cannot write file: " + reason);
    }
  }
}

}  // namespace stickmorph::cli
