// extract_sharp_features: point cloud in, sharp feature curves out.
//
//   extract_sharp_features INPUT -o OUT.polylines.txt [--ply OUT.ply] [--patches LABELS.txt] [overrides]
//
// Reads .xyz/.ply/.off/.las points (normals ignored), runs the five stages with scales derived from the
// data (or overridden), writes the curves in Mesh_3's polyline format and, optionally, a PLY with
// the curve vertices, edges, both surface normals and corner flags, and the surface patch of
// every point (then also in the PLY: every point with its patch and its patch's colour). Prints
// a summary.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Sharp_feature_extraction/extract_sharp_features.h>
#include <CGAL/Sharp_feature_extraction/IO/read_point_cloud.h>
#include <CGAL/Sharp_feature_extraction/IO/write_PLY_feature_curves.h>
#include <CGAL/Sharp_feature_extraction/IO/write_polylines.h>

#include "utilities/command_line.h"
#include "utilities/progress_bar.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
namespace sfe = CGAL::Sharp_feature_extraction::parameters;

namespace {

const char* usage =
  "usage: extract_sharp_features INPUT -o OUT.polylines.txt [options]\n"
  "  INPUT                     point cloud: .xyz, .ply, .off or .las (only positions are used)\n"
  "  -o, --output FILE         curves in Mesh_3's polyline format (one per line: n x1 y1 z1 ...)\n"
  "  --ply FILE                also write curve vertices, edges, both normals and corner flags\n"
  "                            (with --patches: and every input point, coloured by its patch)\n"
  "  --patches FILE            also write the surface patch of every input point, one integer per\n"
  "                            line in input order (-1: in no patch)\n"
  "  --threads N               number of threads (default: all cores)\n"
  "  --quiet                   no progress bar and no summary\n"
  "overrides (default: derived from the data, see the summary):\n"
  "  --candidate-neighbors K   stage-1 neighbourhood size\n"
  "  --rmls-neighbors K        stage-2 neighbourhood size\n"
  "  --threshold T             stage-1 residual threshold (distance)\n"
  "  --rmls-tolerance D        stage-2 residual tolerance (distance)\n"
  "  --sharpness-angle DEG     smallest angle between the normals of two surfaces (25)\n"
  "  --corner-radius D         corner points closer than D are one corner\n"
  "  --growth-radius D         polyline growing radius\n"
  "  --completion-distance D   largest gap bridged by completion\n"
  "  --smoothing-passes N      stage-3 passes (3)\n";

[[noreturn]] void fail(const std::string& message)
{
  sfe_utilities::fail("extract_sharp_features", message);
}

double number(const std::string& option, const char* text)
{
  return sfe_utilities::non_negative_number("extract_sharp_features", option, text);
}

/// One line per point: its patch, or -1.
bool write_patch_labels(const std::string& path, const CGAL::Surface_patches<K>& patches)
{
  std::ofstream out(path);
  for(std::size_t label : patches.labels)
    out << (label == CGAL::Surface_patches<K>::unassigned ? -1 : static_cast<long long>(label)) << '\n';
  return bool(out);
}

} // namespace

int main(int argc, char** argv)
{
  std::string input, output, ply, patches_file;
  int threads = 0;
  bool quiet = false;
  double candidate_neighbors = 0, rmls_neighbors = 0, threshold = -1, tolerance = 0, sharpness = 25;
  double corner_radius = 0, growth_radius = 0, completion_distance = 0, passes = 3;
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
    else if(a == "--ply") ply = value();
    else if(a == "--patches") patches_file = value();
    else if(a == "--threads") threads = int(number(a, value()));
    else if(a == "--quiet") quiet = true;
    else if(a == "--candidate-neighbors") candidate_neighbors = number(a, value());
    else if(a == "--rmls-neighbors") rmls_neighbors = number(a, value());
    else if(a == "--threshold") threshold = number(a, value());
    else if(a == "--rmls-tolerance") tolerance = number(a, value());
    else if(a == "--sharpness-angle") sharpness = number(a, value());
    else if(a == "--corner-radius") corner_radius = number(a, value());
    else if(a == "--growth-radius") growth_radius = number(a, value());
    else if(a == "--completion-distance") completion_distance = number(a, value());
    else if(a == "--smoothing-passes") passes = number(a, value());
    else if(!a.empty() && a[0] == '-') fail("unknown option " + a + " (see --help)");
    else if(input.empty()) input = a;
    else fail("more than one input file given (see --help)");
  }
  if(input.empty() || output.empty())
    fail("an input file and -o OUTPUT are required (see --help)");

