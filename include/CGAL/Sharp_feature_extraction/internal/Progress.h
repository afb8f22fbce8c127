// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_PROGRESS_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_PROGRESS_H

#include <CGAL/for_each.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// Maps the progress of one stage to a sub-interval [begin, end] of the whole run and forwards
/// it to the user's callback. Once the callback has returned false, every later report fails.
class Progress
{
public:
  typedef std::function<bool(double)> Callback;

  Progress(const Callback& callback = Callback(), double begin = 0, double end = 1)
    : m_callback(callback), m_begin(begin), m_end(end)
  {}

  /// The sub-range [a, b] (fractions of this range) as a new reporter.
  Progress sub(double a, double b) const
  {
    Progress p(m_callback, m_begin + a * (m_end - m_begin), m_begin + b * (m_end - m_begin));
    p.m_cancelled = m_cancelled;
    return p;
  }

  /// Reports `fraction` of this range; returns false if the user asked to stop.
  bool report(double fraction)
  {
    if(*m_cancelled)
      return false;
    if(m_callback && !m_callback(m_begin + (std::min)(1., (std::max)(0., fraction)) * (m_end - m_begin)))
      *m_cancelled = true;
    return !*m_cancelled;
  }

  bool cancelled() const { return *m_cancelled; }

private:
  Callback m_callback;
  double m_begin, m_end;
  std::shared_ptr<bool> m_cancelled = std::make_shared<bool>(false);
};

/// Calls `body(first, last)` on consecutive blocks of [0, n), in parallel when `ConcurrencyTag`
/// allows it, reporting progress between rounds of blocks on the calling thread. The body must
/// only write to per-index output, so that the result does not depend on the thread count.
/// Returns false if the callback cancelled the loop.
template <typename ConcurrencyTag, typename Body>
bool parallel_blocks(std::size_t n, Progress& progress, const Body& body)
{
  // About `blocks_per_loop` blocks (enough to balance the threads; a block is a task), of
  // at least `smallest_block` indices (so that a task outweighs its scheduling), run
  // `blocks_per_round` at a time between two progress reports (often enough for a progress
  // bar and a prompt cancel, rarely enough to keep the threads busy).
  constexpr std::size_t smallest_block = 64, blocks_per_loop = 256, blocks_per_round = 16;
  const std::size_t block_size = (std::max<std::size_t>)(smallest_block, n / blocks_per_loop + 1);
  const std::size_t blocks = (n + block_size - 1) / block_size;
  std::vector<std::size_t> round;
  for(std::size_t first_block = 0; first_block < blocks; first_block += blocks_per_round)
  {
    round.clear();
    for(std::size_t b = first_block; b < (std::min)(blocks, first_block + blocks_per_round); ++b)
      round.push_back(b);
    CGAL::for_each<ConcurrencyTag>(round, [&](std::size_t b) -> bool {
      body(b * block_size, (std::min)(n, (b + 1) * block_size));
      return true;
    });
    if(!progress.report(double((std::min)(blocks, first_block + blocks_per_round)) / double(blocks)))
      return false;
  }
  return progress.report(1.);
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
