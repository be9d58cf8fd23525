#include "sf_estimation/angles.hpp"

#include <algorithm>

namespace estimation {

void requireAngleIndices(const std::vector<Index>& indices, Index size, const std::string& method,
                         const std::string& what) {
  std::vector<bool> listed(static_cast<std::size_t>(std::max<Index>(size, 0)), false);
  for (const Index i : indices) {
    if (i < 0 || i >= size) {
      throw ParameterError(method + ": angle " + what + " index " + std::to_string(i) +
                           " is out of range [0, " + std::to_string(size) + ")");
    }
    if (listed[static_cast<std::size_t>(i)]) {
      throw ParameterError(method + ": angle " + what + " index " + std::to_string(i) +
                           " is listed twice");
    }
    listed[static_cast<std::size_t>(i)] = true;
  }
}

}  // namespace estimation
