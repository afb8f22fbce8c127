// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The extension `sharp_features._sharp_features`, which the package `sharp_features` re-exports:
// `CGAL::extract_sharp_features()` on a NumPy array.
//
// The points are read in place (a C-contiguous float64 array is wrapped by a point map over its
// buffer, other arrays are converted once), the computation runs without the GIL, and the
// progress callback takes the GIL back only for the user's function and the signal check.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features_in_tiles.h>
#include <CGAL/Sharp_feature_extraction/IO/write_PLY_feature_curves.h>
#include <CGAL/Sharp_feature_extraction/IO/write_polylines.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>

#include <boost/property_map/property_map.hpp>
#include <boost/range/counting_range.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl/filesystem.h>

#include "sharp_features_docstrings.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace py = pybind11;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Sharp_features<Kernel> Features;
typedef py::array_t<double, py::array::c_style | py::array::forcecast> Point_array;
namespace sfe_internal = CGAL::Sharp_feature_extraction::internal;

/// Coordinates of a point: the columns of the input array.
constexpr py::ssize_t dimension = 3;
/// A feature curve lies where two smooth surfaces meet: each vertex has a normal of each.
constexpr py::ssize_t surfaces_along_a_curve = 2;

// ---------------------------------------------------------------------------------------------
// Input

/// Reads row `i` of an (N, 3) C-contiguous float64 buffer as a kernel point: the library
/// iterates over the indices 0..N-1 and reads the array through this map, without a copy.
struct Array_point_map
{
  typedef std::size_t key_type;
  typedef Kernel::Point_3 value_type;
  typedef value_type reference;
  typedef boost::readable_property_map_tag category;
  const double* coordinates = nullptr;
  friend value_type get(const Array_point_map& map, std::size_t i)
  {
    const double* p = map.coordinates + dimension * i;
    return value_type(p[0], p[1], p[2]);
  }
};

/// `points` as an (N, 3) C-contiguous float64 array: the same object when it is one already,
/// otherwise one converted copy.
Point_array as_point_array(const py::handle& points)
{
  Point_array array = Point_array::ensure(points);
  if(!array)
    throw py::type_error(std::string("points must be an (N, 3) array of numbers, not ")
                         + Py_TYPE(points.ptr())->tp_name);
  if(array.ndim() != 2 || array.shape(1) != dimension)
  {
    std::string shape;
    for(py::ssize_t d = 0; d < array.ndim(); ++d)
      shape += (d > 0 ? ", " : "") + std::to_string(array.shape(d));
    throw py::value_error("points must have shape (N, 3), not (" + shape + ")");
  }
  return array;
}

/// The named parameters of `CGAL::extract_sharp_features()`, each initialised with the value
/// that selects the library's default: a scale of 0 and a negative `threshold_distance` are
/// derived from the data, the other defaults are those of internal/Stage_parameters.h.
struct Extraction_parameters
{
  int degree_fitting = sfe_internal::Candidate_parameters().degree_fitting;
  double threshold_distance = sfe_internal::Candidate_parameters().residual_threshold;
  double sharpness_angle = sfe_internal::Projection_parameters().sharpness_angle;
  unsigned int number_of_iterations = sfe_internal::Smoothing_parameters().passes;
  double maximum_angle = sfe_internal::Completion_parameters().aperture;
  unsigned int number_of_relaxation_steps = sfe_internal::Completion_parameters().laplacian_passes;
  std::size_t candidate_neighbors = sfe_internal::Scale_parameters().candidate_neighbors;
  std::size_t rmls_neighbors = sfe_internal::Scale_parameters().rmls_neighbors;
  double rmls_tolerance = sfe_internal::Scale_parameters().rmls_tolerance;
  double corner_radius = sfe_internal::Scale_parameters().corner_radius;
  double growth_radius = sfe_internal::Scale_parameters().growth_radius;
  double completion_distance = sfe_internal::Scale_parameters().completion_distance;
};

typedef std::variant<int Extraction_parameters::*, unsigned int Extraction_parameters::*,
                     std::size_t Extraction_parameters::*, double Extraction_parameters::*>
  Parameter_member;

