// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The input points as the stages search them: read through the user's point map, checked,
// duplicates merged, in spatial order, with their spatial index.

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_INDEXED_INPUT_H
#define CGAL_SHARP_FEATURE_EXTRACTION_INTERNAL_INDEXED_INPUT_H

#include <CGAL/Sharp_feature_extraction/internal/Kernel_conversion.h>
#include <CGAL/Sharp_feature_extraction/internal/Point_index.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_sort.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

/// Copies the input points, rejecting non-finite coordinates with `std::invalid_argument`.
template <typename PointRange, typename PointMap>
std::vector<Vec3> read_input_points(const PointRange& points, PointMap point_map)
{
  std::vector<Vec3> out;
  std::size_t i = 0;
  for(const auto& item : points)
  {
    const Vec3 p = to_vec3(get(point_map, item));
    if(!p.allFinite())
      throw std::invalid_argument("Sharp feature extraction: input point " + std::to_string(i)
                                  + " has a non-finite coordinate (NaN or infinity)");
    out.push_back(p);
    ++i;
  }
  return out;
}

/// Reads `Vec3` points as kernel points, for CGAL's spatial sorting.
struct Vec3_as_point_map
{
  typedef std::size_t key_type;
  typedef CGAL::Simple_cartesian<double>::Point_3 value_type;
  typedef value_type reference;
  typedef boost::readable_property_map_tag category;
  const std::vector<Vec3>* points = nullptr;
  friend value_type get(const Vec3_as_point_map& m, std::size_t i)
  {
    const Vec3& p = (*m.points)[i];
    return value_type(p.x(), p.y(), p.z());
  }
};

/// Points with their spatial index, and the point that represents each input point.
struct Indexed_points
{
  /// The points, in spatial order.
  std::vector<Vec3> points;
  /// `position_of_input[j]` is the position in `points` of the point that represents input
  /// point `j`: itself (its first copy), or the point that represents it after a thinning.
  std::vector<std::size_t> position_of_input;
  Point_index index;

  /// The number of input points, copies included.
  std::size_t input_size() const { return position_of_input.size(); }
};

/// The distinct input points in double precision, in spatial (Hilbert curve) order, with their
/// spatial index: what stages 1 and 2 search. Neighbours in space are then neighbours in memory,
/// and consecutive queries visit the same part of the tree, which makes the neighbour searches
/// several times faster than in input order on large clouds.
///
/// Exact duplicates are merged: copies of a point add no surface information (a scanner writes
/// (0,0,0) for every ray without a return, and concatenated files repeat points), they would fill
/// neighbourhoods with one position and make fits degenerate, and a k-d tree over many coincident
/// points cannot split them (CGAL's builds one level per bucket: a stack overflow at ~50k copies).
/// The first copy in input order represents all of them; per-point outputs give every copy the
/// value of its representative, so a cloud and the same cloud with its points repeated give the
/// same curves.
struct Indexed_input : Indexed_points
{
  /// `input_index[i]` is the position in the input range of the first copy of `points[i]`.
  std::vector<std::size_t> input_index;
  /// When `points` are means (see `Sharp_feature_scales::search_fraction`): the points that
  /// they are the means of, with the point that represents each input point among them; stage
  /// 2 refines on them the surfaces it found on the means, and the patches are segmented on
  /// them. Null otherwise.
  std::unique_ptr<Indexed_points> refinement;

  /// Every input point (copies included) whose position is one of `positions`, ascending.
  std::vector<std::size_t> input_indices(const std::vector<std::size_t>& positions) const
  {
    std::vector<bool> selected(points.size(), false);
    for(std::size_t i : positions)
      selected[i] = true;
    std::vector<std::size_t> out;
    for(std::size_t j = 0; j < input_size(); ++j)
      if(selected[position_of_input[j]])
        out.push_back(j);
    return out;
  }

