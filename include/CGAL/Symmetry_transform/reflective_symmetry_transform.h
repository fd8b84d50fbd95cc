// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_REFLECTIVE_SYMMETRY_TRANSFORM_H
#define CGAL_SYMMETRY_TRANSFORM_REFLECTIVE_SYMMETRY_TRANSFORM_H

#include <CGAL/Symmetry_transform/internal/common/defaults.h>
#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/gaussian_distance_transform.h>
#include <CGAL/Symmetry_transform/geom_traits.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>
#include <CGAL/Symmetry_transform/internal/common/named_parameters.h>
#include <CGAL/Symmetry_transform/internal/common/parameter_checks.h>
#include <CGAL/Symmetry_transform/internal/common/progress.h>
#include <CGAL/Symmetry_transform/internal/common/progress_shares.h>
#include <CGAL/Symmetry_transform/internal/prst/plane_bins.h>
#include <CGAL/Symmetry_transform/internal/prst/exact.h>
#include <CGAL/Symmetry_transform/internal/prst/file_format.h>
#include <CGAL/Symmetry_transform/internal/prst/monte_carlo.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL::Symmetry_transform {

/*!
 * \ingroup PkgSymmetryTransformPRSTRef
 * How `reflective_symmetry_transform()` computes the symmetry measures of the bins.
*/
enum class Reflective_symmetry_method {
  /// Monte Carlo sampling of points drawn proportionally to \f$ f \f$, with the estimator given by
  /// the named parameter `monte_carlo_estimator`: \f$ O(N) \f$ for \f$ N \f$ samples
  /// (\f$ O(N n) \f$ for `Monte_carlo_estimator::STRATIFIED_LINES`).
  MONTE_CARLO,
  /// One self-convolution per normal direction by FFT, \f$ O(n^5 \log n) \f$: the reference.
  EXACT
};

/*!
 * \ingroup PkgSymmetryTransformPRSTRef
 * The Monte Carlo estimator used by `Reflective_symmetry_method::MONTE_CARLO`.
*/
enum class Monte_carlo_estimator {
  /// The thesis's: both points drawn proportionally to \f$ f \f$, each pair votes
  /// \f$ 1/(2 d^2 \sin\theta) \f$ for its bisector plane (\f$ d \f$ the distance between the points).
  PAIR_JACOBIAN,
  /// One point drawn proportionally to \f$ f \f$ and the plane uniformly in
  /// \f$ (\theta, \phi, r) \f$ around it; the vote is \f$ f \f$ at the reflected point, a bounded weight.
  BOUNDED_WEIGHT,
  /// For each bin direction, points drawn proportionally to \f$ f \f$ by systematic sampling,
  /// each paired with its reflections through the planes of all offsets of the direction:
  /// an estimate of the values at the bin centres whose noise is spread evenly over the bins.
  /// `number_of_samples` then counts the points drawn over all directions.
  STRATIFIED_LINES
};