/// The keywords of `extract()` that are named parameters of the library, by name.
const std::map<std::string, Parameter_member>& parameter_members()
{
  typedef Extraction_parameters P;
  static const std::map<std::string, Parameter_member> members = {
    {"degree_fitting", &P::degree_fitting},           {"threshold_distance", &P::threshold_distance},
    {"sharpness_angle", &P::sharpness_angle},         {"number_of_iterations", &P::number_of_iterations},
    {"maximum_angle", &P::maximum_angle},             {"number_of_relaxation_steps", &P::number_of_relaxation_steps},
    {"candidate_neighbors", &P::candidate_neighbors}, {"rmls_neighbors", &P::rmls_neighbors},
    {"rmls_tolerance", &P::rmls_tolerance},           {"corner_radius", &P::corner_radius},
    {"growth_radius", &P::growth_radius},             {"completion_distance", &P::completion_distance}};
  return members;
}

/// A Python integer (or any object with `__index__`, such as a NumPy integer) as an `Integer`.
template <typename Integer>
Integer read_integer(const std::string& name, const py::handle& value)
{
  if(!PyIndex_Check(value.ptr()))
    throw py::type_error(name + " must be an integer, not " + Py_TYPE(value.ptr())->tp_name);
  const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if(!index)
    throw py::error_already_set();
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
  const long long lowest = std::is_signed<Integer>::value ? (long long)(std::numeric_limits<Integer>::lowest()) : 0;
  const unsigned long long highest = (std::numeric_limits<Integer>::max)();
  if(overflow != 0 || v < lowest || (v > 0 && (unsigned long long)(v) > highest))
    throw py::value_error(name + " must be an integer in [" + std::to_string(lowest) + ", "
                          + std::to_string(highest) + "]");
  return Integer(v);
}

/// A Python number (any object with `__float__`) as a double; the library checks its range.
double read_real(const std::string& name, const py::handle& value)
{
  const double v = PyFloat_AsDouble(value.ptr());
  if(v == -1 && PyErr_Occurred())
  {
    PyErr_Clear();
    throw py::type_error(name + " must be a number, not " + Py_TYPE(value.ptr())->tp_name);
  }
  return v;
}

/// The keywords of the tiled functions that each reads (the others take all of them).
namespace keywords_of {
const std::set<std::string> scales = {"degree_fitting", "threshold_distance", "candidate_neighbors", "rmls_neighbors",
                                      "rmls_tolerance", "corner_radius", "growth_radius", "completion_distance"};
const std::set<std::string> halo = {"number_of_iterations"};
const std::set<std::string> tile = {"degree_fitting", "sharpness_angle", "number_of_iterations"};
const std::set<std::string> stitch = {"maximum_angle", "number_of_relaxation_steps"};
} // namespace keywords_of

/// The keywords of `function` beyond `threads` and `progress`, among `accepted` (all of them if
/// null); None keeps the default.
Extraction_parameters read_parameters(const py::kwargs& keywords, const std::string& function = "extract",
                                      const std::set<std::string>* accepted = nullptr)
{
  Extraction_parameters parameters;
  for(const auto& [key, value] : keywords)
  {
    const std::string name = py::str(key);
    const auto found = parameter_members().find(name);
    if(found == parameter_members().end() || (accepted != nullptr && accepted->count(name) == 0))
      throw py::type_error(function + "() got an unexpected keyword argument '" + name + "'");
    if(value.is_none())
      continue;
    std::visit([&](auto member) {
      auto& field = parameters.*member;
      typedef std::decay_t<decltype(field)> Field;
      if constexpr(std::is_integral<Field>::value)
        field = read_integer<Field>(name, value);
      else
        field = read_real(name, value);
    }, found->second);
  }
  return parameters;
}

/// The number of threads of `threads` (None: 0, all of them).
std::size_t read_thread_count(const py::handle& threads)
{
  if(threads.is_none())
    return 0;
  const std::size_t count = read_integer<std::size_t>("threads", threads);
  if(count == 0)
    throw py::value_error("threads must be at least 1 (or None: all cores)");
  return count;
}

// ---------------------------------------------------------------------------------------------
// Computation

/// Raised when the progress function returns False.
struct Cancelled : std::runtime_error
{
  Cancelled() : std::runtime_error("the progress function cancelled the extraction") {}
};

/// The library's progress callback, shared by reference by every copy the library makes: it
/// runs on the thread that called `extract()`, which released the GIL, and takes the GIL to
/// check for signals (Ctrl-C) and to call the user's function. Either stops the run; an
/// exception is kept to be raised once the library has returned.
class Progress_relay
{
public:
  explicit Progress_relay(py::object progress) : m_progress(std::move(progress)) {}

