#include "sf_filter/tuning/tuned_parameters_file.hpp"

#include <cstdio>
#include <set>

#include <yaml-cpp/yaml.h>

#include "sf_filter/replay/yaml_parameters.hpp"

namespace sf_filter {

std::string yamlFloat(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.10g", value);
  std::string s = text;
  if (s.find_first_of(".na") != std::string::npos) return s;  // has a '.', or nan / inf
  const std::size_t e = s.find('e');
  return e == std::string::npos ? s + ".0" : s.insert(e, ".0");
}

namespace {

std::string matrixYaml(const Eigen::MatrixXd& m) {
  std::string text = "[";
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    text += r ? ",\n  [" : "[";
    for (Eigen::Index c = 0; c < m.cols(); ++c) text += (c ? ", " : "") + yamlFloat(m(r, c));
    text += "]";
  }
  return text + "]";
}

}  // namespace

std::string tunedParametersYaml(const std::vector<std::string>& comment,
                                const FilterParameters& tuned, const std::vector<FreeEntry>& free,
                                double estimationPeriodSeconds, const std::string& baseParams) {
  std::set<std::string> written{"estimation_period", "frequency"};
  std::string text;
  for (const std::string& line : comment) text += "# " + line + "\n";
  // The period the noise was identified at: Q (and the header's T-dependent entries) hold for
  // it alone. ~frequency would say the same and both are refused, so it is not copied.
  text += "estimation_period: " + yamlFloat(estimationPeriodSeconds) + "\n";
  const struct {
    const char* matrix;
    const char* parameter;
    const Eigen::MatrixXd& value;
  } matrices[] = {{"Q", "process_noise_covariance", tuned.process_noise_covariance},
                  {"R", "measurement_noise_covariance", tuned.measurement_noise_covariance},
                  {"P0", "initial_error_covariance", tuned.initial_error_covariance}};
  for (const auto& m : matrices) {
    bool isFree = false;
    for (const FreeEntry& f : free) isFree = isFree || f.matrix == m.matrix;
    if (!isFree) continue;
    text += std::string(m.parameter) + ": " + matrixYaml(m.value) + "\n";
    written.insert(m.parameter);
  }
  if (!baseParams.empty()) {
    const YAML::Node base = loadParameterFile(baseParams);
    if (base.IsMap()) {
      for (const auto& kv : base) {
        const std::string key = kv.first.as<std::string>();
        if (written.count(key)) continue;
        YAML::Emitter out;  // scalars keep their text, so numbers stay as the user wrote them
        out << YAML::BeginMap << YAML::Key << key << YAML::Value << YAML::Flow << kv.second
            << YAML::EndMap;
        text += std::string(out.c_str()) + "\n";
      }
    }
  }
  return text;
}

}  // namespace sf_filter
