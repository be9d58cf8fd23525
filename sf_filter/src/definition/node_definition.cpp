#include "sf_filter/definition/node_definition.hpp"

#include <utility>

namespace sf_filter {

NodeDefinition::NodeDefinition() = default;
NodeDefinition::~NodeDefinition() = default;
NodeDefinition::NodeDefinition(const NodeDefinition&) = default;
NodeDefinition::NodeDefinition(NodeDefinition&&) noexcept = default;
NodeDefinition& NodeDefinition::operator=(const NodeDefinition&) = default;
NodeDefinition& NodeDefinition::operator=(NodeDefinition&&) noexcept = default;

std::string topicTypeClash(const std::string& resolved, const std::string& earlier,
                           const std::string& later) {
  if (earlier == later) return {};
  return "topic " + resolved + ": two configured topics resolve onto it (a remap?), one read as " +
         earlier + ", the other as " + later + "; a topic holds one message type";
}

void appendTopicReader(std::vector<TopicReader>& readers, TopicReader reader) {
  readers.push_back(std::move(reader));
}

}  // namespace sf_filter