  bool operator()(double fraction)
  {
    py::gil_scoped_acquire gil;
    try
    {
      if(PyErr_CheckSignals() != 0)
        throw py::error_already_set();
      if(!m_progress.is_none())
      {
        const py::object answer = m_progress(fraction);
        m_cancelled = !answer.is_none() && !py::bool_(answer);
      }
    }
    catch(py::error_already_set& e)
    {
      m_error = std::move(e);
    }
    return !m_cancelled && !m_error;
  }

  /// After the run, with the GIL held: raises the exception of the progress function or of a
  /// signal (KeyboardInterrupt for Ctrl-C), even if the library finished regardless (stage 5 is
  /// not interrupted), otherwise `Cancelled` if the run did not finish.
  void raise_if_stopped(bool finished) const
  {
    if(m_error)
      throw *m_error;
    if(!finished)
      throw Cancelled();
  }

private:
  py::object m_progress;
  bool m_cancelled = false;
  std::optional<py::error_already_set> m_error;
};

/// The share of the progress range given to the extraction; the patches take the rest.
constexpr double extraction_share_of_progress = 0.9;

/// Runs the extraction on the points of `points`, then the segmentation into surface patches
/// on the same extraction context; returns false if `callback` stopped it. Needs no GIL.
/// The library's named parameters for `p`, reading the points through `point_map`.
auto library_parameters(const Extraction_parameters& p, const Array_point_map& point_map)
{
  namespace sfe = CGAL::Sharp_feature_extraction::parameters;
  return sfe::candidate_neighbors(p.candidate_neighbors,
                  sfe::rmls_neighbors(p.rmls_neighbors,
                  sfe::rmls_tolerance(p.rmls_tolerance,
                  sfe::corner_radius(p.corner_radius,
                  sfe::growth_radius(p.growth_radius,
                  sfe::completion_distance(p.completion_distance))))))
                    .point_map(point_map)
                    .degree_fitting(p.degree_fitting)
                    .threshold_distance(p.threshold_distance)
                    .sharpness_angle(p.sharpness_angle)
                    .number_of_iterations(p.number_of_iterations)
                    .maximum_angle(p.maximum_angle)
                    .number_of_relaxation_steps(p.number_of_relaxation_steps);
}

/// The indices 0..N-1 of the rows of `points`, which `Array_point_map` reads.
auto row_indices(const Point_array& points)
{
  return boost::counting_range(std::size_t(0), std::size_t(points.shape(0)));
}

bool run_extraction(const Point_array& points, const Extraction_parameters& p,
                    const std::function<bool(double)>& callback, Features& features,
                    CGAL::Surface_patches<Kernel>& patches)
{
  const CGAL::Sharp_feature_extraction_context<Kernel> context(row_indices(points),
                                                               library_parameters(p, Array_point_map{points.data()}));
  // One progress from 0 to 1: the extraction, then the (much faster) patches.
  const auto extraction_progress = [&](double x) { return callback(extraction_share_of_progress * x); };
  const auto patch_progress = [&](double x) {
    return callback(extraction_share_of_progress + (1 - extraction_share_of_progress) * x);
  };
  return context.extract_sharp_features(features, CGAL::parameters::callback(std::function<bool(double)>(extraction_progress)))
         && context.segment_into_patches(features.network, patches,
                                         CGAL::parameters::callback(std::function<bool(double)>(patch_progress)));
}

/// Limits the number of threads while it lives (0: no limit).
class Thread_limit
{
public:
  explicit Thread_limit([[maybe_unused]] std::size_t threads)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(threads > 0)
      m_control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
#endif
  }

private:
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> m_control;
#endif
};

// ---------------------------------------------------------------------------------------------
// Output

/// What `extract()` returns: the curves as NumPy arrays, and the curve network for the writers.
/// The Python attributes are documented in sharp_features_docstrings.h.
struct Result
{
  /// The library's curves and corners, which the writers take.
  CGAL::Feature_curve_network<Kernel> network;
  py::list polylines;
  py::list normals;
  py::array_t<double> corners;
  py::list corner_polylines;
  py::array_t<std::int64_t> patches;
  py::dict scales;
  py::dict timings;
};

