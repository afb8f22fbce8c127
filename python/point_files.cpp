// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The extension `sharp_features._point_files`: the package's point cloud readers and its LAS
// writer for Python. `PointReader` streams the points of a LAS or PLY file as NumPy arrays of a
// bounded size (the binning pass of `python3 -m sharp_features` never holds a whole cloud);
// `read_point_cloud` reads a whole file in any format of the extract_sharp_features program.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Sharp_feature_extraction/IO/read_LAS_points.h>
#include <CGAL/Sharp_feature_extraction/IO/read_point_cloud.h>
#include <CGAL/Sharp_feature_extraction/IO/write_LAS_points.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace {

typedef py::array_t<double, py::array::c_style | py::array::forcecast> Point_array;
namespace sfe_internal = CGAL::Sharp_feature_extraction::internal;

/// The extension of `path` in lower case, without the dot.
std::string extension_of(const std::filesystem::path& path)
{
  const std::string e = path.extension().string();
  return sfe_internal::lower_case(e.empty() ? e : e.substr(1));
}

/// OSError with errno's reason and the file name, as Python's own open() raises.
[[noreturn]] void raise_os_error(const std::filesystem::path& path)
{
  PyErr_SetFromErrnoWithFilename(PyExc_OSError, path.string().c_str());
  throw py::error_already_set();
}

/// The x, y, z values of `xyz` as an (N, 3) array that owns them.
Point_array as_array(std::vector<double>&& xyz)
{
  auto* owned = new std::vector<double>(std::move(xyz));
  py::capsule free_when_done(owned, [](void* v) { delete static_cast<std::vector<double>*>(v); });
  return Point_array({py::ssize_t(owned->size() / 3), py::ssize_t(3)}, owned->data(), free_when_done);
}

/// The points of a LAS or PLY file, a bounded number at a time.
class Point_reader
{
public:
  explicit Point_reader(const std::filesystem::path& path) : path_(path), format_(extension_of(path))
  {
    if(format_ != "las" && format_ != "ply")
      throw py::value_error("'" + path.string() + "': PointReader streams .las and .ply files, not '." + format_ +
                            "' (read_point_cloud reads .xyz and .off whole)");
    errno = 0;
    stream_.open(path, std::ios::binary);
    if(!stream_)
      raise_os_error(path);
    if(format_ == "las")
      las_.emplace(stream_); // throws LAS_error, translated to ValueError
    else if(!ply_.open(stream_, state_))
      throw py::value_error("'" + path.string() + "': " + state_.reason);
  }

  std::string format() const { return format_; }

  std::uint64_t count() const { return las_ ? las_->header().point_count : ply_.size(); }

  /// The bounding box the LAS header states, or None (PLY headers have none).
  py::object bounds() const
  {
    if(!las_)
      return py::none();
    return py::make_tuple(py::cast(las_->header().min), py::cast(las_->header().max));
  }

  Point_array read(std::size_t max_points)
  {
    std::vector<double> xyz;
    {
      py::gil_scoped_release released;
      if(las_)
        las_->read(max_points, xyz);
      else
      {
        std::size_t read = 0;
        if(!ply_.read(max_points, xyz, read, state_))
          throw std::invalid_argument(state_.reason);
      }
    }
    return as_array(std::move(xyz));
  }

  void seek(std::uint64_t index)
  {
    if(!las_)
      throw py::value_error("seek() needs a LAS file (PLY records may have variable sizes)");
    las_->seek(index);
  }

private:
  std::filesystem::path path_;
  std::string format_;
  std::ifstream stream_;
  std::optional<CGAL::IO::LAS_point_reader> las_;
  sfe_internal::Ply_vertex_stream ply_;
  sfe_internal::Point_cloud_reader_state state_;
};

typedef CGAL::Simple_cartesian<double>::Point_3 Point_3;

Point_array read_point_cloud(const std::filesystem::path& path)
{
  std::vector<Point_3> points;
  std::string why;
  {
    py::gil_scoped_release released;
    if(!CGAL::IO::read_point_cloud(path.string(), points, &why))
      why = why.empty() ? "cannot read" : why;
  }
  if(!why.empty())
  {
    if(why == "cannot open the file")
      raise_os_error(path);
    throw py::value_error("cannot read '" + path.string() + "': " + why);
  }
  std::vector<double> xyz;
  xyz.reserve(3 * points.size());
  for(const Point_3& p : points)
    xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  return as_array(std::move(xyz));
}