  /// The positions in `points` of the input points `indices`, ascending, each once.
  std::vector<std::size_t> positions(const std::vector<std::size_t>& indices) const
  {
    std::vector<std::size_t> out;
    out.reserve(indices.size());
    for(std::size_t j : indices)
      out.push_back(position_of_input[j]);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  /// `values` (one per point, in spatial order) in input order, copies included.
  template <typename FT>
  std::vector<FT> in_input_order(const std::vector<double>& values) const
  {
    std::vector<FT> out(input_size());
    for(std::size_t j = 0; j < input_size(); ++j)
      out[j] = FT(values[position_of_input[j]]);
    return out;
  }

  /// `values` (one per input point, in input order) in spatial order, each point taking the
  /// value of its first copy; zeros when `values` does not have one value per input point.
  template <typename FT>
  std::vector<double> in_spatial_order(const std::vector<FT>& values) const
  {
    std::vector<double> out(points.size(), 0.);
    if(values.size() == input_size())
      for(std::size_t i = 0; i < points.size(); ++i)
        out[i] = CGAL::to_double(values[input_index[i]]);
    return out;
  }
};

/// For every input point, the index of its first copy in input order (itself if it has no
/// earlier copy). The points are sorted by value with their indices (contiguous records: several
/// times faster than sorting indices that point into `points`), ties broken by index: a total
/// order, so the result is the same sequentially and in parallel.
template <typename ConcurrencyTag>
std::vector<std::size_t> first_copies(const std::vector<Vec3>& points)
{
  struct Indexed_point
  {
    double x, y, z;
    std::size_t index;
  };
  std::vector<Indexed_point> sorted(points.size());
  for(std::size_t j = 0; j < points.size(); ++j)
    sorted[j] = {points[j].x(), points[j].y(), points[j].z(), j};
  const auto before = [](const Indexed_point& p, const Indexed_point& q) {
    if(p.x != q.x) return p.x < q.x;
    if(p.y != q.y) return p.y < q.y;
    if(p.z != q.z) return p.z < q.z;
    return p.index < q.index;
  };
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
    tbb::parallel_sort(sorted.begin(), sorted.end(), before);
  else
#endif
    std::sort(sorted.begin(), sorted.end(), before);
  std::vector<std::size_t> first(points.size());
  for(std::size_t k = 0; k < sorted.size(); ++k)
  {
    const Indexed_point& p = sorted[k];
    const bool copy = k > 0 && p.x == sorted[k - 1].x && p.y == sorted[k - 1].y && p.z == sorted[k - 1].z;
    first[p.index] = copy ? first[sorted[k - 1].index] : p.index;
  }
  return first;
}

template <typename ConcurrencyTag, typename PointRange, typename NamedParameters>
void index_input_points(const PointRange& points, const NamedParameters& np, Indexed_input& out)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  std::vector<Vec3> read = read_input_points(points, NP_helper::get_const_point_map(points, np));
  const std::vector<std::size_t> first = first_copies<ConcurrencyTag>(read);
  out.input_index.clear();
  for(std::size_t j = 0; j < read.size(); ++j)
    if(first[j] == j)
      out.input_index.push_back(j);
  Vec3_as_point_map map;
  map.points = &read;
  // The median policy splits at medians: the order depends on the points only, never on
  // the number of threads.
  CGAL::hilbert_sort<ConcurrencyTag>(out.input_index.begin(), out.input_index.end(),
    CGAL::Spatial_sort_traits_adapter_3<CGAL::Simple_cartesian<double>, Vec3_as_point_map>(map),
    CGAL::Hilbert_sort_median_policy());
  out.points.resize(out.input_index.size());
  out.position_of_input.resize(read.size());
  for(std::size_t i = 0; i < out.input_index.size(); ++i)
  {
    out.points[i] = read[out.input_index[i]];
    out.position_of_input[out.input_index[i]] = i;
  }
  for(std::size_t j = 0; j < read.size(); ++j)
    if(first[j] != j)
      out.position_of_input[j] = out.position_of_input[first[j]];
  read = std::vector<Vec3>();
  out.index.template build<ConcurrencyTag>(out.points);
}

/// One step of SplitMix64 (Steele, Lea and Flood 2014): its increment (the golden ratio in 64
/// bits) and its two multipliers, which mix every input bit into every output bit.
inline std::uint64_t splitmix64(std::uint64_t state)
{
  constexpr std::uint64_t increment = 0x9E3779B97F4A7C15ull;
  constexpr std::uint64_t first_multiplier = 0xBF58476D1CE4E5B9ull, second_multiplier = 0x94D049BB133111EBull;
  std::uint64_t z = state + increment;
  z = (z ^ (z >> 30)) * first_multiplier;
  z = (z ^ (z >> 27)) * second_multiplier;
  return z ^ (z >> 31);
}

/// A number in [0, 1) drawn from the coordinates of `p` alone (SplitMix64 over their bits):
/// whether a point is kept by `thin_input()` then depends on the point, not on its position in
/// the cloud, so that a tile of the cloud keeps the points that the whole cloud keeps.
inline double sampling_value(const Vec3& p)
{
  // The top 53 bits of the hash, the mantissa of a double, scaled by 2^-53.
  constexpr int mantissa_bits = 53;
  const double scale = std::ldexp(1., -mantissa_bits);
  std::uint64_t h = 0;
  for(int axis = 0; axis < 3; ++axis)
  {
    const double x = p[axis] + 0.; // -0 becomes +0: equal points give equal bits
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    h = splitmix64(h ^ bits);
  }
  return double(h >> (64 - mantissa_bits)) * scale;
}

