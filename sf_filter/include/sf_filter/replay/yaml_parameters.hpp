// The node's private parameters from a YAML file, for the offline replay's --params: the
// same file that `rosparam load` (or filter.launch's `params`) gives the online node, read
// with yaml-cpp and converted to XmlRpc values, so that ros_parameters.hpp parses and checks
// it with the same code as the node's parameter server values.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>
#include <yaml-cpp/yaml.h>

#include "sf_filter/node/ros_parameters.hpp"

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

/// The private parameters of a YAML file: a dictionary of parameter names and values, as
/// `rosparam load FILE /node_name` takes it.
class YamlParameterSource final : public ParameterSource {
 public:
  explicit YamlParameterSource(const std::string& path) {
    YAML::Node root;
    try {
      root = YAML::LoadFile(path);
    } catch (const YAML::Exception& e) {
      throw ParameterOverrideError("cannot read parameter file " + path + ": " + e.what());
    }
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
