// Heap allocation counter for the benchmarks. Linking allocation_counter.cpp into a program
// replaces every global operator new (and, with glibc, malloc, calloc and realloc, since
// Eigen's dynamic matrices allocate with std::malloc rather than operator new) by versions that
// count. The counter is a plain integer: the benchmarks are single threaded.
#pragma once

#include <cstddef>

namespace sf_bench {

/// Heap allocations made by the program so far.
std::size_t heapAllocations();

}  // namespace sf_bench