/// What `thin_input()` makes of the points it keeps.
enum class Kept_points
{
  /// They stay as they are.
  as_sampled,
  /// Each becomes the mean of the points it represents (itself included), and the points
  /// before the thinning become `Indexed_input::refinement`.
  means
};

/// Keeps the points of `input` whose `sampling_value()` is below `fraction`, in their spatial
/// order, with a new index; every other point (and its copies) is then represented by the
/// nearest kept point, as a copy is by its first. The kept points of `fraction` include those
/// of any smaller fraction. With `Kept_points::means`, each kept point then moves to the mean
/// of the points it represents. Returns false, leaving `input` as it is, when `fraction` keeps
/// every point or none.
template <typename ConcurrencyTag>
bool thin_input(double fraction, Indexed_input& input, Kept_points kept_points = Kept_points::as_sampled)
{
  // Marks a point whose representative is not known yet.
  constexpr std::size_t no_representative = std::size_t(-1);
  const std::size_t n = input.points.size();
  std::vector<std::size_t> kept_position(n, no_representative);
  std::vector<Vec3> kept;
  std::vector<std::size_t> kept_input_index;
  for(std::size_t i = 0; i < n; ++i)
    if(sampling_value(input.points[i]) < fraction)
    {
      kept_position[i] = kept.size();
      kept.push_back(input.points[i]);
      kept_input_index.push_back(input.input_index[i]);
    }
  if(kept.empty() || kept.size() == n)
    return false;
  std::vector<Vec3> all = std::move(input.points);
  input.points = std::move(kept);
  input.input_index = std::move(kept_input_index);
  input.index.template build<ConcurrencyTag>(input.points);
  Progress untracked;
  parallel_blocks<ConcurrencyTag>(n, untracked, [&](std::size_t first, std::size_t last) {
    std::vector<std::size_t> nearest;
    for(std::size_t i = first; i < last; ++i)
      if(kept_position[i] == no_representative)
      {
        input.index.nearest(all[i], 1, nearest);
        kept_position[i] = nearest.front();
      }
  });
  if(kept_points == Kept_points::means)
  {
    // Summed in the order of the points: the means do not depend on the thread count.
    std::vector<Vec3> sum(input.points.size(), Vec3::Zero());
    std::vector<std::size_t> count(input.points.size(), 0);
    for(std::size_t i = 0; i < n; ++i)
    {
      sum[kept_position[i]] += all[i];
      ++count[kept_position[i]];
    }
    for(std::size_t j = 0; j < input.points.size(); ++j)
      input.points[j] = sum[j] / double(count[j]);
    input.index.template build<ConcurrencyTag>(input.points);
    input.refinement.reset(new Indexed_points());
    input.refinement->points = std::move(all);
    input.refinement->position_of_input = input.position_of_input;
    input.refinement->index.template build<ConcurrencyTag>(input.refinement->points);
  }
  for(std::size_t& position : input.position_of_input)
    position = kept_position[position];
  return true;
}

/// Thins `input` as `scales` say: to their `sampled_fraction`, then to their
/// `search_fraction` with the kept points moved to means (see `Sharp_feature_scales`).
template <typename ConcurrencyTag, typename Scales>
void sample_input(const Scales& scales, Indexed_input& input)
{
  if(scales.sampled_fraction < 1)
    thin_input<ConcurrencyTag>(scales.sampled_fraction, input);
  if(scales.search_fraction < scales.sampled_fraction)
    thin_input<ConcurrencyTag>(scales.search_fraction, input, Kept_points::means);
}

/// The number of sampled points that a mean represents, on average (see
/// `Sharp_feature_scales::search_fraction`): `sampled_fraction / search_fraction`, 1 without means.
template <typename Scales>
double sampled_points_per_mean(const Scales& scales)
{
  return double(scales.sampled_fraction / scales.search_fraction);
}

/// The scales of the sampled points, from `scales`, which are those of their means (see
/// `Sharp_feature_scales::search_fraction`): a neighbourhood of the same radius holds
/// `sampled_points_per_mean()` times as many points, and the spacing is smaller by the square
/// root of that (on a surface, the spacing goes as the inverse square root of the density).
/// The noise and the other distances are those of the surfaces, whichever points sample them.
template <typename Scales>
Scales scales_of_sampled_points(const Scales& scales)
{
  const double per_mean = sampled_points_per_mean(scales);
  Scales sampled = scales;
  sampled.spacing = scales.spacing / std::sqrt(per_mean);
  sampled.candidate_neighbors = std::size_t(std::lround(double(scales.candidate_neighbors) * per_mean));
  sampled.rmls_neighbors = std::size_t(std::lround(double(scales.rmls_neighbors) * per_mean));
  sampled.search_fraction = scales.sampled_fraction;
  return sampled;
}

} // namespace internal
} // namespace Sharp_feature_extraction
} // namespace CGAL

#endif
