#include "sf_estimation/errors.hpp"

namespace estimation {

void rejectStep(const std::string& method, const char* reason) {
  throw NumericalError(method + ": " + reason + "; step rejected");
}

}  // namespace estimation