/// Row `i` of an (N, 3) array, as the LAS writer reads a point.
struct Row
{
  const double* xyz;
  double x() const { return xyz[0]; }
  double y() const { return xyz[1]; }
  double z() const { return xyz[2]; }
};

/// The rows of an (N, 3) array as a range of `Row`s, without a copy.
struct Rows
{
  const double* data;
  std::size_t count;
  struct iterator
  {
    const double* p;
    Row operator*() const { return Row{p}; }
    iterator& operator++()
    {
      p += 3;
      return *this;
    }
    bool operator!=(const iterator& other) const { return p != other.p; }
  };
  iterator begin() const { return iterator{data}; }
  iterator end() const { return iterator{data + 3 * count}; }
};

void write_las(const std::filesystem::path& path, const py::handle& points_object, unsigned version_minor,
               unsigned point_format, std::size_t extra_bytes)
{
  const Point_array points = Point_array::ensure(points_object);
  if(!points || points.ndim() != 2 || points.shape(1) != 3)
    throw py::value_error("points must be an (N, 3) array of numbers");
  CGAL::IO::LAS_write_options options;
  options.version_minor = version_minor;
  options.point_format = point_format;
  options.extra_bytes = extra_bytes;
  bool written = false;
  {
    py::gil_scoped_release released;
    written = CGAL::IO::write_LAS_points(path.string(), Rows{points.data(), std::size_t(points.shape(0))}, options);
  }
  if(!written)
    raise_os_error(path);
}

} // namespace

PYBIND11_MODULE(_point_files, m)
{
  m.doc() = "Point cloud files for sharp_features: streaming LAS and PLY readers, a LAS writer.";
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p)
        std::rethrow_exception(p);
    }
    catch(const CGAL::IO::LAS_error& e)
    {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  py::class_<Point_reader>(m, "PointReader", R"doc(The points of a LAS or PLY file, a bounded number at a time.

    reader = PointReader("cloud.las")      # reads and checks the header
    while len(chunk := reader.read(1 << 20)):
        ...                                # chunk: an (n, 3) float64 array

LAS: uncompressed 1.2 to 1.4, point formats 0 to 10, scale and offset applied. PLY: ASCII or
binary, the x, y, z of the vertex element. Raises ValueError (one line saying why) on a file
that is not valid, OSError if it cannot be opened.)doc")
    .def(py::init<const std::filesystem::path&>(), py::arg("path"))
    .def_property_readonly("format", &Point_reader::format, "'las' or 'ply'.")
    .def_property_readonly("count", &Point_reader::count, "Number of points the header announces.")
    .def_property_readonly("bounds", &Point_reader::bounds,
                           "((xmin, ymin, zmin), (xmax, ymax, zmax)) as the LAS header states it; None for PLY.")
    .def("read", &Point_reader::read, py::arg("max_points"),
         "The next points, at most max_points, as an (n, 3) float64 array; n = 0 at the end.\n"
         "Raises ValueError on a truncated or malformed file.")
    .def("seek", &Point_reader::seek, py::arg("index"),
         "Moves to point `index` (LAS only), so that processes can read ranges of one file.");

  m.def("read_point_cloud", &read_point_cloud, py::arg("path"),
        "All the points of a .xyz, .ply, .off or .las file, as the extract_sharp_features program\n"
        "reads them, as an (N, 3) float64 array. Raises ValueError on a malformed file, OSError if\n"
        "it cannot be opened.");
  m.def("write_las", &write_las, py::arg("path"), py::arg("points"), py::kw_only(), py::arg("version_minor") = 2,
        py::arg("point_format") = 0, py::arg("extra_bytes") = 0,
        "Writes an (N, 3) array as an uncompressed LAS 1.<version_minor> file of the given point\n"
        "format (0 to 10; other fields zero) with `extra_bytes` more bytes per record; coordinates\n"
        "are kept within 1e-9 of the extent. Raises ValueError on an invalid layout or a\n"
        "non-finite coordinate, OSError if the file cannot be written.");
}
