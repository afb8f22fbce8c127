// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_IO_READ_POINT_CLOUD_H
#define CGAL_SHARP_FEATURE_EXTRACTION_IO_READ_POINT_CLOUD_H

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <istream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <CGAL/Sharp_feature_extraction/IO/read_LAS_points.h>

namespace CGAL {
namespace Sharp_feature_extraction {
namespace internal {

// A reader either succeeds or says why it did not; the reason ends up in one line of a program.
struct Point_cloud_reader_state
{
  std::string reason;
  bool fail(const std::string& why)
  {
    reason = why;
    return false;
  }
};

inline std::string lower_case(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

// The numbers of one text line. `parse` reads every whitespace-separated token as a double
// (accepting a leading '+', as strtod does, but independently of the locale); a token that is
// not entirely a number makes the line malformed.
struct Number_line
{
  std::vector<double> values;
  std::string bad_token;

  bool parse(const std::string& line)
  {
    values.clear();
    const char* p = line.data();
    const char* const end = p + line.size();
    while(true)
    {
      while(p != end && is_blank(*p))
        ++p;
      if(p == end)
        return true;
      const char* token = p;
      while(p != end && !is_blank(*p))
        ++p;
      const char* first = (*token == '+' && p - token > 1 && token[1] != '-') ? token + 1 : token;
      double v;
      const std::from_chars_result r = std::from_chars(first, p, v);
      if(r.ec != std::errc() || r.ptr != p)
      {
        // Out of range (a denormal or a value beyond DBL_MAX) is still a number: strtod agrees.
        if(r.ec == std::errc::result_out_of_range && r.ptr == p)
          v = std::strtod(std::string(token, p).c_str(), nullptr);
        else
        {
          bad_token.assign(token, p);
          return false;
        }
      }
      values.push_back(v);
    }
  }
};

// Removes a `#` comment and the line end; true if something is left.
inline bool strip_comment(std::string& line)
{
  const std::size_t hash = line.find('#');
  if(hash != std::string::npos)
    line.erase(hash);
  return line.find_first_not_of(" \t\r\v\f") != std::string::npos;
}

inline std::string at_line(std::size_t line_number) { return "line " + std::to_string(line_number) + ": "; }

inline bool is_count(double v) { return v >= 0 && v == std::floor(v) && v < 9.0e15; } // exact in a double

// `where` and `index` say where the point is ("line", 12), for the reason.
inline bool check_finite(const double* xyz, const char* where, std::uint64_t index, Point_cloud_reader_state& state)
{
  if(!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
    return state.fail(where + (" " + std::to_string(index)) + ": non-finite coordinate");
  return true;
}

template <typename Point_3>
bool append_point(const double* xyz, const char* where, std::uint64_t index, std::vector<Point_3>& points,
                  Point_cloud_reader_state& state)
{
  if(!check_finite(xyz, where, index, state))
    return false;
  points.emplace_back(xyz[0], xyz[1], xyz[2]);
  return true;
}

// XYZ: one point per line, `x y z` and optionally more numbers (normals, colours: ignored);
// blank lines and `#` comments skipped; the first line may hold the number of points alone.
template <typename Point_3>
bool read_xyz_points(std::istream& is, std::vector<Point_3>& points, Point_cloud_reader_state& state)
{
  std::string line;
  Number_line numbers;
  std::size_t line_number = 0;
  bool first = true;
  double announced = -1;
  while(std::getline(is, line))
  {
    ++line_number;
    if(!strip_comment(line))
      continue;
    if(!numbers.parse(line))
      return state.fail(at_line(line_number) + "'" + numbers.bad_token + "' is not a number");
    if(first && numbers.values.size() == 1 && is_count(numbers.values[0]))
      announced = numbers.values[0];
    else if(numbers.values.size() < 3)
      return state.fail(at_line(line_number) + "expected three coordinates, found " +
                        std::to_string(numbers.values.size()));
    else if(!append_point(numbers.values.data(), "line", line_number, points, state))
      return false;
    first = false;
  }
  if(is.bad())
    return state.fail("read error");
  if(announced >= 0 && announced != double(points.size()))
    return state.fail("the first line announces " + std::to_string(std::uint64_t(announced)) +
                      " points, the file holds " + std::to_string(points.size()));
  return true;
}

// Next line with something else than a comment on it; false at the end of the stream.
inline bool next_data_line(std::istream& is, std::string& line, std::size_t& line_number)
{
  while(std::getline(is, line))
  {
    ++line_number;
    if(strip_comment(line))
      return true;
  }
  return false;
}

// OFF (also COFF, NOFF, CNOFF, STOFF...): keyword, `nv nf [ne]`, then one vertex per line
// (`x y z` then normals or colours, ignored); faces are not read.
template <typename Point_3>
bool read_off_points(std::istream& is, std::vector<Point_3>& points, Point_cloud_reader_state& state)
{
  std::string line;
  std::size_t line_number = 0;
  if(!next_data_line(is, line, line_number))
    return state.fail("empty file (expected the OFF keyword)");
  std::istringstream header(line);
  std::string keyword;
  header >> keyword;
  std::string variant = keyword;
  for(const char* prefix : {"ST", "C", "N", "4", "n"})
    if(variant.compare(0, std::strlen(prefix), prefix) == 0 && variant.size() > 3)
      variant.erase(0, std::strlen(prefix));
  if(variant != "OFF")
    return state.fail("not an OFF file (the first word is '" + keyword + "', expected OFF, COFF, NOFF...)");
  if(keyword.find_first_of("4n") != std::string::npos)
    return state.fail("'" + keyword + "': homogeneous and n-dimensional OFF files are not supported");
  std::string counts_text;
  std::getline(header, counts_text);
  if(counts_text.find("BINARY") != std::string::npos)
    return state.fail("binary OFF files are not supported");
  Number_line numbers;
  if(counts_text.find_first_not_of(" \t\r") == std::string::npos && !next_data_line(is, counts_text, line_number))
    return state.fail("no vertex and face counts after '" + keyword + "'");
  if(!numbers.parse(counts_text))
    return state.fail("vertex count: '" + numbers.bad_token + "' is not a number");
  if(numbers.values.size() < 2 || numbers.values.size() > 3 ||
     !std::all_of(numbers.values.begin(), numbers.values.end(), is_count))
    return state.fail("expected the counts 'vertices faces [edges]' after '" + keyword + "'");
  const std::uint64_t vertices = std::uint64_t(numbers.values[0]);
  for(std::uint64_t v = 0; v < vertices; ++v)
  {
    if(!next_data_line(is, line, line_number))
      return state.fail(is.bad() ? std::string("read error")
                                 : "the file ends after " + std::to_string(v) + " of " + std::to_string(vertices) +
                                     " vertices");
    if(!numbers.parse(line))
      return state.fail(at_line(line_number) + "'" + numbers.bad_token + "' is not a number");
    if(numbers.values.size() < 3)
      return state.fail(at_line(line_number) + "expected three vertex coordinates, found " +
                        std::to_string(numbers.values.size()));
    if(!append_point(numbers.values.data(), "line", line_number, points, state))
      return false;
  }
  return true;
}

// The scalar types of PLY, under both of their names.
enum class Ply_type { int8, uint8, int16, uint16, int32, uint32, float32, float64, unknown };

inline Ply_type ply_type(const std::string& name)
{
  static const std::pair<const char*, Ply_type> names[] = {
    {"char", Ply_type::int8},     {"int8", Ply_type::int8},       {"uchar", Ply_type::uint8},
    {"uint8", Ply_type::uint8},   {"short", Ply_type::int16},     {"int16", Ply_type::int16},
    {"ushort", Ply_type::uint16}, {"uint16", Ply_type::uint16},   {"int", Ply_type::int32},
    {"int32", Ply_type::int32},   {"uint", Ply_type::uint32},     {"uint32", Ply_type::uint32},
    {"float", Ply_type::float32}, {"float32", Ply_type::float32}, {"double", Ply_type::float64},
    {"float64", Ply_type::float64}};
  for(const auto& n : names)
    if(name == n.first)
      return n.second;
  return Ply_type::unknown;
}

inline std::size_t ply_size(Ply_type t)
{
  switch(t)
  {
  case Ply_type::int8: case Ply_type::uint8: return 1;
  case Ply_type::int16: case Ply_type::uint16: return 2;
  case Ply_type::int32: case Ply_type::uint32: case Ply_type::float32: return 4;
  default: return 8;
  }
}

struct Ply_property
{
  std::string name;
  Ply_type type;        // of the value, or of the items of a list
  Ply_type count_type;  // Ply_type::unknown for a scalar property
  bool is_list() const { return count_type != Ply_type::unknown; }
};

struct Ply_element
{
  std::string name;
  std::uint64_t count;
  std::vector<Ply_property> properties;
};

// Reads the values of a PLY body, ASCII or binary, as doubles.
class Ply_body
{
public:
  enum Format { ascii, binary_little_endian, binary_big_endian };

  Ply_body(std::istream& is, Format format) : is_(is), format_(format)
  {
    const std::uint16_t one = 1;
    unsigned char first_byte;
    std::memcpy(&first_byte, &one, 1);
    swap_ = (format == binary_little_endian) != (first_byte == 1);
  }

  bool read(Ply_type t, double& v)
  {
    if(format_ == ascii)
      return read_token(v);
    switch(t)
    {
    case Ply_type::int8: return read_binary<std::int8_t>(v);
    case Ply_type::uint8: return read_binary<std::uint8_t>(v);
    case Ply_type::int16: return read_binary<std::int16_t>(v);
    case Ply_type::uint16: return read_binary<std::uint16_t>(v);
    case Ply_type::int32: return read_binary<std::int32_t>(v);
    case Ply_type::uint32: return read_binary<std::uint32_t>(v);
    case Ply_type::float32: return read_binary<float>(v);
    default: return read_binary<double>(v);
    }
  }

  // Skips `n` values of type `t` without storing them (a list count may be huge).
  bool skip(Ply_type t, std::uint64_t n)
  {
    if(format_ != ascii)
    {
      const std::uint64_t bytes = n * ply_size(t);
      return bool(is_.ignore(std::streamsize(bytes))) && std::uint64_t(is_.gcount()) == bytes;
    }
    double ignored;
    for(std::uint64_t i = 0; i < n; ++i)
      if(!read_token(ignored))
        return false;
    return true;
  }

private:
  bool read_token(double& v)
  {
    if(!(is_ >> token_) || !numbers_.parse(token_) || numbers_.values.size() != 1)
      return false;
    v = numbers_.values[0];
    return true;
  }

  template <typename T>
  bool read_binary(double& v)
  {
    char bytes[sizeof(T)];
    if(!is_.read(bytes, sizeof(T)))
      return false;
    if(swap_)
      std::reverse(bytes, bytes + sizeof(T));
    T t;
    std::memcpy(&t, bytes, sizeof(T));
    v = double(t);
    return true;
  }

  std::istream& is_;
  Format format_;
  bool swap_;
  std::string token_;
  Number_line numbers_;
};

inline bool read_ply_header(std::istream& is, Ply_body::Format& format, std::vector<Ply_element>& elements,
                            Point_cloud_reader_state& state)
{
  std::string line;
  if(!std::getline(is, line) || line.substr(0, 3) != "ply" || line.find_first_not_of(" \t\r", 3) != std::string::npos)
    return state.fail("not a PLY file (the first line is not 'ply')");
  bool has_format = false;
  std::size_t line_number = 1;
  while(std::getline(is, line))
  {
    ++line_number;
    const std::string where = "header line " + std::to_string(line_number);
    std::istringstream row(line);
    std::string keyword, a, b, c;
    row >> keyword;
    if(keyword == "comment" || keyword == "obj_info")
      continue;
    row >> a >> b;
    if(keyword == "end_header")
    {
      if(!has_format)
        return state.fail("the header has no format line");
      return true;
    }
    if(keyword == "format")
    {
      if(a == "ascii") format = Ply_body::ascii;
      else if(a == "binary_little_endian") format = Ply_body::binary_little_endian;
      else if(a == "binary_big_endian") format = Ply_body::binary_big_endian;
      else return state.fail(where + ": unknown format '" + a + "'");
      has_format = true;
    }
    else if(keyword == "element")
    {
      Number_line count;
      if(a.empty() || !count.parse(b) || count.values.size() != 1 || !is_count(count.values[0]))
        return state.fail(where + ": expected 'element NAME COUNT'");
      elements.push_back(Ply_element{a, std::uint64_t(count.values[0]), {}});
    }
    else if(keyword == "property")
    {
      if(elements.empty())
        return state.fail(where + ": a property before any element");
      Ply_property property{b, ply_type(a), Ply_type::unknown};
      if(a == "list")
      {
        row >> c >> property.name;
        property.count_type = ply_type(b);
        property.type = ply_type(c);
        if(property.count_type == Ply_type::unknown || property.count_type == Ply_type::float32 ||
           property.count_type == Ply_type::float64)
          return state.fail(where + ": a list count must have an integer type, not '" + b + "'");
      }
      if(property.type == Ply_type::unknown || property.name.empty())
        return state.fail(where + ": expected 'property TYPE NAME' with a PLY type, got '" + line + "'");
      elements.back().properties.push_back(property);
    }
    else
      return state.fail(where + ": unknown keyword '" + keyword + "'");
  }
  return state.fail("the header has no end_header line");
}

// The vertices of a PLY stream, ASCII or binary, a bounded number at a time: `open` reads the
// header and the elements before the vertices, `read` the next vertices' x, y and z (any
// numeric type; other properties are skipped). Elements after the vertices are not read.
class Ply_vertex_stream
{
public:
  bool open(std::istream& is, Point_cloud_reader_state& state)
  {
    Ply_body::Format format = Ply_body::ascii;
    if(!read_ply_header(is, format, elements_, state))
      return false;
    vertex_ = std::size_t(std::find_if(elements_.begin(), elements_.end(), [](const Ply_element& e) {
                            return e.name == "vertex" || e.name == "vertices";
                          }) - elements_.begin());
    if(vertex_ == elements_.size())
      return state.fail("no vertex element in the header");
    const auto& props = elements_[vertex_].properties;
    const char* const axes[3] = {"x", "y", "z"};
    for(int axis = 0; axis < 3; ++axis)
    {
      const auto is_axis = [&](const Ply_property& p) { return p.name == axes[axis]; };
      const auto found = std::find_if(props.begin(), props.end(), is_axis);
      if(found == props.end())
        return state.fail(std::string("the vertex element has no '") + axes[axis] +
                          "' property (x, y and z are required)");
      if(found->is_list() || std::count_if(props.begin(), props.end(), is_axis) > 1)
        return state.fail(std::string("the vertex property '") + axes[axis] + "' must be a single number");
      coordinate_[axis] = std::size_t(found - props.begin());
    }
    is_ = &is;
    body_.emplace(is, format);
    // Items without properties take no room in the body, however many there are.
    for(std::size_t e = 0; e < vertex_; ++e)
      for(std::uint64_t item = 0; item < elements_[e].count && !elements_[e].properties.empty(); ++item)
        if(!read_item(elements_[e], item, state))
          return false;
    return true;
  }

  // Number of vertices the header announces.
  std::uint64_t size() const { return elements_[vertex_].count; }

  // Appends the next vertices, at most `max_points`, to `xyz` (x, y, z each); `read` receives
  // how many were appended, fewer than `max_points` only at the end.
  bool read(std::size_t max_points, std::vector<double>& xyz, std::size_t& read, Point_cloud_reader_state& state)
  {
    const Ply_element& vertex = elements_[vertex_];
    read = 0;
    for(; read < max_points && next_vertex_ < vertex.count; ++read, ++next_vertex_)
    {
      if(!read_item(vertex, next_vertex_, state))
        return false;
      const double point[3] = {values_[coordinate_[0]], values_[coordinate_[1]], values_[coordinate_[2]]};
      if(!check_finite(point, "vertex", next_vertex_, state))
        return false;
      xyz.insert(xyz.end(), point, point + 3);
    }
    return true;
  }

private:
  bool read_item(const Ply_element& element, std::uint64_t item, Point_cloud_reader_state& state)
  {
    values_.clear();
    for(const Ply_property& p : element.properties)
    {
      double v;
      if(!body_->read(p.is_list() ? p.count_type : p.type, v) ||
         (p.is_list() && (!is_count(v) || !body_->skip(p.type, std::uint64_t(v)))))
        return state.fail(is_->bad() ? std::string("read error")
                                     : "element '" + element.name + "': item " + std::to_string(item) + " of " +
                                         std::to_string(element.count) + " is truncated or malformed");
      values_.push_back(v);
    }
    return true;
  }

  std::vector<Ply_element> elements_;
  std::size_t vertex_ = 0;
  std::size_t coordinate_[3] = {0, 0, 0};
  std::istream* is_ = nullptr;
  std::optional<Ply_body> body_;
  std::uint64_t next_vertex_ = 0;
  std::vector<double> values_;
};

// PLY, ASCII or binary: every vertex of the stream (see Ply_vertex_stream).
template <typename Point_3>
bool read_ply_points(std::istream& is, std::vector<Point_3>& points, Point_cloud_reader_state& state)
{
  // Vertices decoded per read: the doubles of a chunk take 24 bytes a vertex, 1.5 MB.
  constexpr std::size_t chunk_points = 1 << 16;
  Ply_vertex_stream vertices;
  if(!vertices.open(is, state))
    return false;
  std::vector<double> xyz;
  std::size_t read = 0;
  do
  {
    xyz.clear();
    if(!vertices.read(chunk_points, xyz, read, state))
      return false;
    for(std::size_t i = 0; i < xyz.size(); i += 3)
      points.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
  } while(read == chunk_points);
  return true;
}

} // namespace internal
} // namespace Sharp_feature_extraction

namespace IO {

/// \ingroup PkgSharpFeatureExtractionIORef
/// Reads the positions of a point cloud from a stream in one of the formats `"xyz"`, `"ply"`,
/// `"off"` or `"las"` (letter case does not matter), and rejects malformed input with a reason:
/// - <b>XYZ</b>: one point per line, `x y z`, optionally followed by more numbers (normals,
///   colours), which are ignored; blank lines and `#` comments are skipped; the first line may
///   hold the number of points alone, which must then match.
/// - <b>OFF</b> (and its variants `COFF`, `NOFF`, `CNOFF`, `STOFF`...): the keyword, the counts
///   `nv nf [ne]`, then `nv` vertex lines `x y z ...`; faces are not read. Binary, homogeneous
///   (`4OFF`) and n-dimensional (`nOFF`) files are rejected.
/// - <b>PLY</b>, ASCII or binary (either byte order): the properties `x`, `y` and `z` of the
///   element `vertex`, of any numeric type; other properties and elements are skipped. A vertex
///   element without all three properties is rejected (CGAL's reader fills missing ones with 0).
/// - <b>LAS</b> 1.2 to 1.4, uncompressed, point formats 0 to 10, scale and offset applied (see
///   `LAS_point_reader`, which reads such a file a chunk at a time); LAZ files are rejected.
///
/// In every format a point with a non-finite coordinate (NaN or infinity) is rejected: the
/// functions of this package would throw `std::invalid_argument` on it.
/// For a binary PLY or a LAS stream, open it with `std::ios::binary`.
/// \tparam Point_3 a point type constructible from three doubles.
/// \param is the stream.
/// \param format `"xyz"`, `"ply"`, `"off"` or `"las"`.
/// \param points receives the points on success, appended; left unchanged on failure.
/// \param error if not null, receives on failure one line saying what is wrong, and where
///   (for example `line 12: expected three coordinates, found 2`).
/// \returns `true` on success, `false` on malformed input, a read error or an unknown format.
template <typename Point_3>
bool read_point_cloud(std::istream& is, const std::string& format, std::vector<Point_3>& points,
                      std::string* error = nullptr)
{
  namespace sfe = CGAL::Sharp_feature_extraction::internal;
  sfe::Point_cloud_reader_state state;
  std::vector<Point_3> read;
  const std::string f = sfe::lower_case(format);
  const bool ok = !is ? state.fail("cannot read the stream")
                : f == "xyz" ? sfe::read_xyz_points(is, read, state)
                : f == "off" ? sfe::read_off_points(is, read, state)
                : f == "ply" ? sfe::read_ply_points(is, read, state)
                : f == "las" ? read_LAS_points(is, read, &state.reason)
                : state.fail("unknown point cloud format '" + format + "' (expected xyz, ply, off or las)");
  if(ok)
    points.insert(points.end(), read.begin(), read.end());
  else if(error != nullptr)
    *error = state.reason;
  return ok;
}

/// \ingroup PkgSharpFeatureExtractionIORef
/// Same, from the file `filename`, whose extension (`.xyz`, `.ply`, `.off` or `.las`, in any letter case)
/// gives the format; `false` with a reason if the extension is none of these or the file cannot
/// be opened. The `extract_sharp_features` program reads its input with this function.
template <typename Point_3>
bool read_point_cloud(const std::string& filename, std::vector<Point_3>& points, std::string* error = nullptr)
{
  const std::size_t dot = filename.find_last_of('.');
  const std::size_t slash = filename.find_last_of("/\\");
  const std::string extension =
    (dot == std::string::npos || (slash != std::string::npos && dot < slash)) ? "" : filename.substr(dot + 1);
  const std::string format = Sharp_feature_extraction::internal::lower_case(extension);
  if(format != "xyz" && format != "ply" && format != "off" && format != "las")
  {
    if(error != nullptr)
      *error = "unknown file extension '" + extension + "' (expected .xyz, .ply, .off or .las)";
    return false;
  }
  std::ifstream is(filename, std::ios::binary);
  if(!is)
  {
    if(error != nullptr)
      *error = "cannot open the file";
    return false;
  }
  return read_point_cloud(is, format, points, error);
}

} // namespace IO
} // namespace CGAL

#endif