/// The points as an (n, 3) array.
py::array_t<double> points_array(const std::vector<Kernel::Point_3>& points)
{
  py::array_t<double> array({py::ssize_t(points.size()), dimension});
  double* out = array.mutable_data();
  for(const Kernel::Point_3& p : points)
    for(int c = 0; c < dimension; ++c)
      *out++ = p[c];
  return array;
}

/// The pairs of normals of a curve as an (n, 2, 3) array.
py::array_t<double> normals_array(const std::vector<std::array<Kernel::Vector_3, 2>>& normals)
{
  py::array_t<double> array({py::ssize_t(normals.size()), surfaces_along_a_curve, dimension});
  double* out = array.mutable_data();
  for(const auto& pair : normals)
    for(const Kernel::Vector_3& n : pair)
      for(int c = 0; c < dimension; ++c)
        *out++ = n[c];
  return array;
}

/// The fields of `Sharp_feature_scales`, by name.
py::dict scales_dict(const CGAL::Sharp_feature_scales<double>& s)
{
  py::dict d;
  d["spacing"] = s.spacing;
  d["noise"] = s.noise;
  d["candidate_neighbors"] = s.candidate_neighbors;
  d["candidate_radius"] = s.candidate_radius;
  d["rmls_neighbors"] = s.rmls_neighbors;
  d["residual_threshold"] = s.residual_threshold;
  d["rmls_tolerance"] = s.rmls_tolerance;
  d["corner_radius"] = s.corner_radius;
  d["growth_radius"] = s.growth_radius;
  d["completion_distance"] = s.completion_distance;
  d["sampled_fraction"] = s.sampled_fraction;
  d["search_fraction"] = s.search_fraction;
  return d;
}

/// The fields of `Sharp_feature_timings`, by name, and their total.
py::dict timings_dict(const CGAL::Sharp_feature_timings& t)
{
  py::dict d;
  d["context"] = t.context;
  d["candidates"] = t.candidates;
  d["projection"] = t.projection;
  d["smoothing"] = t.smoothing;
  d["growing"] = t.growing;
  d["completion"] = t.completion;
  d["total"] = t.total();
  return d;
}

/// The patch of every point (-1: none) as an (N,) array.
py::array_t<std::int64_t> labels_array(const CGAL::Surface_patches<Kernel>& patches)
{
  py::array_t<std::int64_t> array(py::ssize_t(patches.labels.size()));
  std::int64_t* out = array.mutable_data();
  for(std::size_t label : patches.labels)
    *out++ = label == CGAL::Surface_patches<Kernel>::unassigned ? -1 : std::int64_t(label);
  return array;
}

/// Converts the final curve network of `features` and the patch labels for Python (with the
/// GIL held).
Result make_result(Features&& features, const CGAL::Surface_patches<Kernel>& patches)
{
  Result r;
  r.patches = labels_array(patches);
  r.network = std::move(features.network);
  for(const auto& polyline : r.network.polylines)
  {
    r.polylines.append(points_array(polyline.points));
    r.normals.append(normals_array(polyline.normals));
  }
  std::vector<Kernel::Point_3> corner_points;
  for(const auto& corner : r.network.corners)
  {
    corner_points.push_back(corner.point);
    r.corner_polylines.append(py::array_t<std::size_t>(corner.incident_polylines.size(),
                                                       corner.incident_polylines.data()));
  }
  r.corners = points_array(corner_points);
  r.scales = scales_dict(r.network.scales);
  r.timings = timings_dict(features.timings);
  return r;
}

/// Raises OSError with `message`.
[[noreturn]] void raise_os_error(const std::string& message)
{
  PyErr_SetString(PyExc_OSError, message.c_str());
  throw py::error_already_set();
}

/// `Result.write_polylines()`: the library's writer, as the extract_sharp_features program calls it.
void write_polylines(const Result& result, const std::filesystem::path& path)
{
  std::vector<std::vector<Kernel::Point_3>> polylines;
  for(const auto& polyline : result.network.polylines)
    polylines.push_back(polyline.points);
  if(!CGAL::IO::write_polylines(path.string(), polylines))
    raise_os_error("cannot write '" + path.string() + "'");
}

/// `Result.write_ply()`: the library's writer, as the extract_sharp_features program calls it.
void write_ply(const Result& result, const std::filesystem::path& path)
{
  if(!CGAL::IO::write_PLY_feature_curves(path.string(), result.network))
    raise_os_error("cannot write '" + path.string() + "'");
}

// ---------------------------------------------------------------------------------------------
// Tiled extraction

