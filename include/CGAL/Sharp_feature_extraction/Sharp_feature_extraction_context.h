// Copyright (c) 2026 The Sharp_feature_extraction authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHARP_FEATURE_EXTRACTION_SHARP_FEATURE_EXTRACTION_CONTEXT_H
#define CGAL_SHARP_FEATURE_EXTRACTION_SHARP_FEATURE_EXTRACTION_CONTEXT_H

#include <CGAL/Sharp_feature_extraction/Sharp_features.h>
#include <CGAL/Sharp_feature_extraction/parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/Feature_data.h>
#include <CGAL/Sharp_feature_extraction/internal/Indexed_input.h>
#include <CGAL/Sharp_feature_extraction/internal/Kernel_conversion.h>
#include <CGAL/Sharp_feature_extraction/internal/Progress.h>
#include <CGAL/Sharp_feature_extraction/internal/Stage_parameters.h>
#include <CGAL/Sharp_feature_extraction/internal/candidate_points_impl.h>
#include <CGAL/Sharp_feature_extraction/internal/completion_impl.h>
#include <CGAL/Sharp_feature_extraction/internal/patches_impl.h>
#include <CGAL/Sharp_feature_extraction/internal/polyline_growing_impl.h>
#include <CGAL/Sharp_feature_extraction/internal/rmls_projection_impl.h>
#include <CGAL/Sharp_feature_extraction/internal/smoothing_impl.h>
#include <CGAL/Real_timer.h>
#include <CGAL/tags.h>

#include <cstddef>
#include <stdexcept>

namespace CGAL {

/// \ingroup PkgSharpFeatureExtractionRef
/// The extraction context: a point cloud prepared once for the five stages of Daniels et al.
/// 2007, with one member function per stage and one for the whole pipeline.
///
/// Building it reads the points through the point map (rejecting non-finite coordinates),
/// merges exact duplicates (every copy of a point takes the results of the first one: copies
/// add no surface information), sorts the distinct points along a Hilbert curve, builds their
/// spatial index (a k-d tree) and estimates every scale of the pipeline from the data (see
/// `Sharp_feature_scales` and `estimate_sharp_feature_scales()`). The stages then share that
/// index and those scales.
///
/// Each stage reads its own parameters only. The named parameters given to the constructor
/// fix the scales and set the defaults of every stage's parameters; those given to a member
/// function override them for that call. A member function given a parameter that does not
/// belong to its stage, or a scale (which the context fixed), does not compile.
///
/// Stages 2 to 5 read the scales of their input (`Candidate_points::scales`,
/// `Feature_point_set::scales`, `Feature_curve_network::scales`), which stage 1 copies from
/// the context; a user who edits them there changes what the later stages do.
///
/// The member functions are `const` and may be called from several threads at once.
///
/// \tparam GeomTraits a CGAL kernel: the type of the results (`Point_3`, `Vector_3`, `FT`).
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///   `CGAL::Parallel_if_available_tag`. The results do not depend on the number of threads.
template <typename GeomTraits, typename ConcurrencyTag = CGAL::Parallel_if_available_tag>
class Sharp_feature_extraction_context
{
public:
  /// The number type of the results.
  typedef typename GeomTraits::FT FT;