/*!
 * \ingroup PkgSymmetryTransformPRSTRef
 *
 * The Planar Reflective Symmetry Transform (PRST) of a function \f$ f \f$ (usually the GEDT of a
 * shape): the symmetry measure
 * \f$ SM(\gamma) = \int f(x) f(\gamma(x))\,dx / \int f^2 \in [0,1] \f$ of every plane
 * \f$ \gamma \f$, tabulated on \f$ n \times n \times n \f$ bins.
 *
 * A plane is \f$ \{x : \mathbf{n}\cdot(x - c) = r\} \f$, with \f$ c \f$ the centre of mass of the
 * shape and the unit normal
 * \f$ \mathbf{n}(\theta,\phi) = (\sin\theta\cos\phi, \sin\theta\sin\phi, \cos\theta) \f$,
 * \f$ \theta \in [0,\pi/2] \f$, \f$ \phi \in [0, 2\pi) \f$, \f$ r \in [-R, R] \f$ (\f$ R \f$ the
 * radius of the shape). Bin `(i,j,k)` covers
 * \f$ [i, i+1)\,\Delta\theta \times [j, j+1)\,\Delta\phi \times (-R + [k, k+1)\,\Delta r) \f$
 * with \f$ \Delta\theta = \pi/2n \f$, \f$ \Delta\phi = 2\pi/n \f$, \f$ \Delta r = 2R/n \f$.
 * In this parameter space \f$ \phi \f$ wraps around, and a plane on the equator is also
 * \f$ (\pi/2, \phi + \pi, -r) \f$.
 *
 * \tparam GeomTraits a model of `Kernel`
*/
template <typename GeomTraits>
class Reflective_symmetry_transform
{
public:
  /// Point type of the traits.
  typedef typename GeomTraits::Point_3 Point_3;
  /// Plane type of the traits.
  typedef typename GeomTraits::Plane_3 Plane_3;
  /// Bin coordinates `(i,j,k)`: indices of \f$ \theta \f$, \f$ \phi \f$ and \f$ r \f$.
  typedef std::array<std::size_t, 3> Bin;

  /// Creates a transform with `resolution`³ bins, all zero, for a shape of centre `center` and radius `radius`.
  /// \param resolution the number \f$ n \f$ of bins along each of \f$ \theta \f$, \f$ \phi \f$ and \f$ r \f$
  /// \param center the centre \f$ c \f$ from which the offsets of the planes are measured
  /// \param radius the radius \f$ R \f$ of the shape
  /// \throws std::invalid_argument unless `resolution` is even and positive and `radius > 0`.
  Reflective_symmetry_transform(std::size_t resolution, const Point_3& center, double radius)
    : center_(center),
      bins_{resolution, {CGAL::to_double(center.x()), CGAL::to_double(center.y()), CGAL::to_double(center.z())}, radius},
      values_(resolution * resolution * resolution, 0.)
  {
    if(resolution == 0 || resolution % 2 != 0)
      throw std::invalid_argument("Reflective_symmetry_transform: the resolution must be even and positive "
                                  "(the bins of phi + pi must exist)");
    if(!(radius > 0.)) throw std::invalid_argument("Reflective_symmetry_transform: the radius must be positive");
  }

  /// Number \f$ n \f$ of bins along each of \f$ \theta \f$, \f$ \phi \f$ and \f$ r \f$.
  /// \returns \f$ n \f$
  std::size_t resolution() const { return bins_.n; }
  /// Centre \f$ c \f$ of the shape, from which plane offsets are measured.
  /// \returns \f$ c \f$
  const Point_3& center() const { return center_; }
  /// Radius \f$ R \f$ of the shape: offsets lie in \f$ [-R, R] \f$.
  /// \returns \f$ R \f$
  double radius() const { return bins_.radius; }

  /// \f$ \theta \f$ at the centre of the bins of index `i`.
  /// \param i a bin index along \f$ \theta \f$, in \f$ [0, n) \f$
  /// \returns \f$ (i + 1/2)\,\Delta\theta \f$, in radians
  double theta(std::size_t i) const { return bins_.theta(i); }
  /// \f$ \phi \f$ at the centre of the bins of index `j`.
  /// \param j a bin index along \f$ \phi \f$, in \f$ [0, n) \f$
  /// \returns \f$ (j + 1/2)\,\Delta\phi \f$, in radians
  double phi(std::size_t j) const { return bins_.phi(j); }
  /// \f$ r \f$ at the centre of the bins of index `k`.
  /// \param k a bin index along \f$ r \f$, in \f$ [0, n) \f$
  /// \returns \f$ -R + (k + 1/2)\,\Delta r \f$
  double offset(std::size_t k) const { return bins_.offset(k); }