typedef CGAL::Tile_features<Kernel> Tile;
typedef CGAL::Sharp_feature_scales<double> Scales;

/// The tile-count keyword of `extract_tiled()`: at least one tile.
constexpr std::size_t default_number_of_tiles = 8;

/// A dict with the fields of `Sharp_feature_scales` (as `scales_dict()` makes it) as scales.
Scales read_scales(const py::handle& object)
{
  if(!py::isinstance<py::dict>(object))
    throw py::type_error(std::string("scales must be a dict (as estimate_scales() returns it), not ")
                         + Py_TYPE(object.ptr())->tp_name);
  const py::dict d = py::reinterpret_borrow<py::dict>(object);
  const auto field = [&](const char* name) -> py::object {
    if(!d.contains(name))
      throw py::value_error(std::string("scales has no '") + name + "'");
    return d[name];
  };
  Scales s;
  s.spacing = read_real("spacing", field("spacing"));
  s.noise = read_real("noise", field("noise"));
  s.candidate_neighbors = read_integer<std::size_t>("candidate_neighbors", field("candidate_neighbors"));
  s.candidate_radius = read_real("candidate_radius", field("candidate_radius"));
  s.rmls_neighbors = read_integer<std::size_t>("rmls_neighbors", field("rmls_neighbors"));
  s.residual_threshold = read_real("residual_threshold", field("residual_threshold"));
  s.rmls_tolerance = read_real("rmls_tolerance", field("rmls_tolerance"));
  s.corner_radius = read_real("corner_radius", field("corner_radius"));
  s.growth_radius = read_real("growth_radius", field("growth_radius"));
  s.completion_distance = read_real("completion_distance", field("completion_distance"));
  s.sampled_fraction = read_real("sampled_fraction", field("sampled_fraction"));
  s.search_fraction = read_real("search_fraction", field("search_fraction"));
  // The library's rules (ValueError through pybind11's translation of std::invalid_argument),
  // here so that an unpickled tile's scales fail when it is read, not when it is stitched.
  sfe_internal::require_valid_scales(s);
  return s;
}

/// A point given as three numbers (a box corner).
std::array<double, 3> read_corner(const char* name, const py::handle& object)
{
  const Point_array array = Point_array::ensure(object);
  if(!array || array.ndim() != 1 || array.shape(0) != dimension)
    throw py::value_error(std::string(name) + " must be three numbers");
  return {{array.at(0), array.at(1), array.at(2)}};
}

/// What `extract_tile()` returns: a `CGAL::Tile_features`, picklable (its state is plain NumPy
/// arrays and dicts) so that Dask can send it between processes.
struct Tile_result
{
  Tile tile;
};

/// The pairs of normals of edge points, or the triples of corner points, as an (n, k, 3) array.
template <std::size_t k>
py::array_t<double> normal_sets_array(const std::vector<std::array<Kernel::Vector_3, k>>& sets)
{
  py::array_t<double> array({py::ssize_t(sets.size()), py::ssize_t(k), dimension});
  double* out = array.mutable_data();
  for(const auto& set : sets)
    for(const Kernel::Vector_3& n : set)
      for(int c = 0; c < dimension; ++c)
        *out++ = n[c];
  return array;
}

template <typename FeaturePoint>
std::vector<Kernel::Point_3> positions(const std::vector<FeaturePoint>& points)
{
  std::vector<Kernel::Point_3> out;
  for(const FeaturePoint& p : points)
    out.push_back(p.point);
  return out;
}

template <typename FeaturePoint, std::size_t k>
std::vector<std::array<Kernel::Vector_3, k>> normal_sets(const std::vector<FeaturePoint>& points)
{
  std::vector<std::array<Kernel::Vector_3, k>> out;
  for(const FeaturePoint& p : points)
    out.push_back(p.normals);
  return out;
}

template <typename FeaturePoint>
py::array_t<std::int64_t> sources_array(const std::vector<FeaturePoint>& points)
{
  py::array_t<std::int64_t> array(py::ssize_t(points.size()));
  std::int64_t* out = array.mutable_data();
  for(const FeaturePoint& p : points)
    *out++ = std::int64_t(p.source);
  return array;
}