  /// Prepares `points` and estimates the scales.
  ///
  /// \param points a model of `ConstRange` whose value type is the key of `point_map`; no
  ///   normals are needed. A cloud with fewer than 20 distinct points, or without extent, gets
  ///   zero scales and yields no features.
  /// \param np optional named parameters among the ones listed below: the scales, which the
  ///   context fixes, and the parameters of every stage, which become the defaults of the member
  ///   functions (a member function given one overrides it for that call).
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{point_map}
  ///     \cgalParamDescription{a property map associating points to the elements of `points`}
  ///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `GeomTraits::Point_3`}
  ///     \cgalParamDefault{`CGAL::Identity_property_map<GeomTraits::Point_3>`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{degree_fitting}
  ///     \cgalParamDescription{degree of the fitted height fields: 1 (planes) or 2 (quadrics)}
  ///     \cgalParamType{`int`}
  ///     \cgalParamDefault{2}
  ///     \cgalParamExtra{also the degree of the fits that estimate the noise, from which the
  ///       scales are derived; the default of the member functions that read it (see
  ///       `CGAL::compute_candidate_points()` and `CGAL::rmls_project_candidates()`)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{threshold_distance}
  ///     \cgalParamDescription{the candidate threshold tau (a distance)}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{the mean residual of the points whose residual is at most the radius of
  ///       a stage-1 neighbourhood; on noisy clouds at most 1.3 times the median residual}
  ///     \cgalParamExtra{a negative value selects the default; the default of the member functions
  ///       that read it (see `CGAL::compute_candidate_points()`)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{sharpness_angle}
  ///     \cgalParamDescription{smallest angle, in degrees, between the normals of two surfaces
  ///       that meet at a sharp feature}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{25}
  ///     \cgalParamExtra{must be in (0, 90); the default of the member functions that read it (see
  ///       `CGAL::rmls_project_candidates()`)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_iterations}
  ///     \cgalParamDescription{number of smoothing passes}
  ///     \cgalParamType{`unsigned int`}
  ///     \cgalParamDefault{3}
  ///     \cgalParamExtra{the default of the member functions that read it (see
  ///       `CGAL::smooth_feature_points()`)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{maximum_angle}
  ///     \cgalParamDescription{half-angle, in degrees, of the completion search cone at a free end}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{30}
  ///     \cgalParamExtra{must be in (0, 90); the default of the member functions that read it (see
  ///       `CGAL::complete_feature_polylines()`)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_relaxation_steps}
  ///     \cgalParamDescription{number of Laplacian smoothing passes over the completed curves}
  ///     \cgalParamType{`unsigned int`}
  ///     \cgalParamDefault{2}
  ///     \cgalParamExtra{the default of the member functions that read it (see
  ///       `CGAL::complete_feature_polylines()`)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{callback}
  ///     \cgalParamDescription{a function that receives the progress and can stop the computation}
  ///     \cgalParamType{`std::function<bool(double)>`}
  ///     \cgalParamDefault{none}
  ///     \cgalParamExtra{not called by the constructor: it becomes the default callback of the
  ///       member functions of stages 1 to 4 and of `CGAL::extract_sharp_features()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::candidate_neighbors}
  ///     \cgalParamDescription{number of points in a stage-1 neighbourhood}
  ///     \cgalParamType{`std::size_t`}
  ///     \cgalParamDefault{derived from the data (see `estimate_sharp_feature_scales()`)}
  ///     \cgalParamExtra{0 selects the default; clamped to [7, number of distinct points]; the
  ///       scales derived from a given one follow, as `estimate_sharp_feature_scales()` explains}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_neighbors}
  ///     \cgalParamDescription{number of points in a stage-2 (RMLS) neighbourhood}
  ///     \cgalParamType{`std::size_t`}
  ///     \cgalParamDefault{derived from the data (see `estimate_sharp_feature_scales()`)}
  ///     \cgalParamExtra{0 selects the default; clamped to [7, number of distinct points]; the
  ///       scales derived from a given one follow, as `estimate_sharp_feature_scales()` explains}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_tolerance}
  ///     \cgalParamDescription{largest residual (a distance) of a point that belongs to a smooth
  ///       surface in the forward search of stage 2}
  ///     \cgalParamType{`double` (a distance)}
  ///     \cgalParamDefault{derived from the data (see `estimate_sharp_feature_scales()`)}
  ///     \cgalParamExtra{0 selects the default; the scales derived from a given one follow, as
  ///       `estimate_sharp_feature_scales()` explains}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::corner_radius}
  ///     \cgalParamDescription{corner points closer than this distance are grouped into one corner
  ///       (stage 2)}
  ///     \cgalParamType{`double` (a distance)}
  ///     \cgalParamDefault{derived from the data (see `estimate_sharp_feature_scales()`)}
  ///     \cgalParamExtra{0 selects the default; the scales derived from a given one follow, as
  ///       `estimate_sharp_feature_scales()` explains}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::growth_radius}
  ///     \cgalParamDescription{neighbourhood radius of polyline growing (stage 4)}
  ///     \cgalParamType{`double` (a distance)}
  ///     \cgalParamDefault{derived from the data (see `estimate_sharp_feature_scales()`)}
  ///     \cgalParamExtra{0 selects the default; the scales derived from a given one follow, as
  ///       `estimate_sharp_feature_scales()` explains}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::completion_distance}
  ///     \cgalParamDescription{largest gap bridged by completion (stage 5)}
  ///     \cgalParamType{`double` (a distance)}
  ///     \cgalParamDefault{derived from the data (see `estimate_sharp_feature_scales()`)}
  ///     \cgalParamExtra{0 selects the default; the scales derived from a given one follow, as
  ///       `estimate_sharp_feature_scales()` explains}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \throws std::invalid_argument if a coordinate is not finite or a parameter is out of range.
  template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
  explicit Sharp_feature_extraction_context(const PointRange& points,
                                            const NamedParameters& np = parameters::default_values())
  {
    CGAL::Real_timer timer;
    timer.start();
    read_stage_parameters(np);
    index(points, np);
    Sharp_feature_extraction::internal::estimate_scales<ConcurrencyTag>(
      m_input, Sharp_feature_extraction::internal::read_scale_parameters(np),
      Sharp_feature_extraction::internal::Progress(), m_scales);
    m_construction_time = timer.time();
  }

