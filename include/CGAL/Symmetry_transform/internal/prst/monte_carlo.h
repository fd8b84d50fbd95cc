// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_MONTE_CARLO_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_MONTE_CARLO_H

// Monte Carlo estimation of the bin averages of SM(plane) = int f(x) f(g(x)) dx / int f^2,
// with x drawn with probability proportional to f (alias table over the voxels, uniform
// jitter inside the voxel: the density of the piecewise-constant reconstruction of f).
// The work is cut into fixed chunks, each with its own random stream derived from the seed,
// so that results depend on the seed and the number of threads only.

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/common/parallel_for.h>
#include <CGAL/Symmetry_transform/internal/grid/filters.h>
#include <CGAL/Symmetry_transform/internal/prst/line_interpolation.h>
#include <CGAL/Symmetry_transform/internal/prst/plane_bins.h>

#include <boost/random/discrete_distribution.hpp>
#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_01.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

// The random stream of piece `piece` of the work (a chunk of samples, a direction) from the
// user's seed: Knuth's multiplicative hash of the seed plus a small odd multiple of the piece,
// so that the streams of neighbouring pieces and seeds differ.
inline std::uint32_t stream_seed(unsigned seed, std::size_t piece)
{
  return std::uint32_t(seed) * 2654435761u + std::uint32_t(piece) * 40503u + 1u;
}

// The voting estimators draw their samples in chunks of this many, each with its own stream:
// large enough to amortise the per-chunk vote array, small enough to share the work.
constexpr std::size_t monte_carlo_chunk = std::size_t(1) << 15;
// The chunks vote into this many arrays (a bin array each), whatever the thread count: more
// lanes than cores keep every core busy, each costs an array of the transform's size.
constexpr std::size_t monte_carlo_lanes = 8;

// The Monte Carlo estimators of the bins of a PRST (see Monte_carlo_estimator): each run_*()
// fills `values` (n^3 bins) from `samples` samples, the random streams derived from `seed`.
template <typename GT>
class Monte_carlo_reflective_symmetry
{
  typedef boost::random::mt19937 Rng;

public:
  Monte_carlo_reflective_symmetry(const Voxel_grid<GT>& f, const Plane_bins& bins)
    : f_(f), bins_(bins), h_(f.voxel_size())
  {
    std::vector<double> weights;
    for(std::size_t v = 0; v < f.values().size(); ++v)
      if(f.values()[v] > 0.) {
        voxels_.push_back(v);
        weights.push_back(f.values()[v]);
        sum_ += f.values()[v];
        sum_of_squares_ += f.values()[v] * f.values()[v];
      }
    voxel_distribution_ = boost::random::discrete_distribution<std::uint32_t, double>(weights.begin(), weights.end());
    support_ = support_radius(f);
  }

  // The thesis's estimator: pairs of points drawn proportionally to f.
  void run_pair_jacobian(std::size_t samples, unsigned seed, unsigned threads, std::vector<double>& values) const
  {
    // Normalisation: Z = sum f h^3 and ||f||^2 = sum f^2 h^3 (see DESIGN.md).
    const double scale = sum_ * sum_ * (h_ * h_ * h_) / (double(samples) * bins_.bin_volume() * sum_of_squares_);
    run_votes(samples, seed, threads, scale, values,
              [this](Rng& rng, std::size_t count, std::vector<double>& votes) { vote_pairs(rng, count, votes); });
  }

  // A point drawn proportionally to f and a plane drawn uniformly around it.
  void run_bounded_weight(std::size_t samples, unsigned seed, unsigned threads, std::vector<double>& values) const
  {
    const double scale = sum_ * 2. * support_ * CGAL_PI * CGAL_PI / (double(samples) * bins_.bin_volume() * sum_of_squares_);
    run_votes(samples, seed, threads, scale, values,
              [this](Rng& rng, std::size_t count, std::vector<double>& votes) { vote_bounded(rng, count, votes); });
  }

