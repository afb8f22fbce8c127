// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the benchmark runners share: command-line options, the test cloud of a run, and a
// one-line JSON writer for the results (one line per measured configuration).

#ifndef SFE_BENCHMARK_BENCH_SUPPORT_H
#define SFE_BENCHMARK_BENCH_SUPPORT_H

#include "feature_scoring.h"
#include "scan_simulation.h"

#include <utilities/mesh_surface_sampling.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace sfe_bench {

/// `--key value` pairs; every key must be known to the program.
class Command_line
{
public:
  Command_line(int argc, char** argv, const std::map<std::string, std::string>& defaults)
    : values_(defaults)
  {
    for(int i = 1; i < argc; ++i)
    {
      const std::string key = argv[i];
      if(key.size() < 3 || key.compare(0, 2, "--") != 0 || values_.count(key.substr(2)) == 0)
        throw std::invalid_argument("unknown option '" + key + "'\n" + usage());
      if(i + 1 >= argc)
        throw std::invalid_argument("option '" + key + "' needs a value");
      values_[key.substr(2)] = argv[++i];
    }
  }
  std::string usage() const
  {
    std::ostringstream out;
    out << "options (default):";
    for(const auto& entry : values_)
      out << " --" << entry.first << " (" << entry.second << ")";
    return out.str();
  }
  std::string text(const std::string& key) const { return values_.at(key); }
  double number(const std::string& key) const { return std::stod(values_.at(key)); }
  std::vector<double> numbers(const std::string& key) const
  {
    std::vector<double> result;
    std::stringstream list(values_.at(key));
    std::string item;
    while(std::getline(list, item, ','))
      if(!item.empty())
        result.push_back(std::stod(item));
    return result;
  }

private:
  std::map<std::string, std::string> values_;
};

/// The options that define a test cloud, shared by every runner so that ours and the peer
/// see exactly the same points. With `--scan-views V` (1 to 8) the cloud is a simulated scan
/// (scan_simulation.h) instead of a uniform sample: `--points` is then the number of returns,
/// `--noise` the range noise along the rays, `--scan-lines` the spacing of the scan lines over
/// the spacing along them, `--scan-window` the ray grid's width over the object's,
/// `--misregistration` the shift of the last view (fraction of dB), and `--no-returns 1` writes
/// the rays without return as (0,0,0). For either kind, `--offset X` adds (X, X, X) to every
/// point except those (0,0,0) (georeferenced coordinates; the truth is moved with it) and
/// `--duplicates D` appends D exact copies of the cloud's points (the whole cloud over and over).
inline std::map<std::string, std::string> cloud_option_defaults()
{
  return {{"mesh", ""},       {"truth", ""},       {"points", "100000"},    {"noise", "0"},
          {"outliers", "0"},  {"denser", "1"},     {"seed", "1"},           {"label", ""},
          {"output", "-"},    {"scan-views", "0"}, {"scan-lines", "1"},     {"scan-window", "1"},
          {"misregistration", "0"}, {"no-returns", "0"}, {"offset", "0"}, {"duplicates", "0"}};
}

inline std::vector<std::array<double, 3>> scan_cloud(const sfe_utilities::Triangle_soup& soup,
                                                     const Command_line& options)
{
  if(options.number("outliers") != 0 || options.number("denser") != 1)
    throw std::invalid_argument("--outliers and --denser do not apply to a scan (--scan-views)");
  sfe_scan::Scan_options scan;
  scan.views = std::size_t(options.number("scan-views"));
  scan.returns = std::size_t(options.number("points"));
  scan.range_noise = options.number("noise");
  scan.line_spacing_ratio = options.number("scan-lines");
  scan.window = options.number("scan-window");
  scan.misregistration = options.number("misregistration");
  scan.no_returns_as_origin = options.number("no-returns") != 0;
  scan.offset = {{options.number("offset"), options.number("offset"), options.number("offset")}};
  scan.seed = std::uint64_t(options.number("seed"));
  return sfe_scan::scan_mesh(sfe_scan::Mesh{soup.vertices, soup.triangles}, scan).points;
}

inline std::vector<Point> make_cloud(const Command_line& options)
{
  const sfe_utilities::Triangle_soup soup = sfe_utilities::read_triangle_soup(options.text("mesh"));
  std::vector<std::array<double, 3>> samples;
  const double offset = options.number("offset");
  if(options.number("scan-views") > 0)
    samples = scan_cloud(soup, options);
  else
  {
    sfe_utilities::Sampling_options sampling;
    sampling.number_of_points = std::size_t(options.number("points"));
    sampling.noise = options.number("noise");
    sampling.outlier_fraction = options.number("outliers");
    sampling.denser_half_factor = options.number("denser");
    sampling.seed = unsigned(options.number("seed"));
    samples = sfe_utilities::sample_triangle_soup(soup, sampling);
    for(std::array<double, 3>& p : samples)
      p = {{p[0] + offset, p[1] + offset, p[2] + offset}};
  }
  const std::size_t distinct = samples.size(), duplicates = std::size_t(options.number("duplicates"));
  if(duplicates > 0 && distinct == 0)
    throw std::invalid_argument("--duplicates of an empty cloud");
  std::vector<Point> cloud;
  cloud.reserve(distinct + duplicates);
  for(std::size_t i = 0; i < distinct + duplicates; ++i)
    cloud.emplace_back(samples[i % distinct][0], samples[i % distinct][1], samples[i % distinct][2]);
  return cloud;
}

