// Smoke test of the sf_wang_table2 command: it runs with a tiny run count, prints the table
// with every row and column and the run count, and refuses a bad option with exit status 2.
// SF_WANG_TABLE2_EXE is the built command's path (set by CMakeLists.txt).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <regex>
#include <string>

namespace {

struct Result {
  int status = -1;
  std::string output;
};

Result run(const std::string& arguments) {
  Result r;
  const std::string command = std::string(SF_WANG_TABLE2_EXE) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  char buffer[4096];
  for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) r.output.append(buffer, n);
  const int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

TEST(WangTable2Command, PrintsTheTableWithATinyRunCount) {
  const Result r = run("--runs 2 --duration 1.5 --warmup 0.5 --seed 4");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("2 runs x 1.5 s"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("seeds 4..5"), std::string::npos) << r.output;
  for (const char* part : {"sigma_u 0.010 m", "sigma_u 0.049 m", "sigma_u 0.099 m",
                           "sigma_u 0.150 m", "sigma_u 0.202 m"}) {
    EXPECT_NE(r.output.find(part), std::string::npos) << part;
  }
  // Each measured row: the label and ten finite positive numbers (variance, rms per column).
  const std::string number = R"(\s+0\.\d{5})";
  std::string tenNumbers;
  for (int i = 0; i < 10; ++i) tenNumbers += number;
  for (const char* method : {"Kalman filter", "Multi-rate hold", "Filling \\(FILL\\)"}) {
    const std::regex row(std::string(method) + "  measured" + tenNumbers + "\\n");
    EXPECT_TRUE(std::regex_search(r.output, row)) << method << "\n" << r.output;
  }
  EXPECT_TRUE(std::regex_search(r.output, std::regex(R"(\n2 runs in \d+\.\d s\n)"))) << r.output;
}

TEST(WangTable2Command, BadOptionExitsWithTwoAndNamesIt) {
  const Result r = run("--runs 1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("--runs must be between 2 and 1000000, got 1"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("usage: sf_wang_table2"), std::string::npos) << r.output;
}

}  // namespace
