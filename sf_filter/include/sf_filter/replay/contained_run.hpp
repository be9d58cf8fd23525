// Runs the offline replay in a child process, so that a crash inside a library while it reads a
// corrupt file (librosbag trusts the offsets of a bag's index: a flipped bit there makes it
// read outside its buffer and die by SIGSEGV or SIGBUS) or an interrupt (Ctrl-C, SIGTERM)
// still ends with a one-line message and with the partial outputs removed, which a process
// killed by a signal could not do for itself.
#pragma once

#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>

namespace sf_filter {

namespace detail {

inline volatile std::sig_atomic_t containedChild = 0;

/// The parent passes an interrupt on to the child and lets it end first.
inline void forwardToChild(int signal) {
  if (containedChild > 0) ::kill(static_cast<pid_t>(containedChild), signal);
}

}  // namespace detail

/// Runs `body` in a child and returns its exit status. If the child dies by a signal, calls
/// `onSignal(signal)` in this process and returns 128 + signal for SIGINT, SIGTERM and
/// SIGHUP (an interrupt), 1 otherwise (a crash). Without fork() `body` runs here.
inline int runContained(const std::function<int()>& body,
                        const std::function<void(int signal)>& onSignal) {
  std::cout.flush();
  std::cerr.flush();
  const pid_t child = ::fork();
  if (child < 0) return body();
  if (child == 0) {
    // A crash on a corrupt input is reported by the parent; it leaves no core file.
    const rlimit noCore{0, 0};
    ::setrlimit(RLIMIT_CORE, &noCore);
    const int status = body();
    std::exit(status);  // flushes the streams; the parent's handlers are not run twice
  }
  detail::containedChild = child;
  struct sigaction forward {
  }, previous[3];
  forward.sa_handler = detail::forwardToChild;
  sigemptyset(&forward.sa_mask);
  const int interrupts[3] = {SIGINT, SIGTERM, SIGHUP};
  for (int k = 0; k < 3; ++k) ::sigaction(interrupts[k], &forward, &previous[k]);
  int status = 0;
  pid_t waited = 0;
  while ((waited = ::waitpid(child, &status, 0)) < 0 && errno == EINTR) {
  }
  for (int k = 0; k < 3; ++k) ::sigaction(interrupts[k], &previous[k], nullptr);
  detail::containedChild = 0;
  if (waited < 0) return EXIT_FAILURE;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  const int signal = WTERMSIG(status);
  onSignal(signal);
  return signal == SIGINT || signal == SIGTERM || signal == SIGHUP ? 128 + signal : EXIT_FAILURE;
}

}  // namespace sf_filter
