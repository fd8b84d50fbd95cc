// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_SYMMETRY_DESCRIPTOR_H
#define CGAL_SYMMETRY_TRANSFORM_SYMMETRY_DESCRIPTOR_H

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/geom_traits.h>
#include <CGAL/Symmetry_transform/internal/matching/descriptor_format.h>
#include <CGAL/Symmetry_transform/internal/matching/distances.h>
#include <CGAL/Symmetry_transform/internal/matching/settings.h>
#include <CGAL/Symmetry_transform/reflective_symmetry_transform.h>

#include <CGAL/number_type_config.h>

#include <cmath>
#include <fstream>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformMatchingRef
 *
 * The symmetry descriptor of a shape, for matching (thesis, chapter 4): its Planar Reflective
 * Symmetry Transform (PRST) and its Gaussian Euclidean Distance Transform (GEDT), both on
 * \f$ n \times n \times n \f$ bins, stored contiguously as `float` so that comparing two
 * descriptors reads little memory. Beside the PRST's symmetry measures it keeps the values that
 * `reflective_symmetry_descriptor_distance()` compares (a \f$ 32^3 \f$ descriptor: 384 KiB in
 * memory, 256 KiB saved).
 *
 * The descriptors are compared as computed, in the shapes' own coordinates (the PRST bins are
 * measured in the directions of the coordinate axes, the GEDT grid is an axis-aligned cube around
 * the centre of mass, scaled to the shape's radius): the shapes must be aligned first, for
 * instance each moved by `to_canonical(symmetry_frame(tm))` (see symmetry_alignment.h). Both
 * parts are invariant under translation and scaling.
 *
 * Descriptors are computed by `symmetry_descriptor()` or `symmetry_descriptor_of_points()`,
 * compared by `reflective_symmetry_descriptor_distance()`, `gedt_distance()` and `descriptor_distance()`,
 * and saved with `save()` so that a collection is indexed once.
 *
 * \tparam GeomTraits a model of `Kernel`
*/
template <typename GeomTraits>
class Symmetry_descriptor
{
public:
  /// Creates an empty descriptor (resolution 0), to be assigned.
  Symmetry_descriptor() = default;

  /// Creates the descriptor of a shape from its PRST and its GEDT.
  /// \param prst the Planar Reflective Symmetry Transform of `gedt`
  /// \param gedt the normalised GEDT of the shape (unit L² norm, as `gaussian_distance_transform()` returns)
  /// \throws std::invalid_argument if the resolutions of `prst` and `gedt` differ.
  Symmetry_descriptor(const Reflective_symmetry_transform<GeomTraits>& prst, const Voxel_grid<GeomTraits>& gedt)
    : n_(prst.resolution()),
      prst_(prst.values().begin(), prst.values().end()),
      gedt_(gedt.values().begin(), gedt.values().end())
  {
    if(gedt.resolution() != prst.resolution())
      throw std::invalid_argument("Symmetry_descriptor: the PRST and the GEDT must have the same resolution");
    prepare_comparison();
  }

  /// Number \f$ n \f$ of bins (samples) along each axis of the PRST and of the GEDT.
  /// \returns \f$ n \f$, 0 for an empty descriptor
  std::size_t resolution() const { return n_; }

  /// The PRST bin values, in the order of `Reflective_symmetry_transform::values()`.
  /// \returns the \f$ n^3 \f$ values, bin `(i,j,k)` at position \f$ (i n + j) n + k \f$
  const std::vector<float>& reflective_symmetry_values() const { return prst_; }

  /// The GEDT samples, in the order of `Voxel_grid::values()`.
  /// \returns the \f$ n^3 \f$ samples, of unit L² norm
  const std::vector<float>& gedt_values() const { return gedt_; }

  /// Writes the descriptor in a binary format with a versioned header and a checksum.
  /// Several descriptors may follow each other in a stream.
  /// \param os a stream opened in binary mode; its state tells whether the writing succeeded
  void save(std::ostream& os) const { internal::write_descriptor(os, n_, prst_, gedt_); }

  /// Writes the descriptor to the file `filename`, in the format of `save(std::ostream&) const`.
  /// \param filename the name of the file, created or overwritten
  /// \throws std::runtime_error if the file cannot be written.
  void save(const std::string& filename) const
  {
    internal::write_file(filename, "Symmetry_descriptor", [this](std::ostream& os) { save(os); });
  }

