// Runs the attitude filter (sf_estimation/attitude_filter.hpp) over one IMU stream, for the
// BROAD comparison (tools/eval/broad_report.py, doc/broad.md).
//
//   sf_estimation_broad_attitude --rate 285.714 [--option value ...] < imu.csv > quaternions.csv
//
// Input: one sample a line, "gx,gy,gz,ax,ay,az,mx,my,mz" (rad/s, m/s^2, any field unit).
// Output: one line per input line, "w,x,y,z", the sensor-to-ENU estimate after that sample
// (with --print-bias followed by the gyro bias estimate bx,by,bz [rad/s]).
// The filter starts from the first sample's accelerometer and magnetometer.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <string>

#include "sf_estimation/attitude_filter.hpp"

namespace {

using estimation::AttitudeParameters;

struct Options {
  double rate = 0.0;
  double tiltStd = 0.05, headingStd = 0.2, biasStd = 0.01;  // P0 [rad], [rad/s]
  bool printBias = false;
  AttitudeParameters parameters;
};

[[noreturn]] void usage(const std::string& problem) {
  std::cerr
      << "sf_estimation_broad_attitude: " << problem << "\n"
      << "usage: sf_estimation_broad_attitude --rate HZ [--gyro-noise D] [--bias-walk D]\n"
      << "  [--accelerometer-noise RAD] [--acceleration-inflation E] [--acceleration-gate E]\n"
      << "  [--acceleration-time-constant S]\n"
      << "  [--magnetometer-noise RAD] [--field-norm-gate E] [--field-dip-gate RAD] "
         "[--no-magnetometer]\n"
      << "  [--print-bias]\n"
      << "  [--tilt-std RAD] [--heading-std RAD] [--bias-std RAD/S] < imu.csv > quaternions.csv\n";
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  AttitudeParameters& p = o.parameters;
  const std::map<std::string, double*> values = {
      {"--rate", &o.rate},
      {"--gyro-noise", &p.gyroNoise},
      {"--bias-walk", &p.biasWalk},
      {"--accelerometer-noise", &p.accelerometerNoise},
      {"--acceleration-inflation", &p.accelerationInflation},
      {"--acceleration-gate", &p.accelerationGate},
      {"--acceleration-time-constant", &p.accelerationTimeConstant},
      {"--magnetometer-noise", &p.magnetometerNoise},
      {"--field-norm-gate", &p.fieldNormGate},
      {"--field-dip-gate", &p.fieldDipGate},
      {"--tilt-std", &o.tiltStd},
      {"--heading-std", &o.headingStd},
      {"--bias-std", &o.biasStd}};
  for (int i = 1; i < argc; ++i) {
    const std::string name = argv[i];
    if (name == "--no-magnetometer" || name == "--print-bias") {
      (name == "--print-bias" ? o.printBias : p.useMagnetometer) = name == "--print-bias";
      continue;
    }
    const auto found = values.find(name);
    if (found == values.end()) usage("unknown option " + name);
    if (i + 1 >= argc) usage(name + " needs a value");
    char* end = nullptr;
    *found->second = std::strtod(argv[++i], &end);
    if (*end != '\0' || !(*found->second > 0.0))
      usage(name + " needs a positive number, not " + argv[i]);
  }
  if (!(o.rate > 0.0)) usage("--rate is required");
  return o;
}

bool readSample(Eigen::Matrix<double, 9, 1>& s) {
  char line[1024];
  if (!std::fgets(line, sizeof line, stdin)) return false;
  const int n = std::sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &s(0), &s(1), &s(2), &s(3),
                            &s(4), &s(5), &s(6), &s(7), &s(8));
  if (n != 9) usage(std::string("an input line is not 9 comma-separated numbers: ") + line);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  Eigen::Matrix<double, 9, 1> s;
  if (!readSample(s)) usage("no input");
  estimation::Matrix<6, 6> P0 = estimation::Matrix<6, 6>::Zero();
  P0.diagonal() << o.tiltStd * o.tiltStd, o.tiltStd * o.tiltStd, o.headingStd * o.headingStd,
      estimation::Vector<3>::Constant(o.biasStd * o.biasStd);
  const Eigen::Quaterniond q0 =
      estimation::AttitudeFilter::fromAccelerometerAndField(s.segment<3>(3), s.segment<3>(6));
  estimation::AttitudeFilter filter(o.parameters, q0, P0);
  const double dt = 1.0 / o.rate;
  do {
    filter.predict(s.head<3>(), dt);
    filter.correctGravity(s.segment<3>(3), dt);
    filter.correctField(s.segment<3>(6));
    const Eigen::Quaterniond q = filter.orientation();
    std::printf("%.9f,%.9f,%.9f,%.9f", q.w(), q.x(), q.y(), q.z());
    if (o.printBias)
      std::printf(",%.9f,%.9f,%.9f", filter.bias()(0), filter.bias()(1), filter.bias()(2));
    std::printf("\n");
  } while (readSample(s));
  return 0;
}