  /// Symmetry measure of bin `(i,j,k)`.
  /// \param i,j,k the bin indices along \f$ \theta \f$, \f$ \phi \f$ and \f$ r \f$, each in \f$ [0, n) \f$ (not checked)
  /// \returns the value of the bin
  double value(std::size_t i, std::size_t j, std::size_t k) const { return values_[bins_.index(i, j, k)]; }
  /// Symmetry measure of bin `b`.
  /// \param b the bin
  /// \returns the value of the bin
  double value(const Bin& b) const { return value(b[0], b[1], b[2]); }

  /// The plane at the centre of bin `(i,j,k)`, with a unit normal.
  /// \param i,j,k the bin indices along \f$ \theta \f$, \f$ \phi \f$ and \f$ r \f$
  /// \returns the plane \f$ \mathbf{n}(\theta_i,\phi_j)\cdot(x - c) = r_k \f$, oriented by \f$ \mathbf{n} \f$
  Plane_3 plane(std::size_t i, std::size_t j, std::size_t k) const
  {
    const std::array<double, 3> nrm = bins_.normal(i, j);
    const double d = nrm[0] * bins_.center[0] + nrm[1] * bins_.center[1] + nrm[2] * bins_.center[2] + offset(k);
    return Plane_3(nrm[0], nrm[1], nrm[2], -d);
  }
  /// The plane at the centre of bin `b`.
  /// \param b the bin
  /// \returns the plane at the centre of `b`, with a unit normal
  Plane_3 plane(const Bin& b) const { return plane(b[0], b[1], b[2]); }

  /// The bin containing `plane`, whose offset must lie in \f$ [-R, R] \f$.
  /// \param plane any plane; its orientation does not matter
  /// \returns the bin whose cell contains the parameters \f$ (\theta, \phi, r) \f$ of `plane`
  /// \throws std::invalid_argument if the plane is degenerate or farther than \f$ R \f$ from the centre.
  Bin bin(const Plane_3& plane) const
  {
    const std::array<double, 3> u = coordinates(plane);
    const long m = long(bins_.n);
    return {std::size_t((std::min)(m - 1, long(u[0] + 0.5))), std::size_t(long(u[1] + 0.5) % m),
            std::size_t((std::min)(m - 1, long(u[2] + 0.5)))};
  }

  /// Symmetry measure of any `plane` within \f$ R \f$ of the centre, interpolated trilinearly
  /// between bin centres, across the wraps of \f$ \phi \f$, the pole and the equator.
  /// \param plane any plane; its orientation does not matter
  /// \returns the interpolated symmetry measure
  /// \throws std::invalid_argument if the plane is degenerate or farther than \f$ R \f$ from the centre.
  double value(const Plane_3& plane) const
  {
    const std::array<double, 3> u = coordinates(plane);
    const long i = long(std::floor(u[0])), j = long(std::floor(u[1])), k = long(std::floor(u[2]));
    const double a = u[0] - double(i), b = u[1] - double(j), c = u[2] - double(k);
    double result = 0.;
    for(int di = 0; di < 2; ++di)
      for(int dj = 0; dj < 2; ++dj)
        for(int dk = 0; dk < 2; ++dk)
          result += (di ? a : 1. - a) * (dj ? b : 1. - b) * (dk ? c : 1. - c) *
                    values_[bins_.wrapped_index(i + di, j + dj, k + dk)];
    return result;
  }

  /// The bin of largest symmetry measure.
  /// \returns the first bin, in the order of `values()`, whose value is the largest
  Bin maximum() const
  {
    const std::size_t best = std::size_t(std::max_element(values_.begin(), values_.end()) - values_.begin());
    const std::size_t n = bins_.n;
    return {best / (n * n), best / n % n, best % n};
  }