#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> thread_limit;
  if(threads > 0)
    thread_limit.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism, threads));
#endif

  std::vector<Point> points;
  std::string why;
  if(!CGAL::IO::read_point_cloud(input, points, &why))
    fail("cannot read '" + input + "': " + why);
  if(points.empty())
    fail("'" + input + "' contains no points");

  std::function<bool(double)> progress;
  if(!quiet)
    progress = sfe_utilities::Terminal_progress_bar("extracting sharp features");
  CGAL::Sharp_features<K> result;
  CGAL::Surface_patches<K> patches;
  try
  {
    const auto np = sfe::candidate_neighbors(std::size_t(candidate_neighbors),
                    sfe::rmls_neighbors(std::size_t(rmls_neighbors),
                    sfe::rmls_tolerance(tolerance,
                    sfe::corner_radius(corner_radius,
                    sfe::growth_radius(growth_radius,
                    sfe::completion_distance(completion_distance))))))
                      .threshold_distance(threshold)
                      .sharpness_angle(sharpness)
                      .number_of_iterations(unsigned(passes))
                      .callback(progress);
    const CGAL::Sharp_feature_extraction_context<K> context(points, np);
    context.extract_sharp_features(result);
    if(!patches_file.empty())
    {
      std::function<bool(double)> patch_progress;
      if(!quiet)
        patch_progress = sfe_utilities::Terminal_progress_bar("segmenting into patches");
      context.segment_into_patches(result.network, patches, CGAL::parameters::callback(patch_progress));
    }
  }
  catch(const std::exception& e)
  {
    fail(e.what());
  }

  std::vector<std::vector<Point>> polylines;
  for(const auto& p : result.network.polylines)
    polylines.push_back(p.points);
  if(!CGAL::IO::write_polylines(output, polylines))
    fail("cannot write '" + output + "'");
  if(!ply.empty()
     && !(patches_file.empty() ? CGAL::IO::write_PLY_feature_curves(ply, result.network)
                               : CGAL::IO::write_PLY_feature_curves(ply, result.network, points, patches)))
    fail("cannot write '" + ply + "'");
  if(!patches_file.empty() && !write_patch_labels(patches_file, patches))
    fail("cannot write '" + patches_file + "'");

  if(!quiet)
  {
    std::size_t loops = 0;
    for(const auto& p : result.network.polylines)
      loops += p.is_closed() ? 1 : 0;
    const auto& s = result.network.scales;
    const auto& t = result.timings;
    std::cout << "points            " << points.size() << "\n"
              << "candidates        " << result.candidates.indices.size() << "\n"
              << "edge points       " << result.projected.edge_points.size() << "\n"
              << "corner points     " << result.projected.corner_points.size() << "\n"
              << "curves            " << result.network.polylines.size() << " (" << loops << " closed loops)\n"
              << "corners           " << result.network.corners.size() << "\n"
              << (patches_file.empty() ? "" : "patches           " + std::to_string(patches.patches.size()) + "\n")
              << "scales            spacing " << s.spacing << ", noise " << s.noise << ", neighbours "
              << s.candidate_neighbors << "/" << s.rmls_neighbors << ", threshold " << s.residual_threshold
              << ", RMLS tolerance " << s.rmls_tolerance << ", corner radius " << s.corner_radius
              << ", growth radius " << s.growth_radius << ", completion " << s.completion_distance
              << ", sampled fraction " << s.sampled_fraction << ", search fraction " << s.search_fraction << "\n"
              << "time [s]          context " << t.context << ", candidates " << t.candidates
              << ", projection " << t.projection
              << ", smoothing " << t.smoothing << ", growing " << t.growing << ", completion " << t.completion
              << ", total " << t.total() << "\n"
              << "wrote             " << output << (ply.empty() ? "" : ", " + ply)
              << (patches_file.empty() ? "" : ", " + patches_file) << std::endl;
  }
  return 0;
}