/// `TileResult.__getstate__()`: a dict of NumPy arrays, numbers and dicts.
py::dict tile_state(const Tile_result& r)
{
  const Tile& t = r.tile;
  py::dict d;
  d["core_min"] = py::make_tuple(t.core.xmin(), t.core.ymin(), t.core.zmin());
  d["core_max"] = py::make_tuple(t.core.xmax(), t.core.ymax(), t.core.zmax());
  d["edge_points"] = points_array(positions(t.edge_points));
  d["edge_normals"] = normal_sets_array(normal_sets<CGAL::Edge_point<Kernel>, 2>(t.edge_points));
  d["edge_sources"] = sources_array(t.edge_points);
  d["corner_points"] = points_array(positions(t.corner_points));
  d["corner_normals"] = normal_sets_array(normal_sets<CGAL::Corner_point<Kernel>, 3>(t.corner_points));
  std::vector<double> weights;
  for(const auto& c : t.corner_points)
    weights.push_back(c.weight);
  d["corner_weights"] = py::array_t<double>(py::ssize_t(weights.size()), weights.data());
  d["corner_sources"] = sources_array(t.corner_points);
  d["scales"] = scales_dict(t.scales);
  d["number_of_core_points"] = t.number_of_core_points;
  d["number_of_candidates"] = t.number_of_candidates;
  d["timings"] = timings_dict(t.timings);
  return d;
}

/// Row `i` of an (n, k, 3) float64 array as `k` vectors.
template <std::size_t k>
std::array<Kernel::Vector_3, k> normal_set(const py::array_t<double>& a, py::ssize_t i)
{
  std::array<Kernel::Vector_3, k> set;
  for(py::ssize_t j = 0; j < py::ssize_t(k); ++j)
    set[j] = Kernel::Vector_3(a.at(i, j, 0), a.at(i, j, 1), a.at(i, j, 2));
  return set;
}

/// `TileResult.__setstate__()`: the inverse of `tile_state()`.
Tile_result tile_from_state(const py::dict& d)
{
  typedef py::array_t<double, py::array::c_style | py::array::forcecast> Reals;
  typedef py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> Integers;
  Tile_result r;
  Tile& t = r.tile;
  const std::array<double, 3> low = read_corner("core_min", d["core_min"]), high = read_corner("core_max", d["core_max"]);
  t.core = CGAL::Bbox_3(low[0], low[1], low[2], high[0], high[1], high[2]);
  const Reals edge_points = Reals::ensure(d["edge_points"]), edge_normals = Reals::ensure(d["edge_normals"]);
  const Integers edge_sources = Integers::ensure(d["edge_sources"]);
  for(py::ssize_t i = 0; i < edge_sources.shape(0); ++i)
    t.edge_points.push_back({Kernel::Point_3(edge_points.at(i, 0), edge_points.at(i, 1), edge_points.at(i, 2)),
                             normal_set<2>(edge_normals, i), std::size_t(edge_sources.at(i))});
  const Reals corner_points = Reals::ensure(d["corner_points"]), corner_normals = Reals::ensure(d["corner_normals"]);
  const Reals corner_weights = Reals::ensure(d["corner_weights"]);
  const Integers corner_sources = Integers::ensure(d["corner_sources"]);
  for(py::ssize_t i = 0; i < corner_sources.shape(0); ++i)
    t.corner_points.push_back({Kernel::Point_3(corner_points.at(i, 0), corner_points.at(i, 1), corner_points.at(i, 2)),
                               normal_set<3>(corner_normals, i), corner_weights.at(i), std::size_t(corner_sources.at(i))});
  t.scales = read_scales(d["scales"]);
  t.number_of_core_points = d["number_of_core_points"].cast<std::size_t>();
  t.number_of_candidates = d["number_of_candidates"].cast<std::size_t>();
  const py::dict timings = d["timings"].cast<py::dict>();
  t.timings.context = timings["context"].cast<double>();
  t.timings.candidates = timings["candidates"].cast<double>();
  t.timings.projection = timings["projection"].cast<double>();
  t.timings.smoothing = timings["smoothing"].cast<double>();
  return r;
}