  /// Prepares `points` with known scales (from an earlier context or run on the same points,
  /// possibly edited): the estimation is skipped.
  ///
  /// \param points as for the other constructor.
  /// \param scales the scales of the context.
  /// \param np optional named parameters among the ones listed below: the parameters of every
  ///   stage, as for the other constructor, and the scales, each of which replaces the one in
  ///   `scales` (the others stay as given).
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{point_map}
  ///     \cgalParamDescription{a property map associating points to the elements of `points`}
  ///     \cgalParamType{a model of `ReadablePropertyMap` whose value type is `GeomTraits::Point_3`}
  ///     \cgalParamDefault{`CGAL::Identity_property_map<GeomTraits::Point_3>`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{degree_fitting}
  ///     \cgalParamDescription{degree of the fitted height fields: 1 (planes) or 2 (quadrics)}
  ///     \cgalParamType{`int`}
  ///     \cgalParamDefault{2}
  ///     \cgalParamExtra{the default of the member functions that read it (see
  ///       `CGAL::compute_candidate_points()` and `CGAL::rmls_project_candidates()`); the
  ///       scales are given, so it does not change them}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{threshold_distance}
  ///     \cgalParamDescription{the candidate threshold tau (a distance)}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{the mean residual of the points whose residual is at most the radius of
  ///       a stage-1 neighbourhood; on noisy clouds at most 1.3 times the median residual}
  ///     \cgalParamExtra{a negative value selects the default; the default of the member functions
  ///       that read it (see `CGAL::compute_candidate_points()`)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{sharpness_angle}
  ///     \cgalParamDescription{smallest angle, in degrees, between the normals of two surfaces
  ///       that meet at a sharp feature}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{25}
  ///     \cgalParamExtra{must be in (0, 90); the default of the member functions that read it (see
  ///       `CGAL::rmls_project_candidates()`)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_iterations}
  ///     \cgalParamDescription{number of smoothing passes}
  ///     \cgalParamType{`unsigned int`}
  ///     \cgalParamDefault{3}
  ///     \cgalParamExtra{the default of the member functions that read it (see
  ///       `CGAL::smooth_feature_points()`)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{maximum_angle}
  ///     \cgalParamDescription{half-angle, in degrees, of the completion search cone at a free end}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{30}
  ///     \cgalParamExtra{must be in (0, 90); the default of the member functions that read it (see
  ///       `CGAL::complete_feature_polylines()`)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_relaxation_steps}
  ///     \cgalParamDescription{number of Laplacian smoothing passes over the completed curves}
  ///     \cgalParamType{`unsigned int`}
  ///     \cgalParamDefault{2}
  ///     \cgalParamExtra{the default of the member functions that read it (see
  ///       `CGAL::complete_feature_polylines()`)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{callback}
  ///     \cgalParamDescription{a function that receives the progress and can stop the computation}
  ///     \cgalParamType{`std::function<bool(double)>`}
  ///     \cgalParamDefault{none}
  ///     \cgalParamExtra{not called by the constructor: it becomes the default callback of the
  ///       member functions of stages 1 to 4 and of `CGAL::extract_sharp_features()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::candidate_neighbors}
  ///     \cgalParamDescription{number of points in a stage-1 neighbourhood}
  ///     \cgalParamType{`std::size_t`}
  ///     \cgalParamDefault{`scales.candidate_neighbors`}
  ///     \cgalParamExtra{0 keeps `scales.candidate_neighbors`; the other scales do not follow a
  ///       given one}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_neighbors}
  ///     \cgalParamDescription{number of points in a stage-2 (RMLS) neighbourhood}
  ///     \cgalParamType{`std::size_t`}
  ///     \cgalParamDefault{`scales.rmls_neighbors`}
  ///     \cgalParamExtra{0 keeps `scales.rmls_neighbors`; the other scales do not follow a given
  ///       one}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_tolerance}
  ///     \cgalParamDescription{largest residual (a distance) of a point that belongs to a smooth
  ///       surface in the forward search of stage 2}
  ///     \cgalParamType{`double` (a distance)}
  ///     \cgalParamDefault{`scales.rmls_tolerance`}
  ///     \cgalParamExtra{0 keeps `scales.rmls_tolerance`; the other scales do not follow a given
  ///       one}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::corner_radius}
  ///     \cgalParamDescription{corner points closer than this distance are grouped into one corner
  ///       (stage 2)}
  ///     \cgalParamType{`double` (a distance)}
  ///     \cgalParamDefault{`scales.corner_radius`}
  ///     \cgalParamExtra{0 keeps `scales.corner_radius`; the other scales do not follow a given
  ///       one}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::growth_radius}
  ///     \cgalParamDescription{neighbourhood radius of polyline growing (stage 4)}
  ///     \cgalParamType{`double` (a distance)}
  ///     \cgalParamDefault{`scales.growth_radius`}
  ///     \cgalParamExtra{0 keeps `scales.growth_radius`; the other scales do not follow a given
  ///       one}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::completion_distance}
  ///     \cgalParamDescription{largest gap bridged by completion (stage 5)}
  ///     \cgalParamType{`double` (a distance)}
  ///     \cgalParamDefault{`scales.completion_distance`}
  ///     \cgalParamExtra{0 keeps `scales.completion_distance`; the other scales do not follow a
  ///       given one}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \throws std::invalid_argument if a coordinate is not finite, a parameter is out of range,
  ///   or a scale is negative or not finite, or `scales.sampled_fraction` is not in (0, 1], or
  ///   `scales.search_fraction` is not in (0, `scales.sampled_fraction`].
  template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
  Sharp_feature_extraction_context(const PointRange& points, const Sharp_feature_scales<FT>& scales,
                                   const NamedParameters& np = parameters::default_values())
  {
    CGAL::Real_timer timer;
    timer.start();
    read_stage_parameters(np);
    index(points, np);
    m_scales = Sharp_feature_extraction::internal::convert_scales<double>(scales);
    Sharp_feature_extraction::internal::override_scales(np, m_scales);
    Sharp_feature_extraction::internal::sample_input<ConcurrencyTag>(m_scales, m_input);
    m_construction_time = timer.time();
  }