  // For each bin direction, points x drawn proportionally to f by systematic sampling of the
  // cumulative distribution (evenly spread, one random offset per direction), and f evaluated
  // at the reflections of x through the planes of all offsets r_k: the pairs (x, x') lie on a
  // line, so every offset of the direction is estimated from the same points. This estimates
  // sum_x f(x) f(g(x)) / sum_x f(x)^2 at the bin centres, as the exact method computes.
  void run_stratified_lines(std::size_t samples, unsigned seed, unsigned threads, std::vector<double>& values) const
  {
    const std::size_t n = bins_.n;
    poll_progress(); // the preparations take a tenth of a second each at 64^3
    const Strata strata = strata_of_voxels((std::max<std::size_t>)(1, samples / (n * n)));
    poll_progress();
    const Voxel_grid<GT> sharp = sharpened_for_trilinear_interpolation(f_);
    poll_progress();
    const Line_interpolation<GT> interpolate(sharp);
    parallel_for(n * n, threads, [&](unsigned, std::size_t begin, std::size_t end) {
      for(std::size_t direction = begin; direction < end && parallel_step(); ++direction)
        stratified_line(direction, strata, interpolate, seed, values.data() + direction * n);
    });
  }

private:
  // Sums the votes of `samples` samples, drawn by chunks, each with its own random stream, and
  // writes them times `scale` into `values`. vote(rng, count, votes) draws `count` samples. Chunk
  // c votes into the array of lane c % monte_carlo_lanes, the lanes in turn added in order: the
  // sums depend on the seed alone, never on the thread count.
  template <typename Vote>
  void run_votes(std::size_t samples, unsigned seed, unsigned threads, double scale, std::vector<double>& values,
                 const Vote& vote) const
  {
    const std::size_t chunks = (samples + monte_carlo_chunk - 1) / monte_carlo_chunk;
    const std::size_t lanes = (std::min)(monte_carlo_lanes, (std::max<std::size_t>)(chunks, 1));
    std::vector<std::vector<double>> votes(lanes);
    threads = unsigned((std::min<std::size_t>)(threads, lanes));
    parallel_for(chunks, threads, [&](unsigned thread, std::size_t, std::size_t) { // progress in chunks
      for(std::size_t lane = thread; lane < lanes; lane += threads) {
        votes[lane].assign(values.size(), 0.);
        for(std::size_t c = lane; c < chunks; c += lanes) {
          Rng rng(stream_seed(seed, c));
          vote(rng, (std::min)(monte_carlo_chunk, samples - c * monte_carlo_chunk), votes[lane]);
          if(!parallel_step(1)) return; // a chunk takes milliseconds
        }
      }
    });
    values.assign(values.size(), 0.);
    for(const std::vector<double>& v : votes)
      for(std::size_t b = 0; b < values.size(); ++b) values[b] += v[b];
    for(double& v : values) v *= scale;
  }

  std::array<double, 3> draw_point(Rng& rng) const
  {
    const std::size_t v = voxels_[voxel_distribution_(rng)], n = f_.resolution();
    const auto& o = f_.origin();
    boost::random::uniform_01<double> u;
    return {o[0] + (double(v % n) + u(rng)) * h_, o[1] + (double(v / n % n) + u(rng)) * h_,
            o[2] + (double(v / (n * n)) + u(rng)) * h_};
  }

  // Bin of the plane {y : normal.y = d}, or -1 when it is farther than R from the centre.
  long bin_of(const std::array<double, 3>& normal, double d) const
  {
    std::array<double, 3> u;
    if(!bins_.coordinates(normal, d, u)) return -1;
    const long m = long(bins_.n);
    const long i = (std::min)(m - 1, long(u[0] + 0.5)), j = long(u[1] + 0.5) % m, k = (std::min)(m - 1, long(u[2] + 0.5));
    return long(bins_.index(std::size_t(i), std::size_t(j), std::size_t(k)));
  }

