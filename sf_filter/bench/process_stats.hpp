// What the load drivers read about the fusion node's process from /proc (node_load_driver.cpp,
// soak_driver.cpp): its CPU time and its resident memory.
#pragma once

#include <dirent.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sf_bench {

struct CpuSample {
  bool ok = false;
  double statSeconds = 0.0;  ///< utime + stime of the process (all threads, ever)
  double schedNs = 0.0;      ///< sum over the live threads of the time on CPU
  int threads = 0;
};

/// utime + stime of /proc/<pid>/stat (clock ticks) and the sum of /proc/<pid>/task/*/schedstat.
inline CpuSample readCpu(int pid) {
  CpuSample s;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return s;
  const auto close = line.rfind(')');
  if (close == std::string::npos) return s;
  std::istringstream fields(line.substr(close + 2));  // from field 3 (state) on
  std::vector<std::string> f;
  for (std::string token; fields >> token;) f.push_back(token);
  if (f.size() < 13) return s;
  const double tick = static_cast<double>(sysconf(_SC_CLK_TCK));
  s.statSeconds = (std::stod(f[11]) + std::stod(f[12])) / tick;  // fields 14 and 15
  const std::string taskDir = "/proc/" + std::to_string(pid) + "/task";
  if (DIR* dir = opendir(taskDir.c_str())) {
    while (dirent* e = readdir(dir)) {
      if (e->d_name[0] == '.') continue;
      std::ifstream sched(taskDir + "/" + e->d_name + "/schedstat");
      double ns = 0.0;
      if (sched >> ns) {
        s.schedNs += ns;
        ++s.threads;
      }
    }
    closedir(dir);
  }
  s.ok = true;
  return s;
}

/// A field of /proc/<pid>/status in kB ("VmRSS", "VmHWM"); -1 if it cannot be read.
inline long readStatusKiB(int pid, const std::string& field) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);) {
    if (line.compare(0, field.size() + 1, field + ":") == 0) {
      return std::stol(line.substr(field.size() + 1));
    }
  }
  return -1;
}

}  // namespace sf_bench