  /*!
 *   Writes to `out` every bin of positive value that exceeds those of its 26 neighbours
 *   (through the wraps of \f$ \phi \f$, the pole and the equator; along \f$ r \f$ the bins at
 *   \f$ \pm R \f$ have fewer neighbours), strongest first, and returns the past-the-end iterator.
 *   \tparam OutputIterator an output iterator accepting `Bin`
 *   \param out where the bins are written
 *   \returns `out` past the last bin written
  */
  template <typename OutputIterator>
  OutputIterator local_maxima(OutputIterator out) const
  {
    const long n = long(bins_.n);
    std::vector<Bin> maxima;
    for(long i = 0; i < n; ++i)
      for(long j = 0; j < n; ++j)
        for(long k = 0; k < n; ++k) {
          const double v = values_[bins_.index(std::size_t(i), std::size_t(j), std::size_t(k))];
          bool is_maximum = true;
          for(long di = -1; di <= 1 && is_maximum; ++di)
            for(long dj = -1; dj <= 1 && is_maximum; ++dj)
              for(long dk = -1; dk <= 1 && is_maximum; ++dk) {
                if((di == 0 && dj == 0 && dk == 0) || k + dk < 0 || k + dk >= n) continue;
                const std::size_t neighbour = bins_.wrapped_index(i + di, j + dj, k + dk);
                is_maximum = neighbour == bins_.index(std::size_t(i), std::size_t(j), std::size_t(k)) ||
                             values_[neighbour] < v;
              }
          if(is_maximum && v > 0.) maxima.push_back({std::size_t(i), std::size_t(j), std::size_t(k)});
        }
    std::sort(maxima.begin(), maxima.end(), [&](const Bin& a, const Bin& b) { return value(a) > value(b); });
    return std::copy(maxima.begin(), maxima.end(), out);
  }

  /// All bin values, `k` fastest, then `j`, then `i`, for writing.
  /// \returns the \f$ n^3 \f$ values, bin `(i,j,k)` at position \f$ (i n + j) n + k \f$
  std::vector<double>& values() { return values_; }
  /// All bin values, `k` fastest, then `j`, then `i`.
  /// \returns the \f$ n^3 \f$ values, bin `(i,j,k)` at position \f$ (i n + j) n + k \f$
  const std::vector<double>& values() const { return values_; }

  /// Writes the transform in a binary format with a versioned header and a checksum.
  /// \param os a stream opened in binary mode; its state tells whether the writing succeeded
  void save(std::ostream& os) const
  {
    internal::write_reflective_symmetry(os, bins_, values_);
  }
  /// Writes the transform to the file `filename`, in the format of `save(std::ostream&) const`.
  /// \param filename the name of the file, created or overwritten
  /// \throws std::runtime_error if the file cannot be written.
  void save(const std::string& filename) const
  {
    internal::write_file(filename, "Reflective_symmetry_transform", [this](std::ostream& os) { save(os); });
  }

  /// Reads a transform written by `save()`.
  /// \param is a stream opened in binary mode
  /// \returns the transform read
  /// \throws std::runtime_error if the stream does not hold such a transform, is truncated or corrupt.
  static Reflective_symmetry_transform load(std::istream& is)
  {
    internal::Plane_bins bins{0, {0., 0., 0.}, 0.};
    std::vector<double> values;
    internal::read_reflective_symmetry(is, bins, values);
    Reflective_symmetry_transform result(bins.n, Point_3(bins.center[0], bins.center[1], bins.center[2]), bins.radius);
    result.values_ = std::move(values);
    return result;
  }
  /// Reads a transform from the file `filename`.
  /// \param filename the name of a file written by `save()`
  /// \returns the transform read
  /// \throws std::runtime_error if the file cannot be opened or does not hold a transform written by `save()`.
  static Reflective_symmetry_transform load(const std::string& filename)
  {
    return internal::read_file(filename, "Reflective_symmetry_transform", [](std::istream& is) { return load(is); });
  }

