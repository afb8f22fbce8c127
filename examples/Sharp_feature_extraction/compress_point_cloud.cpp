// compress_point_cloud: a point cloud coded as height images (Ochotta and Saupe 2004), over a
// partition into height fields that starts either from the whole cloud (traditional) or from
// the surface patches of the sharp features (guided).
//
//   compress_point_cloud INPUT -o FILE --bpp R        compress to at most R bits per point
//   compress_point_cloud --decode FILE -o CLOUD.xyz   decompress
//   compress_point_cloud INPUT --rate-distortion OUT.csv [--reference-mesh MESH.off]
//
// The rate-distortion rows (partition,step,bpp,rms) come from real encode/decode round trips:
// bpp from the byte count, rms the root-mean-square distance from the decoded points to the
// input surface, in bounding-box diagonals.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Sharp_feature_extraction/IO/read_point_cloud.h>
#include <CGAL/bounding_box.h>
#include <CGAL/Sharp_feature_extraction/compress_point_cloud.h>
#include <CGAL/Sharp_feature_extraction/decompress_point_cloud.h>
#include <CGAL/Sharp_feature_extraction/estimate_sharp_feature_scales.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>

#include "utilities/command_line.h"
#include "utilities/surface_distance.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Parallel_if_available_tag Concurrency;
namespace sfe = CGAL::Sharp_feature_extraction::parameters;

namespace {

const char* usage =
  "usage: compress_point_cloud INPUT -o FILE --bpp R [options]\n"
  "       compress_point_cloud --decode FILE -o CLOUD.xyz\n"
  "       compress_point_cloud INPUT --rate-distortion OUT.csv [--reference-mesh MESH] [options]\n"
  "  INPUT                     point cloud: .xyz, .ply or .off (only positions are used)\n"
  "  --bpp R                   largest rate, in bits per input point\n"
  "  --rate-distortion CSV     rows partition,step,bpp,rms for both partitions and a range of\n"
  "                            quantizer steps (rms in bounding-box diagonals)\n"
  "  --reference-mesh MESH     distortion measured to this surface (default: to the planes of\n"
  "                            the nearest input points)\n"
  "options:\n"
  "  --partition P             traditional (split from the whole cloud) or guided (split from\n"
  "                            the surface patches of the sharp features; default)\n"
  "  --height-field-angle DEG  largest angle between a normal and its height field's (60)\n"
  "  --grid-spacing D          side of a height image cell (default: the sampling spacing)\n"
  "  --partition-labels FILE   with -o: also write the piece of every input point, one a line\n"
  "  --grid-scale F            side of a cell: F times the sampling spacing (default 1): coarser\n"
  "                            grids reach lower rates\n";

[[noreturn]] void fail(const std::string& message)
{
  sfe_utilities::fail("compress_point_cloud", message);
}

double number(const std::string& option, const char* text)
{
  return sfe_utilities::non_negative_number("compress_point_cloud", option, text);
}

/// Quantizer steps of the rate-distortion curves, in grid spacings: from 4 cells (a few
/// hundredths of a bit per point) down to a 128th of a cell (rates of a few bits per point),
/// halving.
const double coarsest_step_per_cell = 4, finest_step_per_cell = 1. / 128;
/// Halvings of the step in the search for a rate: from the coarsest step, down to a 2^-20th
/// of a cell, beyond any rate a user asks for.
const int rate_search_halvings = 20;

std::vector<std::size_t> partition(const std::vector<Point>& points, bool guided, double angle, double cell)
{
  std::vector<std::size_t> initial;
  if(guided)
  {
    const CGAL::Sharp_feature_extraction_context<K, Concurrency> context(points);
    CGAL::Sharp_features<K> features;
    context.extract_sharp_features(features);
    CGAL::Surface_patches<K> patches;
    context.segment_into_patches(features.network, patches);
    initial = patches.labels;
  }
  std::vector<std::size_t> labels;
  CGAL::partition_into_height_fields<Concurrency>(
    points, labels, sfe::initial_labels(initial, sfe::height_field_angle(angle, sfe::grid_spacing(cell))));
  return labels;
}

std::vector<unsigned char> compress(const std::vector<Point>& points, const std::vector<std::size_t>& labels,
                                    double cell, double step)
{
  std::vector<unsigned char> bytes;
  CGAL::compress_point_cloud<Concurrency>(points, labels, bytes, sfe::grid_spacing(cell, sfe::quantization_step(step)));
  return bytes;
}

double bits_per_point(const std::vector<unsigned char>& bytes, std::size_t points)
{
  return 8. * double(bytes.size()) / double(points);
}

} // namespace

