// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Memory measurements for the benchmark programs.
//
// Heap: memory_tracking.cpp replaces the global operator new/delete of the program it is
// linked into and keeps the bytes currently allocated and their peak, so that the peak of
// one stage can be read by resetting the peak before the stage. Allocations that bypass
// operator new (malloc from C code, TBB's scalable allocator) are not counted: the process
// peak resident set size (getrusage) is reported next to it as the all-inclusive figure.

#ifndef SFE_BENCHMARK_MEMORY_TRACKING_H
#define SFE_BENCHMARK_MEMORY_TRACKING_H

#include <cstddef>

namespace sfe_bench {

/// Bytes currently allocated through operator new.
std::size_t heap_bytes_in_use();
/// Largest value of `heap_bytes_in_use()` since the last `reset_heap_peak()`.
std::size_t heap_peak_bytes();
/// Starts a new peak measurement from the current usage.
void reset_heap_peak();
/// Peak resident set size of this process so far (getrusage), in bytes.
std::size_t process_peak_rss_bytes();

} // namespace sfe_bench

#endif // SFE_BENCHMARK_MEMORY_TRACKING_H
