// The detection idiom, once: IsDetected<Op, T> is true when Op<T> names a type, e.g. when a
// filter has a member or sf_estimation has a function for it. Each capability the core asks a
// filter about is then one alias template of the expression it needs.
#pragma once

#include <type_traits>

namespace sf_filter {

namespace detail {
template <template <class> class Op, class T, class = void>
struct Detection : std::false_type {};
template <template <class> class Op, class T>
struct Detection<Op, T, std::void_t<Op<T>>> : std::true_type {};
}  // namespace detail

/// std::true_type when Op<T> is well formed, std::false_type otherwise.
template <template <class> class Op, class T>
using IsDetected = detail::Detection<Op, T>;

}  // namespace sf_filter
