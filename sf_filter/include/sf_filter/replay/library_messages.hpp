// The messages that librosbag and tf2 print through console_bridge while the offline replay
// reads a bag: each on one line of stderr, prefixed with the program's name, instead of
// console_bridge's two-line "Error: ... at line N in file.cpp". The TCPROS header parser that
// librosbag reuses for its record headers complains about a "TCPROS header" on a corrupt
// record; that message is dropped, because the replay's own error names the corrupt bag.
#pragma once

#include <console_bridge/console.h>

#include <cstring>
#include <iostream>
#include <string>
#include <utility>

namespace sf_filter {

class ReplayLibraryMessages : public console_bridge::OutputHandler {
 public:
  explicit ReplayLibraryMessages(std::string program) : program_(std::move(program)) {}

  void log(const std::string& text, console_bridge::LogLevel, const char* filename, int) override {
    if (filename != nullptr && std::strstr(filename, "cpp_common") != nullptr) return;
    std::string line = text;
    for (char& c : line) {
      if (c == '\n') c = ' ';
    }
    std::cerr << program_ << ": " << libraryOf(filename) << ": " << line << std::endl;
  }

 private:
  static std::string libraryOf(const char* filename) {
    if (filename == nullptr) return "a library";
    if (std::strstr(filename, "tf2") != nullptr) return "tf2";
    if (std::strstr(filename, "rosbag") != nullptr) return "rosbag";
    return filename;
  }

  std::string program_;
};

}  // namespace sf_filter