/// The ground truth of `--truth`, moved by `--offset` as the cloud is.
inline Ground_truth read_cloud_truth(const Command_line& options)
{
  Ground_truth truth = read_ground_truth(options.text("truth"));
  const double offset = options.number("offset");
  const Vector shift(offset, offset, offset);
  for(Polyline& curve : truth.curves)
    for(Point& p : curve)
      p = p + shift;
  for(Point& p : truth.corners)
    p = p + shift;
  return truth;
}

/// Wall-clock seconds since construction.
class Stopwatch
{
public:
  double seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// A flat JSON object built key by key, printed on one line.
class Json_line
{
public:
  Json_line& add(const std::string& key, const std::string& value)
  {
    std::string escaped;
    for(char c : value)
    {
      if(c == '"' || c == '\\')
        escaped += '\\';
      escaped += c;
    }
    return raw(key, "\"" + escaped + "\"");
  }
  Json_line& add(const std::string& key, const char* value) { return add(key, std::string(value)); }
  Json_line& add(const std::string& key, double value)
  {
    if(!std::isfinite(value))
      return raw(key, "null");
    std::ostringstream out;
    out.precision(10);
    out << value;
    return raw(key, out.str());
  }
  Json_line& add(const std::string& key, std::size_t value) { return raw(key, std::to_string(value)); }
  Json_line& add(const std::string& key, int value) { return raw(key, std::to_string(value)); }
  Json_line& add(const std::string& key, bool value) { return raw(key, value ? "true" : "false"); }

  /// Appends the line to `path` ("-" for standard output).
  void write(const std::string& path) const
  {
    const std::string line = "{" + body_ + "}\n";
    if(path == "-" || path.empty())
    {
      std::cout << line << std::flush;
      return;
    }
    std::ofstream out(path, std::ios::app);
    if(!(out << line))
      throw std::runtime_error("cannot append to " + path);
  }

private:
  Json_line& raw(const std::string& key, const std::string& value)
  {
    if(!body_.empty())
      body_ += ", ";
    body_ += "\"" + key + "\": " + value;
    return *this;
  }
  std::string body_;
};

/// eps suffix of a metric name: 0.005 -> "0.5", 0.01 -> "1" (percent of dB).
inline std::string eps_tag(double fraction)
{
  std::ostringstream out;
  out << fraction * 100;
  return out.str();
}

inline void add_cloud_fields(Json_line& line, const Command_line& options, std::size_t cloud_size)
{
  line.add("label", options.text("label"))
      .add("mesh", options.text("mesh").substr(options.text("mesh").find_last_of('/') + 1))
      .add("points", std::size_t(options.number("points")))
      .add("cloud_size", cloud_size)
      .add("noise", options.number("noise"))
      .add("outliers", options.number("outliers"))
      .add("denser", options.number("denser"))
      .add("seed", std::size_t(options.number("seed")))
      .add("scan_views", std::size_t(options.number("scan-views")))
      .add("scan_lines", options.number("scan-lines"))
      .add("scan_window", options.number("scan-window"))
      .add("misregistration", options.number("misregistration"))
      .add("no_returns", options.number("no-returns") != 0)
      .add("offset", options.number("offset"))
      .add("duplicates", std::size_t(options.number("duplicates")));
}

inline void add_point_fields(Json_line& line, const std::string& prefix, const Point_evaluation& evaluation,
                             bool has_truth)
{
  line.add(prefix + "_count", evaluation.points);
  if(!has_truth)
    return;
  line.add(prefix + "_mean_dist", evaluation.mean_distance);
  for(const Point_scores& s : evaluation.at_eps)
  {
    line.add(prefix + "_precision@" + eps_tag(s.eps), s.precision);
    line.add(prefix + "_coverage@" + eps_tag(s.eps), s.coverage);
  }
}

inline void add_curve_fields(Json_line& line, const std::string& prefix, const Curve_evaluation& evaluation,
                             bool has_truth)
{
  line.add(prefix + "_curves", evaluation.curves)
      .add(prefix + "_true_curves", evaluation.true_curves)
      .add(prefix + "_corners", evaluation.corners)
      .add(prefix + "_true_corners", evaluation.true_corners)
      .add(prefix + "_length", evaluation.length)
      .add(prefix + "_true_length", evaluation.true_length);
  if(!has_truth)
    return;
  line.add(prefix + "_mean_dist", evaluation.mean_distance)
      .add(prefix + "_rms_dist", evaluation.rms_distance)
      .add(prefix + "_max_dist", evaluation.max_distance);
  for(const Curve_scores& s : evaluation.at_eps)
  {
    const std::string tag = "@" + eps_tag(s.eps);
    line.add(prefix + "_recall" + tag, s.recall)
        .add(prefix + "_precision" + tag, s.precision)
        .add(prefix + "_f1" + tag, s.f1)
        .add(prefix + "_corners_found" + tag, s.true_corners_found)
        .add(prefix + "_pieces_per_true_curve" + tag, s.pieces_per_true_curve)
        .add(prefix + "_true_curves_half_recalled" + tag, s.true_curves_half_recalled);
  }
}

/// The tolerances of the report, as fractions of dB.
inline std::vector<double> report_eps() { return {0.005, 0.01}; }

} // namespace sfe_bench

#endif // SFE_BENCHMARK_BENCH_SUPPORT_H
