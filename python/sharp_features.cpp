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

/// The keywords of `extract()` beyond `threads` and `progress`; None keeps the default.
Extraction_parameters read_parameters(const py::kwargs& keywords)
{
  Extraction_parameters parameters;
  for(const auto& [key, value] : keywords)
  {
    const std::string name = py::str(key);
    const auto found = parameter_members().find(name);
    if(found == parameter_members().end())
      throw py::type_error("extract() got an unexpected keyword argument '" + name + "'");
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
bool run_extraction(const Point_array& points, const Extraction_parameters& p,
                    const std::function<bool(double)>& callback, Features& features,
                    CGAL::Surface_patches<Kernel>& patches)
{
  namespace sfe = CGAL::Sharp_feature_extraction::parameters;
  const Array_point_map point_map{points.data()};
  const auto indices = boost::counting_range(std::size_t(0), std::size_t(points.shape(0)));
  const auto np = sfe::candidate_neighbors(p.candidate_neighbors,
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
  const CGAL::Sharp_feature_extraction_context<Kernel> context(indices, np);
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
}