  /// \cond SKIP_IN_MANUAL
  const internal::Plane_bins& bins() const { return bins_; }
  // The same values, for the planes of offsets measured from `center`.
  void recenter(const Point_3& center)
  {
    center_ = center;
    bins_.center = {CGAL::to_double(center.x()), CGAL::to_double(center.y()), CGAL::to_double(center.z())};
  }
  /// \endcond

private:
  std::array<double, 3> coordinates(const Plane_3& plane) const
  {
    const internal::Dplane p = internal::to_dplane(plane);
    std::array<double, 3> u;
    if(!bins_.coordinates({p.normal[0], p.normal[1], p.normal[2]}, p.offset, u))
      throw std::invalid_argument("Reflective_symmetry_transform: the plane is farther than the radius from the centre");
    return u;
  }

  Point_3 center_;
  internal::Plane_bins bins_;
  std::vector<double> values_;
};

namespace internal {

// The values of `result`, the transform of `f`, by `method`.
template <typename GeomTraits>
void fill_reflective_symmetry(const Voxel_grid<GeomTraits>& f, Reflective_symmetry_method method,
                              Monte_carlo_estimator estimator, std::size_t samples, unsigned seed, unsigned threads,
                              Reflective_symmetry_transform<GeomTraits>& result)
{
  if(method == Reflective_symmetry_method::EXACT) {
    exact_reflective_symmetry(f, result.bins(), threads, result.values());
    return;
  }
  const Monte_carlo_reflective_symmetry<GeomTraits> monte_carlo(f, result.bins());
  switch(estimator) {
  case Monte_carlo_estimator::PAIR_JACOBIAN:
    monte_carlo.run_pair_jacobian(samples, seed, threads, result.values());
    break;
  case Monte_carlo_estimator::BOUNDED_WEIGHT:
    monte_carlo.run_bounded_weight(samples, seed, threads, result.values());
    break;
  case Monte_carlo_estimator::STRATIFIED_LINES:
    monte_carlo.run_stratified_lines(samples, seed, threads, result.values());
    break;
  }
}

// The transform of the GEDT that make_gedt() returns, under the callback of `np`: the GEDT is
// the first part of the work. A cancel there leaves a GEDT zero everywhere, whose transform is zero.
template <typename MakeGedt, typename NamedParameters>
auto reflective_symmetry_transform_of_gedt(const MakeGedt& make_gedt, const NamedParameters& np)
{
  return with_progress_scope(np, [&] {
    Progress_stage stage(0., progress_shares::transform_gedt);
    const auto f = make_gedt();
    stage.move_to(progress_shares::transform_gedt, 1.);
    return reflective_symmetry_transform(f, np);
  });
}

} // namespace internal

