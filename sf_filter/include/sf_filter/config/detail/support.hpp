// C++17 helpers of the configuration layer that do not depend on the user's configuration:
// constexpr scanning of the stringized model expressions (to check x[i] / u[i] indices at
// compile time), topic-name handling and field-access helpers.
#pragma once

#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

namespace sf_config {
namespace detail {

constexpr bool isDigit(char c) { return c >= '0' && c <= '9'; }

constexpr bool isLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

constexpr bool isIdentifierChar(char c) { return isLetter(c) || isDigit(c) || c == '_'; }

/// Strips one pair of surrounding double quotes: topic names may be written as name or "name".
constexpr std::string_view unquote(std::string_view s) {
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') return s.substr(1, s.size() - 2);
  return s;
}

/// ROS graph resource name: starts with a letter, '/' or '~', then letters, digits, '_', '/'.
constexpr bool isValidTopicName(std::string_view s) {
  if (s.empty()) return false;
  if (!(isLetter(s[0]) || s[0] == '/' || s[0] == '~')) return false;
  for (std::size_t k = 1; k < s.size(); ++k) {
    if (!(isIdentifierChar(s[k]) || s[k] == '/')) return false;
    if (s[k] == '/' && s[k - 1] == '/') return false;
  }
  return true;
}

/// Index of the first element of names equal to names[i] (i itself if there is none before).
template <std::size_t K>
constexpr int firstIndexOf(const std::string_view (&names)[K], int i) {
  for (int j = 0; j < i; ++j) {
    if (names[j] == names[i]) return j;
  }
  return i;
}

/// Position right after the occurrence of the single-letter identifier `name` at position k
/// followed by `[` or `(`, or npos if there is no such occurrence at k.
constexpr std::size_t subscriptOpen(std::string_view expr, std::size_t k, char name) {
  if (expr[k] != name) return std::string_view::npos;
  if (k > 0) {
    const char before = expr[k - 1];
    if (isIdentifierChar(before) || before == '.') return std::string_view::npos;
    if (before == '>' && k > 1 && expr[k - 2] == '-') return std::string_view::npos;
  }
  std::size_t p = k + 1;
  while (p < expr.size() && expr[p] == ' ') ++p;
  if (p < expr.size() && (expr[p] == '[' || expr[p] == '(')) return p + 1;
  return std::string_view::npos;
}

/// Highest literal index i of the subscripts name[i] / name(i) in a stringized expression;
/// -1 if there is none. Subscripts that are not integer literals are not counted.
constexpr int maxIndexUsed(std::string_view expr, char name) {
  int highest = -1;
  for (std::size_t k = 0; k < expr.size(); ++k) {
    std::size_t p = subscriptOpen(expr, k, name);
    if (p == std::string_view::npos) continue;
    while (p < expr.size() && expr[p] == ' ') ++p;
    if (p >= expr.size() || !isDigit(expr[p])) continue;
    int value = 0;
    while (p < expr.size() && isDigit(expr[p])) value = value * 10 + (expr[p++] - '0');
    while (p < expr.size() &&
           (expr[p] == 'u' || expr[p] == 'U' || expr[p] == 'l' || expr[p] == 'L' || expr[p] == ' '))
      ++p;
    if (p < expr.size() && (expr[p] == ']' || expr[p] == ')') && value > highest) highest = value;
  }
  return highest;
}

/// True if the single-letter identifier `name` is used in a stringized expression.
constexpr bool usesIdentifier(std::string_view expr, char name) {
  for (std::size_t k = 0; k < expr.size(); ++k) {
    if (expr[k] != name) continue;
    const bool starts = k == 0 || !(isIdentifierChar(expr[k - 1]) || expr[k - 1] == '.');
    const bool ends = k + 1 == expr.size() || !isIdentifierChar(expr[k + 1]);
    if (starts && ends) return true;
  }
  return false;
}

/// Stands in for `u` inside generated functions that have no control input (the observation
/// model), so that a misuse is reported by the configuration's static_assert alone.
struct NoControlInput {
  constexpr double operator[](Eigen::Index) const { return 0.0; }
  constexpr double operator()(Eigen::Index) const { return 0.0; }
};

/// Converts a message field to double; non-numeric fields (already reported by a
/// static_assert of the configuration) give 0 instead of a second error.
template <class Field>
double toDouble(const Field& field) {
  if constexpr (std::is_convertible_v<const Field&, double>) {
    return static_cast<double>(field);
  } else {
    return 0.0;
  }
}

/// Base of the generated descriptors. If the configured message type cannot be declared
/// (typically its header is not #included), the compiler reports that, drops the descriptor's
/// own `using Message = <type>;`, and Message falls back to UnknownMessage here: the generated
/// checks skip UnknownMessage, so the compiler's error on the type is the only one.
struct UnknownMessage {};
struct DescriptorBase {
  using Message = UnknownMessage;
};

/// Base of the generated output descriptors: if the configured state index cannot be compiled
/// (e.g. a name instead of a number), the compiler reports it once and this 0 is used instead.
struct OutputDescriptorBase {
  static constexpr int configured_state_index = 0;
};

/// True if the message type has header.stamp (std_msgs/Header): it can be aligned by stamp.
template <class MessageT, class = void>
struct HasHeaderStamp : std::false_type {};
template <class MessageT>
struct HasHeaderStamp<MessageT, std::void_t<decltype(std::declval<const MessageT&>().header.stamp)>>
    : std::true_type {};

template <class Message>
constexpr bool isUnknownMessage() {
  return std::is_same_v<Message, UnknownMessage>;
}

/// Field status reported by the generated field detectors.
enum FieldStatus : int { kFieldMissing = 0, kFieldNotNumeric = 1, kFieldOk = 2 };

template <class T>
constexpr int fieldStatusOf() {
  return std::is_convertible_v<const T&, double> ? kFieldOk : kFieldNotNumeric;
}

}  // namespace detail
}  // namespace sf_config
