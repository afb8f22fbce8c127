// Samples points uniformly on the surface of a triangle mesh, with optional noise, outliers
// and a denser half: the synthetic inputs of the demo and the benchmark.
//
//   sample_mesh_surface fandisk.off -o fandisk_100k.xyz -n 100000 --noise 0.002 --seed 1

#include "utilities/mesh_surface_sampling.h"

#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

const char* const usage =
  "usage: sample_mesh_surface INPUT_MESH -o OUT.xyz [-n N] [--noise L] [--outliers F]\n"
  "                           [--denser-half K] [--seed S]\n"
  "\n"
  "Draws points uniformly on the surface of a polygon mesh (.off, .obj, .ply, .stl) and writes\n"
  "them as 'x y z' lines.\n"
  "\n"
  "  -o OUT.xyz         output point cloud (required)\n"
  "  -n N               number of surface points (default 100000)\n"
  "  --noise L          each point moves uniformly in a ball of radius L x bounding-box diagonal\n"
  "                     (default 0)\n"
  "  --outliers F       adds F x N points uniform in the bounding box (default 0)\n"
  "  --denser-half K    the half x > bounding-box centre is K times denser (default 1)\n"
  "  --seed S           random seed; a seed gives the same points with any C++ standard\n"
  "                     library (default 1)\n"
  "  -h, --help         shows this help\n";

struct Arguments
{
  std::string input;
  std::string output;
  sfe_utilities::Sampling_options options;
};

double parse_number(const std::string& option, const std::string& text)
{
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch(const std::exception&) {
    used = 0;
  }
  if(used == 0 || used != text.size() || !std::isfinite(value))
    throw std::runtime_error(option + " expects a number, got '" + text + "'");
  return value;
}

unsigned long long parse_count(const std::string& option, const std::string& text, unsigned long long max)
{
  const double value = parse_number(option, text);
  if(value < 0 || value != std::floor(value) || value > double(max))
    throw std::runtime_error(option + " expects a non-negative integer, got '" + text + "'");
  return static_cast<unsigned long long>(value);
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
    else if(option == "-n")
      arguments.options.number_of_points = std::size_t(parse_count(option, value(), 1ull << 40));
    else if(option == "--noise")
      arguments.options.noise = parse_number(option, value());
    else if(option == "--outliers")
      arguments.options.outlier_fraction = parse_number(option, value());
    else if(option == "--denser-half")
      arguments.options.denser_half_factor = parse_number(option, value());
    else if(option == "--seed")
      arguments.options.seed = unsigned(parse_count(option, value(), std::numeric_limits<unsigned>::max()));
    else if(!option.empty() && option[0] == '-')
      throw std::runtime_error("unknown option '" + option + "' (see --help)");
    else if(arguments.input.empty())
      arguments.input = option;
    else
      throw std::runtime_error("more than one input mesh given ('" + arguments.input + "' and '" + option + "')");
  }
  if(arguments.input.empty())
    throw std::runtime_error("no input mesh given (see --help)");
  if(arguments.output.empty())
    throw std::runtime_error("no output file given: use -o OUT.xyz");
  if(arguments.options.number_of_points == 0)
    throw std::runtime_error("-n must be at least 1");
  if(arguments.options.noise < 0)
    throw std::runtime_error("--noise must be >= 0");
  if(arguments.options.outlier_fraction < 0)
    throw std::runtime_error("--outliers must be >= 0");
  if(arguments.options.denser_half_factor <= 0)
    throw std::runtime_error("--denser-half must be > 0");
  return arguments;
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
    const sfe_utilities::Triangle_soup soup = sfe_utilities::read_triangle_soup(arguments.input);
    const auto points = sfe_utilities::sample_triangle_soup(soup, arguments.options);
    sfe_utilities::write_xyz(arguments.output, points);
    std::cout << "wrote " << points.size() << " points sampled on " << soup.triangles.size()
              << " triangles to " << arguments.output << "\n";
  } catch(const std::exception& error) {
    std::cerr << "sample_mesh_surface: error: " << error.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
