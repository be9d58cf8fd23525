// Tests of sf_wang_table2's command line and of its table: parsing, the errors that name the
// bad option, the paper's relative changes by hand and the measured table's bookkeeping.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "wang_table2/options.hpp"
#include "wang_table2/table.hpp"

namespace {

using namespace wang_table2;

std::string errorOf(const std::vector<std::string>& args) {
  try {
    parseOptions(args);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(Options, DefaultsAreThePapersParameters) {
  const Options o = parseOptions({});
  EXPECT_EQ(o.runs, 100);
  EXPECT_EQ(o.seed, 1u);
  EXPECT_EQ(o.parameters.omega, 0.001);
  EXPECT_EQ(o.parameters.fillSamples, 5);
  EXPECT_EQ(o.parameters.holdSamples, 5);
  EXPECT_EQ(o.parameters.differenceSteps, 5);
  EXPECT_EQ(o.parameters.kalmanR, 0.1);
  EXPECT_EQ(o.parameters.holdR, 1.0);
  EXPECT_EQ(o.parameters.fillR, 0.1);
  EXPECT_FALSE(o.help);
}

TEST(Options, EveryOptionIsRead) {
  const Options o = parseOptions(
      {"--runs",       "7",     "--seed",    "99",  "--duration",      "12.5", "--warmup", "1",
       "--omega",      "0.004", "--history", "3",   "--encoder-noise", "0.03", "--speed",  "0.5",
       "--difference", "2",     "--fill-r",  "0.02"});
  EXPECT_EQ(o.runs, 7);
  EXPECT_EQ(o.seed, 99u);
  EXPECT_EQ(o.parameters.duration, 12.5);
  EXPECT_EQ(o.parameters.warmup, 1.0);
  EXPECT_EQ(o.parameters.omega, 0.004);
  EXPECT_EQ(o.parameters.fillSamples, 3);
  EXPECT_EQ(o.parameters.holdSamples, 3);
  EXPECT_EQ(o.parameters.encoderNoiseDensity, 0.03);
  EXPECT_EQ(o.parameters.speedStd, 0.5);
  EXPECT_EQ(o.parameters.differenceSteps, 2);
  EXPECT_EQ(o.parameters.fillR, 0.02);
  EXPECT_TRUE(parseOptions({"--help"}).help);
}

TEST(Options, BadValuesNameTheOption) {
  EXPECT_EQ(errorOf({"--runs", "1"}), "--runs must be between 2 and 1000000, got 1");
  EXPECT_EQ(errorOf({"--runs", "ten"}), "--runs expects a number, got 'ten'");
  EXPECT_EQ(errorOf({"--runs", "2.5"}), "--runs expects a whole number, got '2.5'");
  EXPECT_EQ(errorOf({"--seed"}), "--seed needs a value");
  EXPECT_EQ(errorOf({"--history", "0"}), "--history must be between 1 and 16, got 0");
  EXPECT_EQ(errorOf({"--history", "17"}), "--history must be between 1 and 16, got 17");
  EXPECT_EQ(errorOf({"--difference", "0"}), "--difference must be between 1 and 1000, got 0");
  EXPECT_EQ(errorOf({"--fill-r", "0"}), "--fill-r must be positive, got 0");
  EXPECT_EQ(errorOf({"--frobnicate", "1"}), "unknown option '--frobnicate'");
  EXPECT_EQ(errorOf({"--frobnicate"}), "unknown option '--frobnicate'");
  EXPECT_EQ(errorOf({"--speed", "-1"}), "the speed std must not be negative");
  EXPECT_EQ(errorOf({"stray"}), "unexpected argument 'stray'");
  EXPECT_EQ(errorOf({"--duration", "1", "--warmup", "2"}),
            "the duration must be longer than the warm-up");
  // omega is checked by the fusion core's own FILL validation.
  EXPECT_NE(errorOf({"--omega", "0"}).find("FILL omega must be a positive number"),
            std::string::npos);
}

TEST(Table, PaperChangesByHand) {
  // Filling against the Kalman filter at sigma_u = 0.010 m: (0.00054 - 0.00068) / 0.00068
  // and (0.02328 - 0.02620) / 0.02620; the hold at 0.202 m: (0.00789 - 0.00708) / 0.00708.
  EXPECT_NEAR(paperChange(2, 0).variance, -0.20588, 1e-5);
  EXPECT_NEAR(paperChange(2, 0).rms, -0.11145, 1e-5);
  EXPECT_NEAR(paperChange(1, 4).variance, 0.11441, 1e-5);
  EXPECT_EQ(paperChange(0, 2).variance, 0.0);
}

/// A series whose variance and rms are known: {m - a, m + a} has variance a^2, rms^2 m^2 + a^2.
ErrorSeries series(double m, double a) {
  ErrorSeries e;
  e.add(m - a);
  e.add(m + a);
  return e;
}

TEST(Table, MeasuredTableAveragesRunsAndPairsThemWithTheKalmanFilter) {
  RunErrors first, second;
  for (std::size_t m = 0; m < kRows; ++m) {
    for (std::size_t c = 0; c < kColumns; ++c) {
      first[m][c] = series(0.0, 0.1 * (m + 1));   // variance 0.01 (m + 1)^2
      second[m][c] = series(0.0, 0.2 * (m + 1));  // variance 0.04 (m + 1)^2
    }
  }
  MeasuredTable t;
  t.addRun(first);
  t.addRun(second);
  EXPECT_EQ(t.runs(), 2u);
  EXPECT_NEAR(t.variance(2, 3).mean(), (0.09 + 0.36) / 2.0, 1e-15);
  EXPECT_NEAR(t.rms(1, 0).mean(), (0.2 + 0.4) / 2.0, 1e-15);
  // Row 2 against row 0: variances 9x on both runs -> +800 %; rms 3x -> +200 %.
  EXPECT_NEAR(t.varianceChange(2, 1).relative(), 8.0, 1e-12);
  EXPECT_NEAR(t.rmsChange(2, 1).relative(), 2.0, 1e-12);
  EXPECT_NEAR(t.rmsChange(0, 4).relative(), 0.0, 1e-15);
}

TEST(Table, PrintsEveryRowAndColumnBesideThePaper) {
  RunErrors run;
  for (auto& row : run) {
    for (auto& cell : row) cell = series(0.0, 0.05);
  }
  MeasuredTable t;
  t.addRun(run);
  run[2][0] = series(0.0, 0.04);
  t.addRun(run);
  std::ostringstream out;
  printTable(out, t);
  const std::string text = out.str();
  for (const char* part :
       {"sigma_u 0.010 m", "sigma_u 0.202 m", "Kalman filter  measured",
        "Multi-rate hold  measured", "Filling (FILL)  measured", "std. error",
        "change against the Kalman filter",
        // the paper's Kalman filter row and its filling change at 0.010 m (-20.6 %, -11.1 %)
        "0.00068   0.02620", "-20.6     -11.1"}) {
    EXPECT_NE(text.find(part), std::string::npos) << part << "\n" << text;
  }
  // The filling's variance at 0.010 m: (0.0025 + 0.0016) / 2 = 0.00205; change against the
  // Kalman filter's 0.0025: -18.0 %.
  EXPECT_NE(text.find("Filling (FILL)  measured           0.00205"), std::string::npos) << text;
  EXPECT_NE(text.find("-18.0"), std::string::npos) << text;
}

}  // namespace
