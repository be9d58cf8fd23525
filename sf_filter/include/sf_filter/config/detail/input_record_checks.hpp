// Compile-time helpers of the INPUTS records' checks (input_records.hpp): a record name must be
// an identifier and unique, an option must be given once.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string_view>

namespace sf_config::input_records {

/// True if `name` is a C++ identifier: letters, digits and '_', not starting with a digit.
constexpr bool isIdentifier(std::string_view name) {
  if (name.empty() || (name[0] >= '0' && name[0] <= '9')) return false;
  for (const char c : name) {
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    if (!letter && !(c >= '0' && c <= '9')) return false;
  }
  return true;
}

/// How often `value` occurs among the first `end` entries of `values` (so that a duplicate is
/// reported once, at its second occurrence).
template <class Range, class T>
constexpr int countBefore(const Range& values, int end, const T& value) {
  int k = 0, position = 0;
  for (const auto& v : values) {
    if (position++ < end && v == value) ++k;
  }
  return k;
}
template <std::size_t N>
constexpr int countBefore(const std::string_view (&values)[N], int end, std::string_view value) {
  return countBefore<const std::string_view(&)[N], std::string_view>(values, end, value);
}

}  // namespace sf_config::input_records