  /// The scales estimated from the points, or given.
  Sharp_feature_scales<FT> scales() const
  {
    return Sharp_feature_extraction::internal::convert_scales<FT>(m_scales);
  }

  /// The number of input points, copies included.
  std::size_t number_of_points() const { return m_input.input_size(); }

  /// The number of points that stage 1 and the forward search of stage 2 run on: the distinct
  /// input points, unless the noise made the context thin the cloud (see
  /// `Sharp_feature_scales::sampled_fraction` and `Sharp_feature_scales::search_fraction`).
  std::size_t number_of_distinct_points() const { return m_input.points.size(); }

  /// Wall-clock time taken by the constructor, in seconds.
  double construction_time() const { return m_construction_time; }

  /// Stage 1: see `CGAL::compute_candidate_points()`, with the scales of the context.
  /// \param candidates receives the residuals, the candidate indices and the scales.
  /// \param np optional named parameters among the ones listed below; a parameter of another
  ///   stage, or a scale (which the context fixed), does not compile.
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{degree_fitting}
  ///     \cgalParamDescription{degree of the fitted height fields: 1 (planes) or 2 (quadrics)}
  ///     \cgalParamType{`int`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise 2}
  ///     \cgalParamExtra{see `CGAL::compute_candidate_points()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{threshold_distance}
  ///     \cgalParamDescription{the candidate threshold tau (a distance)}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise the mean residual of the
  ///       points whose residual is at most the radius of a stage-1 neighbourhood; on noisy clouds
  ///       at most 1.3 times the median residual}
  ///     \cgalParamExtra{see `CGAL::compute_candidate_points()`; a negative value selects the
  ///       default}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{callback}
  ///     \cgalParamDescription{a function that receives the progress and can stop the computation}
  ///     \cgalParamType{`std::function<bool(double)>`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise none}
  ///     \cgalParamExtra{see `CGAL::compute_candidate_points()`; called, on the calling thread,
  ///       with the
  ///       fraction of the work done (from 0 to 1); when it returns `false` the computation stops
  ///       and the member function returns `false`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \returns `false` if the callback interrupted the computation.
  template <typename NamedParameters = parameters::Default_named_parameters>
  bool compute_candidate_points(Candidate_points<GeomTraits>& candidates,
                                const NamedParameters& np = parameters::default_values()) const
  {
    namespace sfe = Sharp_feature_extraction::internal;
    static_assert(sfe::holds_none_of<NamedParameters, CGAL_SFE_SCALE_PARAMETER_TAGS, CGAL::internal_np::sharpness_angle_t,
                                     CGAL::internal_np::number_of_iterations_t, CGAL::internal_np::maximum_angle_t,
                                     CGAL::internal_np::number_of_relaxation_steps_t>(),
                  "compute_candidate_points: a parameter of another stage, or a scale (the context fixed those of stage 1)");
    sfe::Candidate_output out;
    const bool completed = sfe::compute_candidates<ConcurrencyTag>(
      m_input, m_scales, sfe::read_candidate_parameters(np, m_candidate_parameters),
      sfe::Progress(sfe::read_callback(np, m_callback)), out);
    candidates = sfe::to_input_order<GeomTraits>(m_input, out);
    return completed;
  }