/*!
 * \ingroup PkgSymmetryTransformPRSTRef
 *
 * Computes the Planar Reflective Symmetry Transform of a function sampled on a grid, usually
 * the GEDT of a shape from `gaussian_distance_transform()`, with as many bins along
 * \f$ \theta \f$, \f$ \phi \f$ and \f$ r \f$ as the grid has samples along an axis.
 *
 * \tparam GeomTraits a model of `Kernel`
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param f the function; its `center()` and `radius()` define the offsets of the planes
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \returns the transform, with `f.resolution()` bins along each axis, `center()` and `radius()` those of `f`
 *
 * \cgalNamedParamsBegin
 *   \cgalParamPrstMethod
 *   \cgalParamMonteCarloSamples
 *   \cgalParamMonteCarloEstimator
 *   \cgalParamRandomSeed{the seed of the Monte Carlo samples: equal seeds and thread counts give identical results}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamVerbose{whether to print the time taken on `std::cerr`}
 *   \cgalParamCallback{a transform of the same bins whose values are all zero}
 * \cgalNamedParamsEnd
 *
 * \throws std::invalid_argument if the resolution of `f` is odd, `f` is zero everywhere, its radius is
 * zero, `number_of_samples` is 0 with the Monte Carlo method, or a numeric named parameter lies out of its range (the message names it and the range).
*/
template <typename GeomTraits, typename NamedParameters = parameters::Default_named_parameters>
Reflective_symmetry_transform<GeomTraits>
reflective_symmetry_transform(const Voxel_grid<GeomTraits>& f, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const Reflective_symmetry_method method =
    choose_parameter(get_parameter(np, internal_np::st_prst_method), Reflective_symmetry_method::MONTE_CARLO);
  internal::check_named_parameters(np);
  const std::size_t samples = internal::read_count(np, internal_np::number_of_samples, internal::defaults::monte_carlo_pairs,
                                                   internal::parameter_ranges::number_of_samples_or_zero);
  const Monte_carlo_estimator estimator =
    choose_parameter(get_parameter(np, internal_np::st_monte_carlo_estimator), Monte_carlo_estimator::STRATIFIED_LINES);
  const unsigned seed = internal::read_random_seed(np, internal::defaults::random_seed);
  const unsigned threads = internal::read_number_of_threads(np);
  const bool verbose = choose_parameter(get_parameter(np, internal_np::verbose), false);

  if(f.resolution() % 2 != 0)
    throw std::invalid_argument("reflective_symmetry_transform: grid_resolution must be even "
                                "(a plane on the equator is also the plane of phi + pi)");
  if(internal::stop_requested()) // cancelled in the GEDT of a shape: zero, as `f`
    return Reflective_symmetry_transform<GeomTraits>(f.resolution(), f.center(), f.radius());
  if(std::none_of(f.values().begin(), f.values().end(), [](double v) { return v != 0.; }))
    throw std::invalid_argument("reflective_symmetry_transform: the grid is zero everywhere");

  const auto start = std::chrono::steady_clock::now();
  Reflective_symmetry_transform<GeomTraits> result(f.resolution(), f.center(), f.radius());
  if(method != Reflective_symmetry_method::EXACT && samples == 0)
    throw std::invalid_argument("reflective_symmetry_transform: number_of_samples must be an integer in [1, " +
                                std::to_string(internal::parameter_ranges::number_of_samples.most) +
                                "] with the Monte Carlo method, not 0");
  internal::with_progress(np, [&] {
    internal::fill_reflective_symmetry(f, method, estimator, samples, seed, (std::max)(1u, threads), result);
    return true;
  }, [&] {
    std::fill(result.values().begin(), result.values().end(), 0.);
    return false;
  });
  if(verbose)
    std::cerr << "reflective_symmetry_transform: " << f.resolution() << "^3 bins, "
              << (method == Reflective_symmetry_method::EXACT ? "exact" : "Monte Carlo") << ", "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
  return result;
}