  /// Reads a descriptor written by `save()`.
  /// \param is a stream opened in binary mode, positioned at the start of a descriptor
  /// \returns the descriptor read
  /// \throws std::runtime_error if the stream does not hold such a descriptor, is truncated or corrupt.
  static Symmetry_descriptor load(std::istream& is)
  {
    Symmetry_descriptor result;
    result.n_ = internal::read_descriptor(is, result.prst_, result.gedt_);
    result.prepare_comparison();
    return result;
  }

  /// Reads a descriptor from the file `filename`.
  /// \param filename the name of a file written by `save()`
  /// \returns the descriptor read
  /// \throws std::runtime_error if the file cannot be opened or does not hold a descriptor written by `save()`.
  static Symmetry_descriptor load(const std::string& filename)
  {
    return internal::read_file(filename, "Symmetry_descriptor", [](std::istream& is) { return load(is); });
  }

  /// \cond SKIP_IN_MANUAL
  const std::vector<double>& row_weights() const { return weights_; }
  const std::vector<float>& compared_symmetry_values() const { return compared_; }
  /// \endcond

private:
  // The PRST bins as compared (internal/matching/distances.h), computed once rather than per
  // pair; sqrt(sin theta_i) at the centres of the theta bins: the weight of the n^2 bins of index i.
  void prepare_comparison()
  {
    compared_ = internal::compared_symmetry_values(prst_);
    weights_.resize(n_);
    for(std::size_t i = 0; i < n_; ++i)
      weights_[i] = std::sqrt(std::sin((double(i) + 0.5) * CGAL_PI / 2. / double(n_)));
  }

  std::size_t n_ = 0;
  std::vector<float> prst_;
  std::vector<float> gedt_;
  std::vector<float> compared_;
  std::vector<double> weights_;
};

/*!
 * \ingroup PkgSymmetryTransformMatchingRef
 *
 * The distance between the PRSTs of two descriptors (thesis, section 4.2): the L² difference of
 * the bins, each bin weighted by \f$ \sqrt{\sin\theta} \f$ (\f$ \theta \f$ at its centre,
 * the angle of the plane normals from the \f$ z \f$ axis) so that every direction of normals
 * counts as much as its area on the sphere of directions would make it count, on a square root.
 * A bin of symmetry measure \f$ SM \f$ is compared through its plane's normalised symmetry
 * distance \f$ D = \sqrt{(1 - SM)/2} \f$ (thesis, section 3.2.1) raised to the power 1/4:
 * \f[ d_{SM}(a, b) = \sqrt{\frac{\sum_{\text{bins}} \sqrt{\sin\theta}\,(D_a^{1/4} - D_b^{1/4})^2}{\sum_{\text{bins}} \sqrt{\sin\theta}}}. \f]
 * The power is steep near \f$ D = 0 \f$: a plane that is a perfect symmetry of one shape and
 * only a good one of the other weighs more than two middling values as far apart, which is what
 * the thesis expects of the comparison. On the Princeton Shape Benchmark it retrieves better than
 * the plain difference of the \f$ SM \f$ or of the thesis's values \f$ \sqrt{(1+SM)/2} \f$ (the power chosen on the training set, measured
 * on the test set: \ref SymmetryTransformMatching). Normalised by the sum of the weights, it is a
 * weighted root mean square: a number without unit, comparable across resolutions. Symmetric, zero
 * for equal descriptors, and it satisfies the triangle inequality.
 *
 * \param a,b two descriptors of the same resolution
 * \returns \f$ d_{SM}(a, b) \in [0, 1) \f$
 * \throws std::invalid_argument if the resolutions differ or the descriptors are empty.
*/
template <typename GeomTraits>
double reflective_symmetry_descriptor_distance(const Symmetry_descriptor<GeomTraits>& a, const Symmetry_descriptor<GeomTraits>& b)
{
  internal::check_same_resolution(a, b, "reflective_symmetry_descriptor_distance");
  return internal::weighted_rms_difference(a.compared_symmetry_values().data(), b.compared_symmetry_values().data(),
                                           a.resolution(), a.row_weights().data());
}

