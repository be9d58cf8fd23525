// What every configuration check includes that no configuration header changes: the standard
// library, Eigen and Boost.Preprocessor headers of sf_filter/config/. check_config_errors.py
// precompiles it once per run and force-includes it before each case's header: parsing these
// was 90 % of a case's compile (1.2 of 1.4 s), for nearly 200 cases.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <boost/preprocessor.hpp>