/// Checks `progress` and runs `compute(callback)` without the GIL and within the thread limit;
/// raises if the progress function stopped it.
template <typename Computation>
void run_without_gil(const py::object& threads, py::object progress, const Computation& compute)
{
  const std::size_t thread_count = read_thread_count(threads);
  if(!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress must be callable or None");
  Progress_relay relay(std::move(progress));
  bool finished = false;
  {
    py::gil_scoped_release released;
    const Thread_limit limit(thread_count);
    finished = compute(std::function<bool(double)>(std::ref(relay)));
  }
  relay.raise_if_stopped(finished);
}

/// `sharp_features.estimate_scales()`.
py::dict estimate_scales(const py::object& points_object, const py::object& threads, const py::kwargs& keywords)
{
  namespace sfe = CGAL::Sharp_feature_extraction::parameters;
  const Point_array points = as_point_array(points_object);
  const Extraction_parameters p = read_parameters(keywords, "estimate_scales", &keywords_of::scales);
  Scales scales;
  run_without_gil(threads, py::none(), [&](const std::function<bool(double)>&) {
    scales = CGAL::estimate_sharp_feature_scales_for_tiles<CGAL::Parallel_if_available_tag>(
      row_indices(points),
      sfe::candidate_neighbors(p.candidate_neighbors,
      sfe::rmls_neighbors(p.rmls_neighbors,
      sfe::rmls_tolerance(p.rmls_tolerance,
      sfe::corner_radius(p.corner_radius,
      sfe::growth_radius(p.growth_radius,
      sfe::completion_distance(p.completion_distance))))))
        .point_map(Array_point_map{points.data()})
        .degree_fitting(p.degree_fitting)
        .threshold_distance(p.threshold_distance));
    return true;
  });
  return scales_dict(scales);
}

/// `sharp_features.tile_halo_width()`.
double tile_halo_width(const py::object& scales, const py::kwargs& keywords)
{
  const Extraction_parameters p = read_parameters(keywords, "tile_halo_width", &keywords_of::halo);
  return CGAL::tile_halo_width(read_scales(scales), CGAL::parameters::number_of_iterations(p.number_of_iterations));
}

/// `sharp_features.extract_tile()`.
Tile_result extract_tile(const py::object& points_object, const py::object& box_min, const py::object& box_max,
                         const py::object& scales_object, const py::object& threads, py::object progress,
                         const py::kwargs& keywords)
{
  const Point_array points = as_point_array(points_object);
  const Extraction_parameters p = read_parameters(keywords, "extract_tile", &keywords_of::tile);
  const std::array<double, 3> low = read_corner("box_min", box_min), high = read_corner("box_max", box_max);
  const CGAL::Bbox_3 core(low[0], low[1], low[2], high[0], high[1], high[2]);
  const Scales scales = read_scales(scales_object);
  Tile_result r;
  run_without_gil(threads, std::move(progress), [&](const std::function<bool(double)>& callback) {
    return CGAL::extract_tile_features<CGAL::Parallel_if_available_tag>(
      row_indices(points), core, scales, r.tile,
      CGAL::parameters::point_map(Array_point_map{points.data()})
        .degree_fitting(p.degree_fitting)
        .sharpness_angle(p.sharpness_angle)
        .number_of_iterations(p.number_of_iterations)
        .callback(callback));
  });
  return r;
}

/// `sharp_features.stitch_tiles()`.
Result stitch_tiles(const py::iterable& tile_objects, py::object progress, const py::kwargs& keywords)
{
  const Extraction_parameters p = read_parameters(keywords, "stitch_tiles", &keywords_of::stitch);
  std::vector<Tile> tiles;
  for(const py::handle& t : tile_objects)
  {
    if(!py::isinstance<Tile_result>(t))
      throw py::type_error(std::string("stitch_tiles() takes TileResult objects, not ") + Py_TYPE(t.ptr())->tp_name);
    tiles.push_back(t.cast<const Tile_result&>().tile);
  }
  Features features;
  run_without_gil(py::none(), std::move(progress), [&](const std::function<bool(double)>& callback) {
    return CGAL::stitch_tile_features(tiles, features,
                                      CGAL::parameters::maximum_angle(p.maximum_angle)
                                        .number_of_relaxation_steps(p.number_of_relaxation_steps)
                                        .callback(callback));
  });
  return make_result(std::move(features), CGAL::Surface_patches<Kernel>());
}

/// `sharp_features.extract_tiled()`.
Result extract_tiled(const py::object& points_object, const py::object& tiles, const py::object& threads,
                     py::object progress, const py::kwargs& keywords)
{
  const Point_array points = as_point_array(points_object);
  const Extraction_parameters p = read_parameters(keywords, "extract_tiled");
  const std::size_t tile_count = tiles.is_none() ? default_number_of_tiles : read_integer<std::size_t>("tiles", tiles);
  Features features;
  run_without_gil(threads, std::move(progress), [&](const std::function<bool(double)>& callback) {
    return CGAL::extract_sharp_features_in_tiles<CGAL::Parallel_if_available_tag>(
      row_indices(points), features,
      CGAL::Sharp_feature_extraction::parameters::number_of_tiles(tile_count,
        library_parameters(p, Array_point_map{points.data()}).callback(callback)));
  });
  return make_result(std::move(features), CGAL::Surface_patches<Kernel>());
}

/// `TileResult.__repr__()`.
std::string tile_repr(const Tile_result& r)
{
  return "<sharp_features.TileResult: " + std::to_string(r.tile.edge_points.size()) + " edge points, "
         + std::to_string(r.tile.corner_points.size()) + " corner points>";
}

// ---------------------------------------------------------------------------------------------
// The module

/// `sharp_features.extract()` (see its docstring): reads and checks the arguments with the GIL,
/// computes without it, converts the result with it.
Result extract(const py::object& points_object, const py::object& threads, py::object progress,
               const py::kwargs& keywords)
{
  const Point_array points = as_point_array(points_object);
  const Extraction_parameters parameters = read_parameters(keywords);
  const std::size_t thread_count = read_thread_count(threads);
  if(!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress must be callable or None");
  Progress_relay relay(std::move(progress));
  Features features;
  CGAL::Surface_patches<Kernel> patches;
  bool finished = false;
  {
    py::gil_scoped_release released;
    const Thread_limit limit(thread_count);
    finished = run_extraction(points, parameters, std::ref(relay), features, patches);
  }
  relay.raise_if_stopped(finished);
  return make_result(std::move(features), patches);
}

/// `Result.__repr__()`.
std::string result_repr(const Result& r)
{
  return "<sharp_features.Result: " + std::to_string(r.network.polylines.size()) + " polylines, "
         + std::to_string(r.network.corners.size()) + " corners>";
}

} // namespace

PYBIND11_MODULE(_sharp_features, m)
{
  m.doc() = docstrings::module;
  m.attr("__version__") = SFE_VERSION;
  py::register_exception<Cancelled>(m, "Cancelled").doc() = docstrings::cancelled;

  py::class_<Result>(m, "Result", docstrings::result)
    .def_readonly("polylines", &Result::polylines, docstrings::polylines)
    .def_readonly("normals", &Result::normals, docstrings::normals)
    .def_readonly("corners", &Result::corners, docstrings::corners)
    .def_readonly("corner_polylines", &Result::corner_polylines, docstrings::corner_polylines)
    .def_readonly("patches", &Result::patches, docstrings::patches)
    .def_readonly("scales", &Result::scales, docstrings::scales)
    .def_readonly("timings", &Result::timings, docstrings::timings)
    .def("write_polylines", &write_polylines, py::arg("path"), docstrings::write_polylines)
    .def("write_ply", &write_ply, py::arg("path"), docstrings::write_ply)
    .def("__repr__", &result_repr, docstrings::result_repr);

  m.def("extract", &extract, py::arg("points"), py::kw_only(), py::arg("threads") = py::none(),
        py::arg("progress") = py::none(), docstrings::extract);

  py::class_<Tile_result>(m, "TileResult", docstrings::tile_result)
    .def_property_readonly("state", &tile_state, docstrings::tile_state)
    .def("__repr__", &tile_repr, docstrings::tile_repr)
    .def(py::pickle(&tile_state, &tile_from_state));
  m.def("estimate_scales", &estimate_scales, py::arg("points"), py::kw_only(), py::arg("threads") = py::none(),
        docstrings::estimate_scales);
  m.def("tile_halo_width", &tile_halo_width, py::arg("scales"), docstrings::tile_halo_width);
  m.def("extract_tile", &extract_tile, py::arg("points"), py::arg("box_min"), py::arg("box_max"), py::arg("scales"),
        py::kw_only(), py::arg("threads") = py::none(), py::arg("progress") = py::none(), docstrings::extract_tile);
  m.def("stitch_tiles", &stitch_tiles, py::arg("tiles"), py::kw_only(), py::arg("progress") = py::none(),
        docstrings::stitch_tiles);
  m.def("extract_tiled", &extract_tiled, py::arg("points"), py::kw_only(), py::arg("tiles") = py::none(),
        py::arg("threads") = py::none(), py::arg("progress") = py::none(), docstrings::extract_tiled);
}