int main(int argc, char** argv)
{
  std::string input, output, decode, curve, reference, labels_file, kind = "guided";
  double bpp = -1, angle = CGAL::Sharp_feature_extraction::internal::default_height_field_angle, cell = 0, scale = 1;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> const char* {
      if(i + 1 >= argc)
        fail("option " + a + " expects a value");
      return argv[++i];
    };
    if(a == "-h" || a == "--help") { std::cout << usage; return 0; }
    else if(a == "-o" || a == "--output") output = value();
    else if(a == "--decode") decode = value();
    else if(a == "--bpp") bpp = number(a, value());
    else if(a == "--rate-distortion") curve = value();
    else if(a == "--reference-mesh") reference = value();
    else if(a == "--partition") kind = value();
    else if(a == "--partition-labels") labels_file = value();
    else if(a == "--height-field-angle") angle = number(a, value());
    else if(a == "--grid-spacing") cell = number(a, value());
    else if(a == "--grid-scale") scale = number(a, value());
    else if(!a.empty() && a[0] == '-') fail("unknown option " + a + " (see --help)");
    else if(input.empty()) input = a;
    else fail("more than one input file given (see --help)");
  }
  if(kind != "guided" && kind != "traditional")
    fail("--partition expects 'traditional' or 'guided', got '" + kind + "'");
  try
  {
    if(!decode.empty())
    {
      if(output.empty())
        fail("--decode needs -o CLOUD.xyz (see --help)");
      std::ifstream in(decode, std::ios::binary);
      if(!in)
        fail("cannot read '" + decode + "'");
      const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      std::vector<Point> decoded;
      CGAL::decompress_point_cloud(bytes, decoded);
      std::ofstream out(output);
      out.precision(9);
      for(const Point& p : decoded)
        out << p << '\n';
      if(!out)
        fail("cannot write '" + output + "'");
      std::cout << "decoded " << decoded.size() << " points into " << output << std::endl;
      return 0;
    }
    if(input.empty() || (curve.empty() && (output.empty() || bpp <= 0)))
      fail("give INPUT with -o FILE --bpp R, or with --rate-distortion CSV, or --decode FILE -o CLOUD (see --help)");
    std::vector<Point> points;
    std::string why;
    if(!CGAL::IO::read_point_cloud(input, points, &why))
      fail("cannot read '" + input + "': " + why);
    if(points.empty())
      fail("'" + input + "' contains no points");
    if(cell <= 0)
      cell = scale * CGAL::estimate_sharp_feature_scales<Concurrency>(points).spacing;

    if(!curve.empty())
    {
      std::ofstream csv(curve);
      csv << "partition,step,bpp,rms\n";
      const K::Iso_cuboid_3 box = CGAL::bounding_box(points.begin(), points.end());
      const double diagonal = std::sqrt(CGAL::squared_distance(box.min(), box.max()));
      for(const std::string partition_kind : {"traditional", "guided"})
      {
        const std::vector<std::size_t> labels = partition(points, partition_kind == "guided", angle, cell);
        for(double step = coarsest_step_per_cell * cell; step >= finest_step_per_cell * cell * (1 - 1e-9); step /= 2)
        {
          const std::vector<unsigned char> bytes = compress(points, labels, cell, step);
          std::vector<Point> decoded;
          CGAL::decompress_point_cloud(bytes, decoded);
          const double rms = reference.empty() ? sfe_utilities::rms_distance_to_samples(decoded, points)
                                               : sfe_utilities::rms_distance_to_mesh(decoded, reference);
          csv << partition_kind << ',' << step << ',' << bits_per_point(bytes, points.size()) << ','
              << rms / diagonal << '\n';
          std::cout << partition_kind << " step " << step << ": " << bits_per_point(bytes, points.size())
                    << " bpp, rms " << rms / diagonal << " diagonals, " << decoded.size() << " points" << std::endl;
        }
      }
      if(!csv)
        fail("cannot write '" + curve + "'");
      return 0;
    }

    // The finest step whose rate stays within R: the rate falls as the step grows.
    const std::vector<std::size_t> labels = partition(points, kind == "guided", angle, cell);
    double coarse = coarsest_step_per_cell * cell, fine = coarse * std::ldexp(1., -rate_search_halvings);
    std::vector<unsigned char> best = compress(points, labels, cell, coarse);
    if(bits_per_point(best, points.size()) > bpp)
      fail("the smallest bitstream takes " + std::to_string(bits_per_point(best, points.size())) + " bits per point");
    for(int halving = 0; halving < rate_search_halvings; ++halving)
    {
      const double middle = std::sqrt(coarse * fine);
      std::vector<unsigned char> bytes;
      try
      {
        bytes = compress(points, labels, cell, middle);
      }
      catch(const std::invalid_argument&) // too fine a step for 16-bit heights: finer is no better
      {
        fine = middle;
        continue;
      }
      if(bits_per_point(bytes, points.size()) <= bpp) { coarse = middle; best = bytes; }
      else fine = middle;
    }
    std::ofstream out(output, std::ios::binary);
    out.write(reinterpret_cast<const char*>(best.data()), std::streamsize(best.size()));
    if(!out)
      fail("cannot write '" + output + "'");
    if(!labels_file.empty())
    {
      std::ofstream labels_out(labels_file);
      for(std::size_t label : labels)
        labels_out << label << '\n';
      if(!labels_out)
        fail("cannot write '" + labels_file + "'");
    }
    std::cout << "wrote " << output << ": " << best.size() << " bytes, " << bits_per_point(best, points.size())
              << " bits per point (" << kind << " partition, step " << coarse << ")" << std::endl;
  }
  catch(const std::exception& e)
  {
    fail(e.what());
  }
  return 0;
}
