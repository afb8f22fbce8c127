// Draws a point cloud and its feature curves into a PNG picture: two 3/4 views from opposite
// sides, points in grey (or tinted by surface patch), each curve in its own colour, corners as
// dots.
//
//   render_feature_curves fandisk_100k.xyz --polylines fandisk.polylines.txt -o fandisk.png

#include "utilities/feature_rendering.h"
#include "utilities/png_image.h"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using Point = std::array<double, 3>;

const char* const usage =
  "usage: render_feature_curves CLOUD.xyz [--polylines CURVES.polylines.txt] -o OUT.png\n"
  "                             [--patches LABELS.txt] [--width W] [--height H] [--max-points M]\n"
  "\n"
  "Writes a PNG picture with two 3/4 views (front and back) of a point cloud and its feature\n"
  "curves.\n"
  "\n"
  "  CLOUD.xyz          points, one per line: 'x y z' or 'x y z nx ny nz' ('#' starts a comment)\n"
  "  --polylines FILE   curves, one per line: 'n x1 y1 z1 ... xn yn zn' (CGAL Mesh_3 format);\n"
  "                     polyline ends shared by 2+ curves, or by 3+ ends, are drawn as corners\n"
  "  --patches FILE     one patch label per point, in the cloud's order ('extract_sharp_features\n"
  "                     --patches'): points are tinted by patch, dark grey for -1\n"
  "  -o OUT.png         output picture (required)\n"
  "  --width W          picture width in pixels (default 1600)\n"
  "  --height H         picture height in pixels (default 800)\n"
  "  --max-points M     draws at most M evenly spread points (default 1000000)\n"
  "  -h, --help         shows this help\n";

struct Arguments
{
  std::string cloud;
  std::string polylines;
  std::string patches;
  std::string output;
  int width = 1600;
  int height = 800;
  std::size_t max_points = 1000000;
};

long long parse_positive_integer(const std::string& option, const std::string& text, long long max)
{
  errno = 0;
  char* end = nullptr;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if(text.empty() || *end != '\0' || errno != 0 || value <= 0 || value > max)
    throw std::runtime_error(option + " expects an integer between 1 and " + std::to_string(max) + ", got '" +
                             text + "'");
  return value;
}

Arguments parse_arguments(int argc, char** argv)
{
  Arguments arguments;
  for(int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw std::runtime_error(option + " expects a value");
      return argv[++i];
    };
    if(option == "-o")
      arguments.output = value();
    else if(option == "--polylines")
      arguments.polylines = value();
    else if(option == "--patches")
      arguments.patches = value();
    else if(option == "--width")
      arguments.width = int(parse_positive_integer(option, value(), 20000));
    else if(option == "--height")
      arguments.height = int(parse_positive_integer(option, value(), 20000));
    else if(option == "--max-points")
      arguments.max_points = std::size_t(parse_positive_integer(option, value(), 1ll << 40));
    else if(!option.empty() && option[0] == '-')
      throw std::runtime_error("unknown option '" + option + "' (see --help)");
    else if(arguments.cloud.empty())
      arguments.cloud = option;
    else
      throw std::runtime_error("more than one point cloud given ('" + arguments.cloud + "' and '" + option + "')");
  }
  if(arguments.cloud.empty())
    throw std::runtime_error("no point cloud given (see --help)");
  if(arguments.output.empty())
    throw std::runtime_error("no output file given: use -o OUT.png");
  return arguments;
}

// The numbers of one text line, up to a '#' comment. Throws on anything that is not a number.
std::vector<double> numbers_of_line(const std::string& line, const std::string& where)
{
  std::vector<double> numbers;
  const char* cursor = line.c_str();
  for(;;) {
    while(*cursor == ' ' || *cursor == '\t' || *cursor == '\r' || *cursor == ',')
      ++cursor;
    if(*cursor == '\0' || *cursor == '#')
      return numbers;
    char* end = nullptr;
    const double value = std::strtod(cursor, &end);
    if(end == cursor || !std::isfinite(value)) {
      std::string token(cursor);
      token = token.substr(0, token.find_first_of(" \t\r,"));
      throw std::runtime_error(where + ": '" + token + "' is not a finite number");
    }
    numbers.push_back(value);
    cursor = end;
    if(*cursor != '\0' && *cursor != ' ' && *cursor != '\t' && *cursor != '\r' && *cursor != ',' && *cursor != '#')
      throw std::runtime_error(where + ": malformed number near '" + std::string(cursor).substr(0, 20) + "'");
  }
}

std::vector<Point> read_xyz(const std::string& path)
{
  std::ifstream in(path);
  if(!in)
    throw std::runtime_error("cannot open point cloud '" + path + "'");
  std::vector<Point> points;
  std::string line;
  for(std::size_t line_number = 1; std::getline(in, line); ++line_number) {
    const std::string where = path + ":" + std::to_string(line_number);
    const std::vector<double> numbers = numbers_of_line(line, where);
    if(numbers.empty())
      continue;
    if(numbers.size() != 3 && numbers.size() != 6)
      throw std::runtime_error(where + ": expected 3 or 6 numbers (x y z [nx ny nz]), found " +
                               std::to_string(numbers.size()));
    points.push_back({numbers[0], numbers[1], numbers[2]});
  }
  if(points.empty())
    throw std::runtime_error("point cloud '" + path + "' contains no point");
  return points;
}

