// Runs Armesto's multi-rate inertial+vision filter (models/armesto_multi_rate.hpp) over one
// stream sampled every period, for the reproduction of the paper on BROAD
// (tools/eval/armesto_report.py, doc/armesto.md).
//
//   sf_estimation_armesto_fusion --filter ekf|ukf [--no-vision] [--option value ...]
//       < stream.csv > estimates.csv
//
// Input: one period a line, "ax,ay,az,gx,gy,gz,seen,px,py,pz,qw,qx,qy,qz": the IMU sample
// (m/s^2, rad/s), 1 when a vision frame (position [m], quaternion sensor to ENU) arrived in
// this period, else 0 (its numbers are then ignored). The first line must have a frame: the
// filter starts from it, at rest, with the line's gyro as its angular velocity.
// Output: one line per input line, "px,py,pz,qw,qx,qy,qz" (the estimate after that line;
// with --print-bias followed by the accelerometer bias; --ukf-alpha sets UKF-M's three
// sigma-point spreads, 1e-3 by default). On stderr at the end: "cpu_per_step_us
// X", the process CPU time of the filter's steps alone. A step the filter refuses
// (non-finite, a failed covariance root) ends the run with status 3 and "diverged at line N".
#include <time.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>

#include <Eigen/Geometry>

#include "sf_estimation/manifold_extended_kalman_filter.hpp"
#include "sf_estimation/manifold_unscented_kalman_filter.hpp"
#include "sf_estimation/models/armesto_multi_rate.hpp"

namespace {

namespace am = estimation::armesto;
using estimation::Matrix;
using estimation::Vector;
using Line = Eigen::Matrix<double, 14, 1>;

struct Options {
  std::string filter;
  bool vision = true, printBias = false;
  double period = 0.01, gravity = 9.81;
  double ukfAlpha = 1e-3;  // the three sigma-point spreads of UKF-M
  double velocityStd = 0.1, accelerationStd = 1.0, biasStd = 0.1;  // P0 [m/s, m/s^2, m/s^2]
  am::Noise noise;
};

[[noreturn]] void usage(const std::string& problem) {
  std::cerr
      << "sf_estimation_armesto_fusion: " << problem << "\n"
      << "usage: sf_estimation_armesto_fusion --filter ekf|ukf [--no-vision] [--print-bias]\n"
      << "  [--period S] [--gravity G] [--r-acc V] [--r-gyro V] [--r-pos V] [--r-quat V]\n"
      << "  [--q-jerk V] [--q-alpha V] [--q-bias V] [--velocity-std S]\n"
      << "  [--acceleration-std S] [--bias-std S] [--ukf-alpha A] < stream.csv > estimates.csv\n";
  std::exit(2);
}

double positiveNumber(const std::string& name, const char* text) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (*end != '\0' || !(value > 0.0)) usage(name + " needs a positive number, not " + text);
  return value;
}

Options parse(int argc, char** argv) {
  Options o;
  am::Noise& n = o.noise;
  const std::map<std::string, double*> values = {{"--period", &o.period},
                                                 {"--gravity", &o.gravity},
                                                 {"--r-acc", &n.accelerometer},
                                                 {"--r-gyro", &n.gyro},
                                                 {"--r-pos", &n.position},
                                                 {"--r-quat", &n.quaternion},
                                                 {"--q-jerk", &n.jerk},
                                                 {"--q-alpha", &n.angularAcceleration},
                                                 {"--q-bias", &n.biasRate},
                                                 {"--velocity-std", &o.velocityStd},
                                                 {"--acceleration-std", &o.accelerationStd},
                                                 {"--bias-std", &o.biasStd},
                                                 {"--ukf-alpha", &o.ukfAlpha}};
  for (int i = 1; i < argc; ++i) {
    const std::string name = argv[i];
    if (name == "--no-vision") {
      o.vision = false;
    } else if (name == "--print-bias") {
      o.printBias = true;
    } else if (i + 1 >= argc) {
      usage(name + " needs a value");
    } else if (name == "--filter") {
      o.filter = argv[++i];
    } else if (values.count(name) == 0) {
      usage("unknown option " + name);
    } else {
      *values.at(name) = positiveNumber(name, argv[++i]);
    }
  }
  if (o.filter != "ekf" && o.filter != "ukf") usage("--filter must be ekf or ukf");
  return o;
}

