// The benchmarks' child processes: each case runs in a fork of its own with
// an address-space limit and an alarm, so that one case that runs out of
// memory or time is reported as such (and measured by its own ru_maxrss)
// instead of ending the whole run. Shared by stickmorph_benchmark_morph and
// stickmorph_benchmark_correspondence.
#pragma once

#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <functional>
#include <iostream>
#include <new>
#include <string>

#include "stickmorph/errors.h"

namespace stickmorph::bench {

using Clock = std::chrono::steady_clock;
inline double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct ChildResult {
  std::string status;  ///< ok, failed, timeout, out_of_memory, crashed
  std::string body;    ///< the child's JSON fields (ok) or message
  double wall_ms = 0;
  long peak_kib = 0;
};

/// Runs `work` in a child with an address-space limit and an alarm; the child
/// writes "ok <json>" or "failed <message>" to a pipe.
inline ChildResult run_child(const std::function<std::string()>& work, int seconds, long memory_mib) {
  ChildResult result;
  int fds[2];
  if (pipe(fds) != 0) throw Error(std::string("pipe: ") + std::strerror(errno));
  std::cout.flush();
  std::cerr.flush();
  const auto start = Clock::now();
  const pid_t child = fork();
  if (child < 0) throw Error(std::string("fork: ") + std::strerror(errno));
  if (child == 0) {
    close(fds[0]);
    struct rlimit limit {};
    limit.rlim_cur = limit.rlim_max = rlim_t(memory_mib) * 1024 * 1024;
    setrlimit(RLIMIT_AS, &limit);
    alarm(unsigned(seconds));  // SIGALRM's default action ends the child
    std::string message;
    try {
      message = "ok " + work();
    } catch (const std::bad_alloc&) {
      message = "out_of_memory more than the " + std::to_string(memory_mib) + " MiB address-space limit";
    } catch (const std::exception& error) {
      message = std::string("failed ") + error.what();
    }
    for (char& c : message)
      if (c == '\n') c = ' ';
    std::size_t sent = 0;
    while (sent < message.size()) {
      const ssize_t wrote = write(fds[1], message.data() + sent, message.size() - sent);
      if (wrote <= 0) break;
      sent += std::size_t(wrote);
    }
    close(fds[1]);
    _exit(0);
  }
  close(fds[1]);
  std::string text;
  char chunk[4096];
  ssize_t got;
  while ((got = read(fds[0], chunk, sizeof chunk)) > 0) text.append(chunk, std::size_t(got));
  close(fds[0]);
  int status = 0;
  struct rusage usage {};
  wait4(child, &status, 0, &usage);
  result.wall_ms = ms_since(start);
  result.peak_kib = long(usage.ru_maxrss);  // kilobytes on Linux
  const std::size_t space = text.find(' ');
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM) {
    result.status = "timeout";
    result.body = "stopped after the " + std::to_string(seconds) + " s limit";
  } else if (WIFSIGNALED(status) || space == std::string::npos) {
    result.status = "crashed";
    result.body = WIFSIGNALED(status) ? "signal " + std::to_string(WTERMSIG(status))
                                      : "exit status " + std::to_string(WEXITSTATUS(status));
  } else {
    result.status = text.substr(0, space);
    result.body = text.substr(space + 1);
  }
  return result;
}

}  // namespace stickmorph::bench