  /// Stage 2: see `CGAL::rmls_project_candidates()`, with the scales of `candidates`.
  /// \param candidates the output of `compute_candidate_points()` on this context.
  /// \param projected receives the edge and corner points.
  /// \param np optional named parameters among the ones listed below; a parameter of another
  ///   stage does not compile.
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{degree_fitting}
  ///     \cgalParamDescription{degree of the fitted height fields: 1 (planes) or 2 (quadrics)}
  ///     \cgalParamType{`int`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise 2}
  ///     \cgalParamExtra{see `CGAL::rmls_project_candidates()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{sharpness_angle}
  ///     \cgalParamDescription{smallest angle, in degrees, between the normals of two surfaces
  ///       that meet at a sharp feature}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise 25}
  ///     \cgalParamExtra{see `CGAL::rmls_project_candidates()`; must be in (0, 90)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{callback}
  ///     \cgalParamDescription{a function that receives the progress and can stop the computation}
  ///     \cgalParamType{`std::function<bool(double)>`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise none}
  ///     \cgalParamExtra{see `CGAL::rmls_project_candidates()`; called, on the calling thread,
  ///       with the
  ///       fraction of the work done (from 0 to 1); when it returns `false` the computation stops
  ///       and the member function returns `false`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_neighbors}
  ///     \cgalParamDescription{number of points in a stage-2 (RMLS) neighbourhood}
  ///     \cgalParamType{`std::size_t`}
  ///     \cgalParamDefault{`candidates.scales.rmls_neighbors`}
  ///     \cgalParamExtra{see `CGAL::rmls_project_candidates()`; 0 keeps
  ///       `candidates.scales.rmls_neighbors`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::rmls_tolerance}
  ///     \cgalParamDescription{largest residual (a distance) of a point that belongs to a smooth
  ///       surface in the forward search of stage 2}
  ///     \cgalParamType{`double` (a distance)}
  ///     \cgalParamDefault{`candidates.scales.rmls_tolerance`}
  ///     \cgalParamExtra{see `CGAL::rmls_project_candidates()`; 0 keeps
  ///       `candidates.scales.rmls_tolerance`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::corner_radius}
  ///     \cgalParamDescription{corner points closer than this distance are grouped into one corner
  ///       (stage 2)}
  ///     \cgalParamType{`double` (a distance)}
  ///     \cgalParamDefault{`candidates.scales.corner_radius`}
  ///     \cgalParamExtra{see `CGAL::rmls_project_candidates()`; 0 keeps
  ///       `candidates.scales.corner_radius`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \returns `false` if the callback interrupted the computation.
  /// \throws std::invalid_argument if a candidate index is out of the range of the points, or
  ///   a scale of `candidates.scales` is negative or not finite.
  template <typename NamedParameters = parameters::Default_named_parameters>
  bool rmls_project_candidates(const Candidate_points<GeomTraits>& candidates, Feature_point_set<GeomTraits>& projected,
                               const NamedParameters& np = parameters::default_values()) const
  {
    namespace sfe = Sharp_feature_extraction::internal;
    static_assert(sfe::holds_only_projection_parameters<NamedParameters>(),
                  "rmls_project_candidates: a parameter of another stage");
    for(std::size_t i : candidates.indices)
      if(i >= m_input.input_size())
        throw std::invalid_argument("rmls_project_candidates: candidate index out of range of the points");
    sfe::Scales scales = sfe::convert_scales<double>(candidates.scales);
    sfe::override_scales(np, scales);
    sfe::Working_feature_points out;
    const bool completed = sfe::rmls_project<ConcurrencyTag>(
      m_input, m_input.positions(candidates.indices), m_input.in_spatial_order(candidates.residuals),
      scales, sfe::read_projection_parameters(np, m_projection_parameters),
      sfe::Progress(sfe::read_callback(np, m_callback)), out);
    projected = sfe::convert_feature_points<GeomTraits>(out);
    return completed;
  }

