// An output file of the offline tools (--csv, --bag, --tune's --out), written under a
// temporary name beside its target and renamed into place only when the whole run succeeded,
// so that a failed run never leaves a partial result behind (and never replaces an older
// complete one); refused up front when it would replace an input or something that is not a
// regular file.
#pragma once

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace sf_filter {

/// A replay that cannot run (unreadable bag, missing topic, wrong type, unwritable output).
class ReplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The temporary name under which `path` is written until the replay has succeeded.
inline std::string partialPath(const std::string& path) { return path + ".partial"; }

namespace atomic_output_detail {

/// What a file of type `mode` is, for the messages.
inline const char* kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISLNK(mode)) return "a symbolic link";
  return "not a regular file";
}

/// Refuses `path` as an output if something other than a regular file is there (lstat: a
/// symbolic link is not followed, the rename would replace the link itself).
inline void requireRegularOrNew(const std::string& path, const std::string& what) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    throw ReplayError("cannot write " + what + " " + path + ": it is " + kind(st.st_mode) +
                      ", not a regular file (the output is written beside it and renamed "
                      "onto it)");
  }
}

/// The directory part and the file name of `path`.
inline std::pair<std::string, std::string> split(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return {".", path};
  return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

}  // namespace atomic_output_detail

/// Whether `a` and `b` name the same file: the same device and inode if both exist,
/// otherwise the same file name in the same directory (device and inode of the directories).
inline bool sameFile(const std::string& a, const std::string& b) {
  struct stat sa {
  }, sb{};
  const bool ea = ::stat(a.c_str(), &sa) == 0, eb = ::stat(b.c_str(), &sb) == 0;
  if (ea && eb) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  if (ea || eb) return false;
  const auto [da, na] = atomic_output_detail::split(a);
  const auto [db, nb] = atomic_output_detail::split(b);
  if (na != nb) return false;
  return ::stat(da.c_str(), &sa) == 0 && ::stat(db.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

/// Files by what they are: (option or kind, path), e.g. ("--csv", "out.csv"), ("bag", "in.bag").
using NamedFiles = std::vector<std::pair<std::string, std::string>>;

/// The checks of one output, given by `option` (--csv, --bag, --out): neither `path` nor its
/// temporary name is one of the files the run reads (`inputs`: the bags, the --params file;
/// by device and inode, so another spelling or a hard link is found), and what exists there
/// is a regular file (lstat: a symbolic link, a directory, a device or a FIFO is refused,
/// the rename would replace it). Every output of every tool is checked by this function alone.
inline void checkOutput(const std::string& option, const std::string& path,
                        const NamedFiles& inputs) {
  for (const std::string& p : {path, partialPath(path)}) {
    for (const auto& [what, input] : inputs) {
      if (sameFile(p, input)) {
        throw ReplayError(option + " " + path + " is the input " + what + " " + input +
                          ": refusing to overwrite the input");
      }
    }
  }
  atomic_output_detail::requireRegularOrNew(path, option);
  atomic_output_detail::requireRegularOrNew(partialPath(path), option);
}

/// Refuses outputs that would destroy an input or each other, before anything is read:
/// checkOutput() for each, and no file named by two outputs.
inline void checkOutputs(const NamedFiles& inputs, const NamedFiles& outputs) {
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const auto& [option, path] = outputs[k];
    if (path.empty()) continue;
    checkOutput(option, path, inputs);
    for (std::size_t j = 0; j < k; ++j) {
      if (!outputs[j].second.empty() && sameFile(outputs[j].second, path)) {
        throw ReplayError(outputs[j].first + " and " + option + " name the same file " + path);
      }
    }
  }
}

/// The one writer of the tools' output files: checkOutput() when it is made and again just
/// before the rename, the content written under the temporary name.
class AtomicOutput {
 public:
  /// `path` empty: no output. Refuses a target that checkOutput() refuses up front: the
  /// rename at the end would replace it, or fail after all the work with the other output
  /// already in place.
  AtomicOutput(std::string option, std::string path, NamedFiles inputs)
      : option_(std::move(option)),
        path_(std::move(path)),
        temporary_(path_.empty() ? "" : partialPath(path_)),
        inputs_(std::move(inputs)) {
    if (enabled()) checkOutput(option_, path_, inputs_);
  }
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  ~AtomicOutput() {
    if (!committed_ && !temporary_.empty()) std::remove(temporary_.c_str());
  }
  bool enabled() const { return !path_.empty(); }
  const std::string& path() const { return path_; }
  const std::string& temporary() const { return temporary_; }
  /// Renames the temporary file onto the target, checked again (checkOutput()).
  void commit() {
    if (!enabled()) return;
    checkOutput(option_, path_, inputs_);
    if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
      throw ReplayError("cannot move " + temporary_ + " to " + path_ + ": " + std::strerror(errno));
    }
    committed_ = true;
  }
  /// The whole file at once: `text` written under the temporary name, then commit().
  void write(const std::string& text) {
    if (!enabled()) return;
    std::ofstream file(temporary_);
    file << text;
    file.close();
    if (!file) {
      throw ReplayError("cannot write " + path_ + " (as " + temporary_ +
                        "): " + std::strerror(errno));
    }
    commit();
  }

 private:
  std::string option_, path_, temporary_;
  NamedFiles inputs_;
  bool committed_ = false;
};

}  // namespace sf_filter
