// An output file of the offline replay, written under a temporary name beside its target and
// renamed into place only when the whole replay succeeded, so that a failed run never leaves
// a partial result behind (and never replaces an older complete one).
#pragma once

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace sf_filter {

/// A replay that cannot run (unreadable bag, missing topic, wrong type, unwritable output).
class ReplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The temporary name under which `path` is written until the replay has succeeded.
inline std::string partialPath(const std::string& path) { return path + ".partial"; }

class AtomicOutput {
 public:
  /// `path` empty: no output. Refuses a target that is a directory up front: the rename at the
  /// end would fail after all the work, with the other output already in place.
  explicit AtomicOutput(std::string path)
      : path_(std::move(path)), temporary_(path_.empty() ? "" : partialPath(path_)) {
    struct stat st {};
    if (enabled() && ::stat(path_.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
      throw ReplayError("cannot write " + path_ + ": it is a directory");
    }
  }
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  ~AtomicOutput() {
    if (!committed_ && !temporary_.empty()) std::remove(temporary_.c_str());
  }
  bool enabled() const { return !path_.empty(); }
  const std::string& path() const { return path_; }
  const std::string& temporary() const { return temporary_; }
  void commit() {
    if (!enabled()) return;
    if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
      throw ReplayError("cannot move " + temporary_ + " to " + path_ + ": " + std::strerror(errno));
    }
    committed_ = true;
  }

 private:
  std::string path_, temporary_;
  bool committed_ = false;
};

}  // namespace sf_filter