  /// Stage 3: see `CGAL::smooth_feature_points()`.
  /// \param features the output of `CGAL::rmls_project_candidates()`, smoothed in place.
  /// \param np optional named parameters among the ones listed below; a parameter of another
  ///   stage, or a scale (which the context fixed), does not compile.
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{number_of_iterations}
  ///     \cgalParamDescription{number of smoothing passes}
  ///     \cgalParamType{`unsigned int`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise 3}
  ///     \cgalParamExtra{see `CGAL::smooth_feature_points()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{callback}
  ///     \cgalParamDescription{a function that receives the progress and can stop the computation}
  ///     \cgalParamType{`std::function<bool(double)>`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise none}
  ///     \cgalParamExtra{see `CGAL::smooth_feature_points()`; called, on the calling thread, with
  ///       the
  ///       fraction of the work done (from 0 to 1); when it returns `false` the computation stops
  ///       and the member function returns `false`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \returns `false` if the callback interrupted the computation (`features` is then unchanged).
  template <typename NamedParameters = parameters::Default_named_parameters>
  bool smooth_feature_points(Feature_point_set<GeomTraits>& features,
                             const NamedParameters& np = parameters::default_values()) const
  {
    namespace sfe = Sharp_feature_extraction::internal;
    static_assert(sfe::holds_only_smoothing_parameters<NamedParameters>(),
                  "smooth_feature_points: a parameter of another stage, or a scale (fixed by the context)");
    return sfe::smooth_feature_point_set<ConcurrencyTag>(features, sfe::read_smoothing_parameters(np, m_smoothing_parameters),
                                                         sfe::read_callback(np, m_callback));
  }

  /// Stage 4: see `CGAL::grow_feature_polylines()`, with the growth radius of `features.scales`.
  /// \param features the output of `CGAL::smooth_feature_points()`.
  /// \param network receives the polylines and the corners.
  /// \param np optional named parameters among the ones listed below; a parameter of another
  ///   stage does not compile.
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{callback}
  ///     \cgalParamDescription{a function that receives the progress and can stop the computation}
  ///     \cgalParamType{`std::function<bool(double)>`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise none}
  ///     \cgalParamExtra{see `CGAL::grow_feature_polylines()`; called, on the calling thread, with
  ///       the
  ///       fraction of the work done (from 0 to 1); when it returns `false` the computation stops
  ///       and the member function returns `false`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::growth_radius}
  ///     \cgalParamDescription{neighbourhood radius of polyline growing (stage 4)}
  ///     \cgalParamType{`double` (a distance)}
  ///     \cgalParamDefault{`features.scales.growth_radius`}
  ///     \cgalParamExtra{see `CGAL::grow_feature_polylines()`; 0 keeps
  ///       `features.scales.growth_radius`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \returns `false` if the callback interrupted the computation.
  /// \throws std::invalid_argument if a parameter is out of range or a scale of
  ///   `features.scales` is negative or not finite.
  template <typename NamedParameters = parameters::Default_named_parameters>
  bool grow_feature_polylines(const Feature_point_set<GeomTraits>& features, Feature_curve_network<GeomTraits>& network,
                              const NamedParameters& np = parameters::default_values()) const
  {
    namespace sfe = Sharp_feature_extraction::internal;
    static_assert(sfe::holds_only_growing_parameters<NamedParameters>(),
                  "grow_feature_polylines: a parameter of another stage");
    return sfe::grow_feature_curve_network(features, network, np, sfe::read_callback(np, m_callback));
  }

  /// Stage 5: see `CGAL::complete_feature_polylines()`, with the scales of `network.scales`.
  /// \param network the output of `CGAL::grow_feature_polylines()`, completed in place.
  /// \param np optional named parameters among the ones listed below; a parameter of another
  ///   stage, and `callback`, do not compile.
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{maximum_angle}
  ///     \cgalParamDescription{half-angle, in degrees, of the search cone at a free end}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise 30}
  ///     \cgalParamExtra{see `CGAL::complete_feature_polylines()`; must be in (0, 90)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_relaxation_steps}
  ///     \cgalParamDescription{number of Laplacian smoothing passes over the completed curves}
  ///     \cgalParamType{`unsigned int`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise 2}
  ///     \cgalParamExtra{see `CGAL::complete_feature_polylines()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{Sharp_feature_extraction::parameters::completion_distance}
  ///     \cgalParamDescription{largest gap bridged by completion (stage 5)}
  ///     \cgalParamType{`double` (a distance)}
  ///     \cgalParamDefault{`network.scales.completion_distance`}
  ///     \cgalParamExtra{see `CGAL::complete_feature_polylines()`; 0 keeps
  ///       `network.scales.completion_distance`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \throws std::invalid_argument if a parameter is out of range or a scale of
  ///   `network.scales` is negative or not finite.
  template <typename NamedParameters = parameters::Default_named_parameters>
  void complete_feature_polylines(Feature_curve_network<GeomTraits>& network,
                                  const NamedParameters& np = parameters::default_values()) const
  {
    namespace sfe = Sharp_feature_extraction::internal;
    static_assert(sfe::holds_only_completion_parameters<NamedParameters>(),
                  "complete_feature_polylines: a parameter of another stage");
    sfe::complete_feature_curve_network(network, np, sfe::read_completion_parameters(np, m_completion_parameters));
  }

