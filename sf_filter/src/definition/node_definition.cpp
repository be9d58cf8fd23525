#include "sf_filter/definition/node_definition.hpp"

#include <utility>

namespace sf_filter {

NodeDefinition::NodeDefinition() = default;
NodeDefinition::~NodeDefinition() = default;
NodeDefinition::NodeDefinition(const NodeDefinition&) = default;
NodeDefinition::NodeDefinition(NodeDefinition&&) noexcept = default;
NodeDefinition& NodeDefinition::operator=(const NodeDefinition&) = default;
NodeDefinition& NodeDefinition::operator=(NodeDefinition&&) noexcept = default;

void appendTopicReader(std::vector<TopicReader>& readers, TopicReader reader) {
  readers.push_back(std::move(reader));
}

}  // namespace sf_filter