/*!
 * \ingroup PkgSymmetryTransformPRSTRef
 *
 * Computes the Planar Reflective Symmetry Transform of a triangle mesh: its GEDT by
 * `gaussian_distance_transform(tm, np)`, then `reflective_symmetry_transform()` of that grid.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the input mesh
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width; even}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamVertexPointMap{tm,TriangleMesh}
 *   \cgalParamGeomTraits
 *   \cgalParamPrstMethod
 *   \cgalParamMonteCarloSamples
 *   \cgalParamMonteCarloEstimator
 *   \cgalParamRandomSeed{the seed of the Monte Carlo samples: equal seeds and thread counts give identical results}
 *   \cgalParamVerbose{whether to print the time taken on `std::cerr`}
 *   \cgalParamCallback{a transform of the same bins whose values are all zero}
 * \cgalNamedParamsEnd
 *
 * \returns the Planar Reflective Symmetry Transform of the GEDT of `tm`, with `grid_resolution`
 * bins along each axis, centred on the centre of mass of `tm`
 *
 * \throws std::invalid_argument as `gaussian_distance_transform()` and the overload on grids.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Reflective_symmetry_transform<Geom_traits_of_mesh<TriangleMesh, NamedParameters>>
reflective_symmetry_transform(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  return internal::reflective_symmetry_transform_of_gedt([&] { return gaussian_distance_transform(tm, np); }, np);
}

/*!
 * \ingroup PkgSymmetryTransformPRSTRef
 *
 * Computes the Planar Reflective Symmetry Transform of a point set: its GEDT by
 * `gaussian_distance_transform_of_points(points, np)`, then `reflective_symmetry_transform()` of that grid.
 *
 * \tparam PointRange a model of `ConstRange` whose value type is the key type of the point map
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the input points
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width; even}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamPointMap
 *   \cgalParamNormalMap{not read: the GEDT is the distance to the points, whatever their normals}
 *   \cgalParamGeomTraits
 *   \cgalParamPrstMethod
 *   \cgalParamMonteCarloSamples
 *   \cgalParamMonteCarloEstimator
 *   \cgalParamRandomSeed{the seed of the Monte Carlo samples: equal seeds and thread counts give identical results}
 *   \cgalParamVerbose{whether to print the time taken on `std::cerr`}
 *   \cgalParamCallback{a transform of the same bins whose values are all zero}
 * \cgalNamedParamsEnd
 *
 * \returns the Planar Reflective Symmetry Transform of the GEDT of `points`, centred on their mean
 *
 * \throws std::invalid_argument as `gaussian_distance_transform_of_points()` and the overload on grids.
*/
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Reflective_symmetry_transform<Geom_traits_of_points<PointRange, NamedParameters>>
reflective_symmetry_transform_of_points(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  return internal::reflective_symmetry_transform_of_gedt([&] { return gaussian_distance_transform_of_points(points, np); }, np);
}

/*!
 * \ingroup PkgSymmetryTransformPRSTRef
 *
 * Computes the Planar Reflective Symmetry Transform of a triangle soup: its GEDT by
 * `gaussian_distance_transform_of_triangle_soup(points, triangles, np)`, then `reflective_symmetry_transform()` of that grid.
 *
 * \tparam PointRange a model of `RandomAccessRange` whose value type is the key type of the point map
 * \tparam TriangleRange a model of `Range` whose value type is a range of three indices into `points`
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param points the points of the soup
 * \param triangles the triangles, as indices into `points`
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamsGrid{64,at least 8 and more than 12 times the Gaussian width; even}
 *   \cgalParamThreads{the number of threads\, at most 1024 (0: the default); it changes the speed only\, never the result}
 *   \cgalParamPointMap
 *   \cgalParamGeomTraits
 *   \cgalParamPrstMethod
 *   \cgalParamMonteCarloSamples
 *   \cgalParamMonteCarloEstimator
 *   \cgalParamRandomSeed{the seed of the Monte Carlo samples: equal seeds and thread counts give identical results}
 *   \cgalParamVerbose{whether to print the time taken on `std::cerr`}
 *   \cgalParamCallback{a transform of the same bins whose values are all zero}
 * \cgalNamedParamsEnd
 *
 * \returns the Planar Reflective Symmetry Transform of the GEDT of the soup
 *
 * \throws std::invalid_argument as `gaussian_distance_transform_of_triangle_soup()` and the overload on grids.
*/
template <typename PointRange, typename TriangleRange, typename NamedParameters = parameters::Default_named_parameters>
Reflective_symmetry_transform<Geom_traits_of_points<PointRange, NamedParameters>>
reflective_symmetry_transform_of_triangle_soup(const PointRange& points, const TriangleRange& triangles,
                                               const NamedParameters& np = parameters::default_values())
{
  return internal::reflective_symmetry_transform_of_gedt(
    [&] { return gaussian_distance_transform_of_triangle_soup(points, triangles, np); }, np);
}

} // namespace CGAL::Symmetry_transform

#endif // CGAL_SYMMETRY_TRANSFORM_REFLECTIVE_SYMMETRY_TRANSFORM_H