  /// The surface patches bounded by the curves of `network`: see `CGAL::segment_into_patches()`,
  /// with the scales of `network.scales`.
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{callback}
  ///     \cgalParamDescription{receives the progress in [0,1]; returning `false` stops the computation}
  ///     \cgalParamType{`std::function<bool(double)>`}
  ///     \cgalParamDefault{the one given to the constructor, if any}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \returns `false` if the callback interrupted the computation (`patches` is then empty).
  template <typename NamedParameters = parameters::Default_named_parameters>
  bool segment_into_patches(const Feature_curve_network<GeomTraits>& network, Surface_patches<GeomTraits>& patches,
                            const NamedParameters& np = parameters::default_values()) const
  {
    namespace sfe = Sharp_feature_extraction::internal;
    static_assert(sfe::holds_only_patch_parameters<NamedParameters>(),
                  "segment_into_patches: a parameter of another stage");
    sfe::Working_patches working;
    patches = Surface_patches<GeomTraits>();
    if(!sfe::segment_patches<ConcurrencyTag>(m_input, sfe::convert_network<sfe::Working_traits>(network),
                                             sfe::Progress(sfe::read_callback(np, m_callback)), working))
      return false;
    patches = sfe::convert_patches<GeomTraits>(working);
    return true;
  }

  /// The five stages: see `CGAL::extract_sharp_features()`.
  /// \param result receives the curves, corners, normals and every intermediate point set.
  /// \param np optional named parameters among the ones listed below: those of every stage; a
  ///   scale (which the context fixed: give it to the constructor) does not compile.
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{degree_fitting}
  ///     \cgalParamDescription{degree of the fitted height fields: 1 (planes) or 2 (quadrics)}
  ///     \cgalParamType{`int`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise 2}
  ///     \cgalParamExtra{see `CGAL::compute_candidate_points()` and
  ///       `CGAL::rmls_project_candidates()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{threshold_distance}
  ///     \cgalParamDescription{the candidate threshold tau (a distance)}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise the mean residual of the
  ///       points whose residual is at most the radius of a stage-1 neighbourhood; on noisy clouds
  ///       at most 1.3 times the median residual}
  ///     \cgalParamExtra{see `CGAL::compute_candidate_points()`; a negative value selects the
  ///       default}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{sharpness_angle}
  ///     \cgalParamDescription{smallest angle, in degrees, between the normals of two surfaces
  ///       that meet at a sharp feature}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise 25}
  ///     \cgalParamExtra{see `CGAL::rmls_project_candidates()`; must be in (0, 90)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_iterations}
  ///     \cgalParamDescription{number of smoothing passes}
  ///     \cgalParamType{`unsigned int`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise 3}
  ///     \cgalParamExtra{see `CGAL::smooth_feature_points()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{maximum_angle}
  ///     \cgalParamDescription{half-angle, in degrees, of the completion search cone at a free end}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise 30}
  ///     \cgalParamExtra{see `CGAL::complete_feature_polylines()`; must be in (0, 90)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_relaxation_steps}
  ///     \cgalParamDescription{number of Laplacian smoothing passes over the completed curves}
  ///     \cgalParamType{`unsigned int`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise 2}
  ///     \cgalParamExtra{see `CGAL::complete_feature_polylines()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{callback}
  ///     \cgalParamDescription{a function that receives the progress and can stop the computation}
  ///     \cgalParamType{`std::function<bool(double)>`}
  ///     \cgalParamDefault{the value given to the constructor, otherwise none}
  ///     \cgalParamExtra{see `CGAL::extract_sharp_features()`; called with the fraction of the
  ///       work of
  ///       stages 1 to 4 done (from 0 to 1)}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// \returns `false` if the callback interrupted the computation (the result is then partial).
  template <typename NamedParameters = parameters::Default_named_parameters>
  bool extract_sharp_features(Sharp_features<GeomTraits>& result,
                              const NamedParameters& np = parameters::default_values()) const
  {
    namespace sfe = Sharp_feature_extraction::internal;
    static_assert(sfe::holds_none_of<NamedParameters, CGAL_SFE_SCALE_PARAMETER_TAGS>(),
                  "extract_sharp_features: the scales are fixed by the context; give them to its constructor");
    return run_pipeline(result, sfe::read_candidate_parameters(np, m_candidate_parameters),
                        sfe::read_projection_parameters(np, m_projection_parameters),
                        sfe::read_smoothing_parameters(np, m_smoothing_parameters),
                        sfe::read_completion_parameters(np, m_completion_parameters),
                        sfe::read_callback(np, m_callback));
  }

private:
  Sharp_feature_extraction::internal::Indexed_input m_input;
  Sharp_feature_extraction::internal::Scales m_scales;
  Sharp_feature_extraction::internal::Candidate_parameters m_candidate_parameters;
  Sharp_feature_extraction::internal::Projection_parameters m_projection_parameters;
  Sharp_feature_extraction::internal::Smoothing_parameters m_smoothing_parameters;
  Sharp_feature_extraction::internal::Completion_parameters m_completion_parameters;
  Sharp_feature_extraction::internal::Progress_callback m_callback;
  double m_construction_time = 0;

