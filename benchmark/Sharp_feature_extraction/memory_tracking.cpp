// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Counting replacements of the global allocation functions (see memory_tracking.h).
// malloc_usable_size gives the size on release, so sized and unsized deletes agree.

#include "memory_tracking.h"

#include <atomic>
#include <cstdlib>
#include <new>

#include <malloc.h>
#include <sys/resource.h>

namespace {

std::atomic<std::size_t> bytes_in_use{0};
std::atomic<std::size_t> peak_bytes{0};

void count_allocation(void* p)
{
  const std::size_t now = bytes_in_use.fetch_add(malloc_usable_size(p), std::memory_order_relaxed) +
                          malloc_usable_size(p);
  std::size_t peak = peak_bytes.load(std::memory_order_relaxed);
  while(now > peak && !peak_bytes.compare_exchange_weak(peak, now, std::memory_order_relaxed))
  {
  }
}

void* counted_malloc(std::size_t size)
{
  void* p = std::malloc(size == 0 ? 1 : size);
  if(p != nullptr)
    count_allocation(p);
  return p;
}

void* counted_aligned_alloc(std::size_t size, std::size_t alignment)
{
  if(alignment < sizeof(void*))
    alignment = sizeof(void*);
  void* p = nullptr;
  if(posix_memalign(&p, alignment, size == 0 ? 1 : size) != 0)
    return nullptr;
  count_allocation(p);
  return p;
}

void counted_free(void* p) noexcept
{
  if(p == nullptr)
    return;
  bytes_in_use.fetch_sub(malloc_usable_size(p), std::memory_order_relaxed);
  std::free(p);
}

} // namespace

namespace sfe_bench {

std::size_t heap_bytes_in_use() { return bytes_in_use.load(); }
std::size_t heap_peak_bytes() { return peak_bytes.load(); }
void reset_heap_peak() { peak_bytes.store(bytes_in_use.load()); }
std::size_t process_peak_rss_bytes()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return std::size_t(usage.ru_maxrss) * 1024; // Linux reports kilobytes
}

} // namespace sfe_bench

void* operator new(std::size_t size)
{
  void* p = counted_malloc(size);
  if(p == nullptr)
    throw std::bad_alloc();
  return p;
}
void* operator new[](std::size_t size) { return operator new(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return counted_malloc(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return counted_malloc(size); }
void* operator new(std::size_t size, std::align_val_t alignment)
{
  void* p = counted_aligned_alloc(size, std::size_t(alignment));
  if(p == nullptr)
    throw std::bad_alloc();
  return p;
}
void* operator new[](std::size_t size, std::align_val_t alignment) { return operator new(size, alignment); }
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept
{
  return counted_aligned_alloc(size, std::size_t(alignment));
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept
{
  return counted_aligned_alloc(size, std::size_t(alignment));
}

void operator delete(void* p) noexcept { counted_free(p); }
void operator delete[](void* p) noexcept { counted_free(p); }
void operator delete(void* p, std::size_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::size_t) noexcept { counted_free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { counted_free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { counted_free(p); }
void operator delete(void* p, std::align_val_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { counted_free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { counted_free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { counted_free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { counted_free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { counted_free(p); }