std::string number_text(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

std::vector<std::vector<Point>> read_polylines(const std::string& path)
{
  std::ifstream in(path);
  if(!in)
    throw std::runtime_error("cannot open polylines file '" + path + "'");
  std::vector<std::vector<Point>> polylines;
  std::string line;
  for(std::size_t line_number = 1; std::getline(in, line); ++line_number) {
    const std::string where = path + ":" + std::to_string(line_number);
    const std::vector<double> numbers = numbers_of_line(line, where);
    if(numbers.empty())
      continue;
    const double count = numbers[0];
    if(count < 1 || count != std::floor(count))
      throw std::runtime_error(where + ": a polyline line must start with its number of points, found '" +
                               number_text(count) + "'");
    if(count > double(numbers.size()) || numbers.size() != 1 + 3 * std::size_t(count))
      throw std::runtime_error(where + ": the polyline announces " + number_text(count) + " points, i.e. 3 x " +
                               number_text(count) + " coordinates, but " + std::to_string(numbers.size() - 1) +
                               " coordinates follow");
    std::vector<Point> polyline;
    for(std::size_t k = 1; k + 2 < numbers.size(); k += 3)
      polyline.push_back({numbers[k], numbers[k + 1], numbers[k + 2]});
    polylines.push_back(polyline);
  }
  return polylines;
}

// Polyline ends where two or more curves meet, or three or more ends (a closed curve brings
// two ends to its start point, which alone does not make a corner). Ends must match exactly,
// as they do when one program writes all the curves.
std::vector<Point> corners_of(const std::vector<std::vector<Point>>& polylines)
{
  struct Meeting
  {
    std::size_t ends = 0;
    std::set<std::size_t> curves;
  };
  std::map<Point, Meeting> meetings;
  for(std::size_t i = 0; i < polylines.size(); ++i) {
    if(polylines[i].empty())
      continue;
    for(const Point& end : {polylines[i].front(), polylines[i].back()}) {
      Meeting& meeting = meetings[end];
      ++meeting.ends;
      meeting.curves.insert(i);
    }
  }
  std::vector<Point> corners;
  for(const auto& [point, meeting] : meetings)
    if(meeting.curves.size() >= 2 || meeting.ends >= 3)
      corners.push_back(point);
  return corners;
}

// One tint per point from a file of patch labels (one integer per line, -1: no patch).
std::vector<sfe_utilities::Colour> read_patch_tints(const std::string& path, std::size_t number_of_points)
{
  std::ifstream in(path);
  if(!in)
    throw std::runtime_error("cannot open patch labels '" + path + "'");
  std::vector<sfe_utilities::Colour> tints;
  const std::size_t none = std::size_t(-1);
  long long label = 0;
  while(in >> label)
    tints.push_back(sfe_utilities::patch_tint(label < 0 ? none : std::size_t(label), none));
  if(!in.eof() || tints.size() != number_of_points)
    throw std::runtime_error("'" + path + "' must hold one integer label per point (" + std::to_string(number_of_points) +
                             "), read " + std::to_string(tints.size()));
  return tints;
}

// At most `max_points` items, evenly spread over the input order.
template <typename Item>
std::vector<Item> subsample(const std::vector<Item>& points, std::size_t max_points)
{
  if(points.size() <= max_points)
    return points;
  std::vector<Item> kept;
  kept.reserve(max_points);
  for(std::size_t i = 0; i < max_points; ++i)
    kept.push_back(points[std::size_t((static_cast<long double>(i) * points.size()) / max_points)]);
  return kept;
}

} // namespace

int main(int argc, char** argv)
{
  for(int i = 1; i < argc; ++i)
    if(std::string(argv[i]) == "-h" || std::string(argv[i]) == "--help") {
      std::cout << usage;
      return EXIT_SUCCESS;
    }

  try {
    const Arguments arguments = parse_arguments(argc, argv);
    const std::vector<Point> all_points = read_xyz(arguments.cloud);
    const std::vector<Point> points = subsample(all_points, arguments.max_points);
    const std::vector<sfe_utilities::Colour> tints =
      arguments.patches.empty() ? std::vector<sfe_utilities::Colour>()
                                : subsample(read_patch_tints(arguments.patches, all_points.size()), arguments.max_points);
    const std::vector<std::vector<Point>> polylines =
      arguments.polylines.empty() ? std::vector<std::vector<Point>>() : read_polylines(arguments.polylines);
    const std::vector<Point> corners = corners_of(polylines);

    sfe_utilities::Png_image image(arguments.width, arguments.height);
    sfe_utilities::render_side_by_side(image, points, polylines, corners, sfe_utilities::front_and_back_views(), tints);
    if(!image.write(arguments.output))
      throw std::runtime_error("cannot write '" + arguments.output + "'");
    std::cout << "wrote " << arguments.output << " (" << arguments.width << "x" << arguments.height << "): "
              << points.size() << " points, " << polylines.size() << " polylines, " << corners.size()
              << " corners\n";
  } catch(const std::exception& error) {
    std::cerr << "render_feature_curves: error: " << error.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