/*!
 * \ingroup PkgSymmetryTransformMatchingRef
 *
 * The distance between the GEDTs of two descriptors: the L² norm of the difference of the
 * samples, \f$ d_{G}(a, b) = \sqrt{\sum (f_a - f_b)^2} \f$. Each GEDT having unit L² norm and no
 * negative sample, \f$ d_G \in [0, \sqrt 2] \f$, without unit. Symmetric, zero for equal
 * descriptors, and it satisfies the triangle inequality.
 *
 * \param a,b two descriptors of the same resolution
 * \returns \f$ d_G(a, b) \f$
 * \throws std::invalid_argument if the resolutions differ or the descriptors are empty.
*/
template <typename GeomTraits>
double gedt_distance(const Symmetry_descriptor<GeomTraits>& a, const Symmetry_descriptor<GeomTraits>& b)
{
  internal::check_same_resolution(a, b, "gedt_distance");
  const std::size_t n = a.resolution();
  const std::vector<double> unit(n, 1.);
  // weighted_rms_difference with unit weights is the RMS: times sqrt(n^3) it is the L2 norm.
  return internal::weighted_rms_difference(a.gedt_values().data(), b.gedt_values().data(), n, unit.data()) *
         std::sqrt(double(n * n * n));
}

/*!
 * \ingroup PkgSymmetryTransformMatchingRef
 *
 * The combined distance of two descriptors (thesis, section 4.2): the product
 * `reflective_symmetry_descriptor_distance(a, b) * gedt_distance(a, b)`, small only when both the symmetries
 * and the shapes are close. Symmetric and zero for equal descriptors; it is not a metric (no
 * triangle inequality). Comparing two \f$ 32^3 \f$ descriptors takes a few microseconds
 * (benchmark_descriptor, RESULTS.md).
 *
 * \param a,b two descriptors of the same resolution
 * \returns \f$ d_{SM}(a, b)\, d_G(a, b) \f$
 * \throws std::invalid_argument if the resolutions differ or the descriptors are empty.
*/
template <typename GeomTraits>
double descriptor_distance(const Symmetry_descriptor<GeomTraits>& a, const Symmetry_descriptor<GeomTraits>& b)
{
  return reflective_symmetry_descriptor_distance(a, b) * gedt_distance(a, b);
}

/*!
 * \ingroup PkgSymmetryTransformMatchingRef
 *
 * Computes the symmetry descriptor of a triangle mesh: its GEDT by
 * `gaussian_distance_transform(tm, np)` and the PRST of that GEDT by
 * `reflective_symmetry_transform()`, both with `grid_resolution` bins along each axis. The mesh
 * should be aligned first (see `Symmetry_descriptor`).
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the input mesh
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamsGrid{32,at least 8 and more than 12 times the Gaussian width; even}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 *   \cgalParamPrstMethod
 *   \cgalParamMonteCarloSamples
 *   \cgalParamMonteCarloEstimator
 *   \cgalParamRandomSeed{the seed of the Monte Carlo samples: equal seeds and thread counts give identical results}
 *   \cgalParamVerbose{whether to print the time taken on `std::cerr`}
 * \cgalNamedParamsEnd
 *
 * \returns the descriptor of `tm`
 * \throws std::invalid_argument as `gaussian_distance_transform()` and `reflective_symmetry_transform()`.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Symmetry_descriptor<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>
symmetry_descriptor(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  const auto params = internal::descriptor_parameters(np);
  const auto gedt = gaussian_distance_transform(tm, params);
  return Symmetry_descriptor<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>(
    reflective_symmetry_transform(gedt, params), gedt);
}

/*!
 * \ingroup PkgSymmetryTransformMatchingRef
 *
 * Computes the symmetry descriptor of a point set, as `symmetry_descriptor()` does for a mesh:
 * its GEDT by `gaussian_distance_transform_of_points(points, np)` and the PRST of that GEDT.
 *
 * \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the input points
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamsGrid{32,at least 8 and more than 12 times the Gaussian width; even}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamPointMap
 *   \cgalParamGeomTraits
 *   \cgalParamPrstMethod
 *   \cgalParamMonteCarloSamples
 *   \cgalParamMonteCarloEstimator
 *   \cgalParamRandomSeed{the seed of the Monte Carlo samples: equal seeds and thread counts give identical results}
 *   \cgalParamVerbose{whether to print the time taken on `std::cerr`}
 * \cgalNamedParamsEnd
 *
 * \returns the descriptor of `points`
 * \throws std::invalid_argument as `gaussian_distance_transform_of_points()` and `reflective_symmetry_transform()`.
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Symmetry_descriptor<Geom_traits_of_points<PointRange, NamedParameters>>
symmetry_descriptor_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  const auto params = internal::descriptor_parameters(np);
  const auto gedt = gaussian_distance_transform_of_points(points, params);
  return Symmetry_descriptor<Geom_traits_of_points<PointRange, NamedParameters>>(
    reflective_symmetry_transform(gedt, params), gedt);
}

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_SYMMETRY_DESCRIPTOR_H