  // The thesis's estimator: the pair (x, x') votes for its bisector plane with weight
  // 1/|J| = 1/(2 d^2 sin(theta)), d = |x - x'|.
  void vote_pairs(Rng& rng, std::size_t count, std::vector<double>& votes) const
  {
    for(std::size_t s = 0; s < count; ++s) {
      const std::array<double, 3> x = draw_point(rng), y = draw_point(rng);
      std::array<double, 3> normal = {y[0] - x[0], y[1] - x[1], y[2] - x[2]};
      const double d2 = normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2];
      if(d2 == 0.) continue;
      const double d = std::sqrt(d2);
      for(double& c : normal) c /= d;
      const double sin_theta = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1]);
      if(sin_theta == 0.) continue;
      const long b = bin_of(normal, 0.5 * (normal[0] * (x[0] + y[0]) + normal[1] * (x[1] + y[1]) +
                                           normal[2] * (x[2] + y[2])));
      if(b >= 0) votes[std::size_t(b)] += 1. / (2. * d2 * sin_theta);
    }
  }

  // The bounded-weight estimator of DESIGN.md: the plane is drawn uniformly in
  // (theta, phi, r - n.x) around x, and votes f(x') for the reflection x' of x.
  void vote_bounded(Rng& rng, std::size_t count, std::vector<double>& votes) const
  {
    boost::random::uniform_01<double> u;
    // |x' - x| <= 2 * support: the signed distance from x to x' spans a width W = 4 * support,
    // so the density of the plane is 2 / (pi^2 W) and the vote's weight pi^2 W / 2.
    const double width = 4. * support_;
    for(std::size_t s = 0; s < count; ++s) {
      const std::array<double, 3> x = draw_point(rng);
      const double t = u(rng) * CGAL_PI / 2., p = u(rng) * 2. * CGAL_PI;
      const double distance = (u(rng) - 0.5) * width;
      const std::array<double, 3> normal = {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
      const double image = f_.sample_or_zero(voxel(x[0] + distance * normal[0], 0),
                                             voxel(x[1] + distance * normal[1], 1),
                                             voxel(x[2] + distance * normal[2], 2));
      if(image == 0.) continue;
      const long b = bin_of(normal, normal[0] * x[0] + normal[1] * x[1] + normal[2] * x[2] + 0.5 * distance);
      if(b >= 0) votes[std::size_t(b)] += image;
    }
  }

  // The non-zero voxels in the order of a Hilbert curve and the cumulative sum of f along it;
  // each direction draws `per_direction` points from it.
  struct Strata
  {
    std::vector<std::size_t> voxels;
    std::vector<double> cumulative;
    std::size_t per_direction;
  };

  // In Hilbert-curve order, consecutive strata of the cumulative distribution are compact
  // regions of space: systematic sampling spreads the points evenly on the shape.
  Strata strata_of_voxels(std::size_t per_direction) const
  {
    Strata strata{{}, std::vector<double>(voxels_.size()), per_direction};
    const std::size_t res = f_.resolution();
    std::vector<std::pair<std::uint64_t, std::size_t>> keyed; // each voxel's index on the curve, computed once
    keyed.reserve(voxels_.size());
    for(std::size_t v : voxels_) keyed.emplace_back(hilbert_index(v % res, v / res % res, v / (res * res)), v);
    std::sort(keyed.begin(), keyed.end()); // the indices are distinct: the order of the curve
    strata.voxels.reserve(keyed.size());
    for(const auto& key : keyed) strata.voxels.push_back(key.second);
    double running = 0.;
    for(std::size_t v = 0; v < strata.voxels.size(); ++v) strata.cumulative[v] = running += f_.values()[strata.voxels[v]];
    return strata;
  }

  // The n values of the bins of direction `direction` into `line`.
  void stratified_line(std::size_t direction, const Strata& strata, const Line_interpolation<GT>& interpolate,
                       unsigned seed, double* line) const
  {
    const std::size_t n = bins_.n, res = f_.resolution();
    const double step = bins_.offset_step(), support2 = support_ * support_, running = strata.cumulative.back();
    const auto& o = f_.origin();
    Rng rng(stream_seed(seed, direction));
    const double offset = boost::random::uniform_01<double>()(rng);
    const std::array<double, 3> nrm = bins_.normal(direction / n, direction % n);
    std::fill_n(line, n, 0.);
    auto stratum = strata.cumulative.begin();
    for(std::size_t m = 0; m < strata.per_direction; ++m) {
      // Targets increase with m: each search starts where the previous one ended.
      const double target = (double(m) + offset) / double(strata.per_direction) * running;
      stratum = std::lower_bound(stratum, strata.cumulative.end() - 1, target);
      const std::size_t v = strata.voxels[std::size_t(stratum - strata.cumulative.begin())];
      const double x[3] = {o[0] + (double(v % res) + 0.5) * h_ - bins_.center[0],
                           o[1] + (double(v / res % res) + 0.5) * h_ - bins_.center[1],
                           o[2] + (double(v / (res * res)) + 0.5) * h_ - bins_.center[2]};
      // x' - c = q + (2 r_k - s) n, q the part of x - c orthogonal to n: only the offsets
      // with |x' - c| <= support can see f.
      const double s = nrm[0] * x[0] + nrm[1] * x[1] + nrm[2] * x[2];
      const double q2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - s * s;
      if(q2 > support2) continue;
      const double reach = std::sqrt(support2 - q2);
      const long first = (std::max)(0L, long(std::ceil(((s - reach) / 2. + bins_.radius) / step - 0.5)));
      const long last = (std::min)(long(n) - 1, long(std::floor(((s + reach) / 2. + bins_.radius) / step - 0.5)));
      if(first > last) continue;
      const double t = 2. * (bins_.offset(std::size_t(first)) - s);
      interpolate.add_along_line({bins_.center[0] + x[0] + t * nrm[0], bins_.center[1] + x[1] + t * nrm[1],
                                  bins_.center[2] + x[2] + t * nrm[2]},
                                 {2. * step * nrm[0], 2. * step * nrm[1], 2. * step * nrm[2]}, last - first + 1,
                                 line + first);
    }
    const double scale = sum_ / (double(strata.per_direction) * sum_of_squares_);
    for(std::size_t k = 0; k < n; ++k) line[k] *= scale;
  }

  // Position of voxel (i,j,k) along a Hilbert curve through the grid (J. Skilling,
  // "Programming the Hilbert curve", 2004): consecutive voxels along it are neighbours.
  // Kept instead of CGAL::hilbert_sort: no policy or axis order of CGAL's sort gives this order,
  // so it would change every Monte Carlo result, for no gain in error or time.
  static std::uint64_t hilbert_index(std::size_t i, std::size_t j, std::size_t k)
  {
    constexpr int bits = 12;
    std::uint32_t x[3] = {std::uint32_t(i), std::uint32_t(j), std::uint32_t(k)};
    for(std::uint32_t q = 1u << (bits - 1); q > 1; q >>= 1) { // inverse undo of excess work
      const std::uint32_t p = q - 1;
      for(int a = 0; a < 3; ++a) {
        if(x[a] & q)
          x[0] ^= p;
        else {
          const std::uint32_t t = (x[0] ^ x[a]) & p;
          x[0] ^= t;
          x[a] ^= t;
        }
      }
    }
    for(int a = 1; a < 3; ++a) x[a] ^= x[a - 1]; // Gray encode
    std::uint32_t t = 0;
    for(std::uint32_t q = 1u << (bits - 1); q > 1; q >>= 1)
      if(x[2] & q) t ^= q - 1;
    for(int a = 0; a < 3; ++a) x[a] ^= t;
    std::uint64_t code = 0; // interleave the transposed bits, most significant first
    for(int bit = bits - 1; bit >= 0; --bit)
      for(int a = 0; a < 3; ++a) code = (code << 1) | ((x[a] >> bit) & 1u);
    return code;
  }

  long voxel(double coordinate, int axis) const { return long(std::floor((coordinate - f_.origin()[axis]) / h_)); }

  const Voxel_grid<GT>& f_;
  Plane_bins bins_;
  double h_;
  std::vector<std::size_t> voxels_;
  boost::random::discrete_distribution<std::uint32_t, double> voxel_distribution_;
  double sum_ = 0., sum_of_squares_ = 0., support_ = 0.;
};

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_PRST_MONTE_CARLO_H