bool readLine(Line& s) {
  char text[2048];
  if (!std::fgets(text, sizeof text, stdin)) return false;
  int n = 0, used = 0;
  const char* at = text;
  while (n < 14 && std::sscanf(at, "%lf%n", &s(n), &used) == 1) {
    at += used;
    ++n;
    if (*at == ',') ++at;
  }
  if (n != 14) usage(std::string("an input line is not 14 comma-separated numbers: ") + text);
  return true;
}

double cpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

/// The start: the first frame's pose, at rest, the first gyro sample as the angular velocity;
/// P0 from the vision noise for the pose, the gyro noise for the rate.
template <class Filter, class... FilterOptions>
Filter start(const Options& o, const Line& first, const FilterOptions&... options) {
  if (first(6) == 0.0) usage("the first line must carry a vision frame");
  Vector<19> x0 = Vector<19>::Zero();
  x0.head<3>() = first.segment<3>(7);
  x0.segment<4>(am::kQ) = first.tail<4>().normalized();
  x0.tail<3>() = first.segment<3>(3);
  Vector<18> p0;
  p0 << Vector<3>::Constant(o.noise.position), Vector<3>::Constant(o.velocityStd * o.velocityStd),
      Vector<3>::Constant(o.accelerationStd * o.accelerationStd),
      Vector<3>::Constant(o.biasStd * o.biasStd), Vector<3>::Constant(4.0 * o.noise.quaternion),
      Vector<3>::Constant(o.noise.gyro);
  return Filter(o.noise, x0, Matrix<18, 18>(p0.asDiagonal()), o.period, o.gravity, options...);
}

template <class Filter>
void print(const Options& o, const Filter& filter) {
  const Vector<19>& x = filter.state();
  std::printf("%.9f,%.9f,%.9f,%.9f,%.9f,%.9f,%.9f", x(0), x(1), x(2), x(12), x(13), x(14), x(15));
  if (o.printBias) std::printf(",%.9f,%.9f,%.9f", x(9), x(10), x(11));
  std::printf("\n");
}

template <template <class> class Kind, class... FilterOptions>
int run(const Options& o, const FilterOptions&... options) {
  using Filter = am::MultiRateFilter<Kind>;
  Line s;
  if (!readLine(s)) usage("no input");
  Filter filter = start<Filter>(o, s, options...);
  print(o, filter);
  double cpu = 0.0;
  long steps = 0;
  for (long line = 2; readLine(s); ++line, ++steps) {
    const double before = cpuSeconds();
    try {
      if (o.vision && s(6) != 0.0) {
        filter.step(s.head<6>(), s.tail<7>());
      } else {
        filter.step(s.head<6>());
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "diverged at line %ld: %s\n", line, e.what());
      return 3;
    }
    cpu += cpuSeconds() - before;
    print(o, filter);
  }
  std::fprintf(stderr, "cpu_per_step_us %.3f\n", steps > 0 ? 1e6 * cpu / steps : 0.0);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  if (o.filter == "ekf") return run<estimation::ManifoldExtendedKalmanFilter>(o);
  if (!(o.ukfAlpha <= 1.0)) usage("--ukf-alpha must be in (0, 1]");
  const estimation::ManifoldUnscentedParameters spread{o.ukfAlpha, o.ukfAlpha, o.ukfAlpha};
  return run<estimation::ManifoldUnscentedKalmanFilter>(o, spread);
}
