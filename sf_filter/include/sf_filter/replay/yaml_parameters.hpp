// The node's private parameters from a YAML file, for the offline replay's --params: the
// same file that `rosparam load` (or filter.launch's `params`) gives the online node, read
// with yaml-cpp and converted to XmlRpc values, so that ros_parameters.hpp parses and checks
// it with the same code as the node's parameter server values.
#pragma once

#include <sys/stat.h>

#include <cerrno>
#include <cstddef>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>
#include <yaml-cpp/yaml.h>

#include "sf_filter/io/ros_parameters.hpp"

namespace sf_filter {

namespace yaml_detail {

/// A YAML value as rosparam would store it: plain scalars as booleans, integers or numbers
/// where they read as such (.inf and .nan included), quoted scalars as strings.
inline XmlRpc::XmlRpcValue toXmlRpc(const YAML::Node& node, const std::string& where) {
  switch (node.Type()) {
    case YAML::NodeType::Scalar: {
      if (node.Tag() != "!") {  // a plain scalar
        bool b = false;
        if (YAML::convert<bool>::decode(node, b)) return XmlRpc::XmlRpcValue(b);
        int i = 0;
        if (YAML::convert<int>::decode(node, i)) return XmlRpc::XmlRpcValue(i);
        double d = 0.0;
        if (YAML::convert<double>::decode(node, d)) return XmlRpc::XmlRpcValue(d);
      }
      return XmlRpc::XmlRpcValue(node.Scalar());
    }
    case YAML::NodeType::Sequence: {
      XmlRpc::XmlRpcValue list;
      list.setSize(static_cast<int>(node.size()));
      for (std::size_t k = 0; k < node.size(); ++k) {
        list[static_cast<int>(k)] = toXmlRpc(node[k], where + " entry " + std::to_string(k));
      }
      return list;
    }
    case YAML::NodeType::Map: {
      XmlRpc::XmlRpcValue map;
      map.begin();  // an empty struct
      for (const auto& kv : node) {
        const std::string key = kv.first.as<std::string>();
        map[key] = toXmlRpc(kv.second, where + "/" + key);
      }
      return map;
    }
    default:
      throw ParameterOverrideError(where + ": no value");
  }
}

}  // namespace yaml_detail

/// The largest --params file read: a node's private parameters are a few kB (the shipped
/// tuned files about 1 kB; three full 30x30 matrices about 60 kB). Parsed, a file costs up
/// to about 260 bytes of memory per byte (a long list of numbers; doc/evaluation.md): 100 MB
/// took 105 s and 12 GB, 256 KiB takes 0.8 s and 80 MB.
constexpr std::size_t kMaxParameterFileBytes = 256 * 1024;

/// The YAML document of parameter file `path`, read up to kMaxParameterFileBytes and no
/// further (a device or a FIFO as well); refuses a directory, a larger file and bad YAML,
/// naming the file.
inline YAML::Node loadParameterFile(const std::string& path) {
  const std::string name = "parameter file " + path;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
    throw ParameterOverrideError(name + " is a directory, not a YAML file");
  }
  std::ifstream in(path, std::ios::binary);
  std::string text(kMaxParameterFileBytes + 1, '\0');
  if (in) in.read(&text[0], static_cast<std::streamsize>(text.size()));
  if (!in && !in.eof()) {
    throw ParameterOverrideError("cannot read " + name + ": " + std::strerror(errno));
  }
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxParameterFileBytes) {
    throw ParameterOverrideError(name + " is larger than " +
                                 std::to_string(kMaxParameterFileBytes / 1024) +
                                 " KiB, the limit for a node's private parameters (a few kB)");
  }
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ParameterOverrideError("cannot read " + name + ": " + e.what());
  }
}

/// The private parameters of a YAML file: a dictionary of parameter names and values, as
/// `rosparam load FILE /node_name` takes it.
class YamlParameterSource final : public ParameterSource {
 public:
  explicit YamlParameterSource(const std::string& path) {
    const YAML::Node root = loadParameterFile(path);
    if (root.IsNull()) return;  // an empty file: no parameters
    if (!root.IsMap()) {
      throw ParameterOverrideError("parameter file " + path +
                                   ": expected a dictionary of private parameters");
    }
    for (const auto& kv : root) {
      const std::string name = kv.first.as<std::string>();
      values_[name] = yaml_detail::toXmlRpc(kv.second, "parameter ~" + name);
      names_.push_back(name);
    }
  }
  bool get(const std::string& name, XmlRpc::XmlRpcValue& value) const override {
    const auto it = values_.find(name);
    if (it == values_.end()) return false;
    value = it->second;
    return true;
  }
  std::vector<std::string> names() const override { return names_; }

 private:
  std::map<std::string, XmlRpc::XmlRpcValue> values_;
  std::vector<std::string> names_;
};

}  // namespace sf_filter
