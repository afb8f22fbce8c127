/*!
\ingroup PkgSharpFeatureExtractionRef
\cgalConcept

The geometric traits of the package: the types in which the results are given (points, vectors
and numbers), and in which the input points are read through the point map.

The stages compute in double precision whatever the traits: the input coordinates are read
with `CGAL::to_double()`, and the results are constructed from doubles. Exact kernels are
accepted (their results hold the computed doubles exactly); they do not make the computation
exact.

\cgalHasModel All CGAL kernels with a 3D point type: `CGAL::Simple_cartesian<double>`,
`CGAL::Exact_predicates_inexact_constructions_kernel`,
`CGAL::Exact_predicates_exact_constructions_kernel`, ...
*/
class SharpFeatureExtractionTraits
{
public:
  /// \name Types
  /// @{

  /// The number type: constructible from `double`, and `CGAL::to_double()` applies to it.
  typedef unspecified_type FT;

  /// The point type: constructible from three `double`s, with `x()`, `y()` and `z()`
  /// returning a type that `CGAL::to_double()` applies to.
  typedef unspecified_type Point_3;

  /// The vector type of the normals: constructible from three `double`s, with `x()`, `y()`
  /// and `z()` as `Point_3`.
  typedef unspecified_type Vector_3;

  /// @}
};