  template <typename NamedParameters>
  void read_stage_parameters(const NamedParameters& np)
  {
    namespace sfe = Sharp_feature_extraction::internal;
    m_candidate_parameters = sfe::read_candidate_parameters(np);
    m_projection_parameters = sfe::read_projection_parameters(np);
    m_smoothing_parameters = sfe::read_smoothing_parameters(np);
    m_completion_parameters = sfe::read_completion_parameters(np);
    m_callback = sfe::read_callback(np);
  }

  template <typename PointRange, typename NamedParameters>
  void index(const PointRange& points, const NamedParameters& np)
  {
    Sharp_feature_extraction::internal::index_input_points<ConcurrencyTag>(points, np, m_input);
  }

  bool run_pipeline(Sharp_features<GeomTraits>& result,
                    const Sharp_feature_extraction::internal::Candidate_parameters& candidate_parameters,
                    const Sharp_feature_extraction::internal::Projection_parameters& projection_parameters,
                    const Sharp_feature_extraction::internal::Smoothing_parameters& smoothing_parameters,
                    const Sharp_feature_extraction::internal::Completion_parameters& completion_parameters,
                    const Sharp_feature_extraction::internal::Progress_callback& callback) const;
};

namespace Sharp_feature_extraction {
namespace internal {

/// Share of the progress range given to each stage (stage 1 and 2 dominate).
constexpr double progress_end_of_stage[5] = {0.35, 0.9, 0.97, 0.99, 1.0};

} // namespace internal
} // namespace Sharp_feature_extraction

template <typename GeomTraits, typename ConcurrencyTag>
bool Sharp_feature_extraction_context<GeomTraits, ConcurrencyTag>::run_pipeline(
  Sharp_features<GeomTraits>& result,
  const Sharp_feature_extraction::internal::Candidate_parameters& candidate_parameters,
  const Sharp_feature_extraction::internal::Projection_parameters& projection_parameters,
  const Sharp_feature_extraction::internal::Smoothing_parameters& smoothing_parameters,
  const Sharp_feature_extraction::internal::Completion_parameters& completion_parameters,
  const Sharp_feature_extraction::internal::Progress_callback& callback) const
{
  namespace sfe = Sharp_feature_extraction::internal;
  using sfe::progress_end_of_stage;
  result = Sharp_features<GeomTraits>();
  result.timings.context = m_construction_time;
  sfe::Progress progress(callback);
  CGAL::Real_timer timer;

  timer.start();
  sfe::Candidate_output candidates;
  if(!sfe::compute_candidates<ConcurrencyTag>(m_input, m_scales, candidate_parameters,
                                              progress.sub(0, progress_end_of_stage[0]), candidates))
    return false;
  result.candidates = sfe::to_input_order<GeomTraits>(m_input, candidates);
  result.timings.candidates = timer.time();

  timer.reset();
  sfe::Working_feature_points features;
  if(!sfe::rmls_project<ConcurrencyTag>(m_input, candidates.candidates, candidates.residuals, candidates.scales,
                                        projection_parameters,
                                        progress.sub(progress_end_of_stage[0], progress_end_of_stage[1]), features))
    return false;
  result.projected = sfe::convert_feature_points<GeomTraits>(features);
  result.timings.projection = timer.time();

  timer.reset();
  if(!sfe::smooth_edge_points<ConcurrencyTag>(features, smoothing_parameters,
                                              progress.sub(progress_end_of_stage[1], progress_end_of_stage[2])))
    return false;
  result.smoothed = sfe::convert_feature_points<GeomTraits>(features);
  result.timings.smoothing = timer.time();

  timer.reset();
  sfe::Progress growing = progress.sub(progress_end_of_stage[2], progress_end_of_stage[3]);
  sfe::Working_network network = sfe::grow_polylines(features, growing);
  if(growing.cancelled())
    return false;
  result.grown = sfe::convert_network<GeomTraits>(network);
  result.timings.growing = timer.time();

  timer.reset();
  sfe::complete_polylines(network, completion_parameters);
  result.network = sfe::convert_network<GeomTraits>(network);
  result.timings.completion = timer.time();
  return progress.report(1.);
}

} // namespace CGAL

#endif
