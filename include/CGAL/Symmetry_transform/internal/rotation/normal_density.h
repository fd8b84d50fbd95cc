// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_NORMAL_DENSITY_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_NORMAL_DENSITY_H

// The density of the normals of a surface on the unit sphere (its extended Gaussian image),
// smoothed, and its correlation with its own rotations. A rotational symmetry of the shape about
// any axis of direction a is a symmetry of this density about the line through the origin along
// a, wherever the shape's axis lies: the search of directions needs no axis point, and works
// when the centre of mass is off the axis (a part of the shape missing).

#include <CGAL/Symmetry_transform/Voxel_grid.h>
#include <CGAL/Symmetry_transform/internal/common/geometry.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL::Symmetry_transform::internal {

class Normal_density
{
  // The density lives on a grid of this resolution over [-1.3, 1.3]^3: voxels of 0.13, about
  // 7.5 degrees on the sphere.
  static constexpr std::size_t resolution = 20;
  static constexpr double half_side = 1.3;
  // Gaussian width of each normal's contribution (about 6 degrees on the sphere) and its reach
  // in voxels (2.4 widths): with the voxels' own smoothing, the density resolves the 30 degrees
  // between the teeth of a 12-fold object and is smooth at the 6 degrees between the directions
  // searched.
  static constexpr double width = 0.11;
  static constexpr long reach = 2;

public:
  // `normals`: unit normals of area-uniform surface samples (or of the points); their signs
  // do not matter (n and -n are both counted: meshes need not be oriented, nor point normals).
  // `probes`: those at which the correlation is evaluated.
  Normal_density(const std::vector<Eigen::Vector3d>& normals, std::vector<Eigen::Vector3d> probes)
    : grid_(resolution, Dpoint(0., 0., 0.), 1., 2. * half_side), probes_(std::move(probes))
  {
    for(const Eigen::Vector3d& n : normals) {
      add(n);
      add(-n);
    }
    for(const Eigen::Vector3d& n : probes_) self_ += value(n);
  }

  // The mean density at the rotated probes over that at the probes: 1 if the rotation maps the
  // density onto itself, lower otherwise.
  double correlation(const Eigen::Matrix3d& rotation) const
  {
    if(!(self_ > 0.)) return 0.;
    double sum = 0.;
    for(const Eigen::Vector3d& n : probes_) sum += value(rotation * n);
    return sum / self_;
  }

private:
  double value(const Eigen::Vector3d& n) const { return grid_.trilinear_value(n.x(), n.y(), n.z()); }

  void add(const Eigen::Vector3d& n)
  {
    const double h = grid_.voxel_size();
    const auto& o = grid_.origin();
    long nearest[3];
    for(int a = 0; a < 3; ++a) nearest[a] = long(std::floor((n[a] - o[a]) / h));
    for(long k = nearest[2] - reach; k <= nearest[2] + reach; ++k)
      for(long j = nearest[1] - reach; j <= nearest[1] + reach; ++j)
        for(long i = nearest[0] - reach; i <= nearest[0] + reach; ++i) {
          if(i < 0 || j < 0 || k < 0 || i >= long(resolution) || j >= long(resolution) || k >= long(resolution)) continue;
          const Eigen::Vector3d centre(o[0] + (double(i) + 0.5) * h, o[1] + (double(j) + 0.5) * h,
                                       o[2] + (double(k) + 0.5) * h);
          grid_(std::size_t(i), std::size_t(j), std::size_t(k)) +=
            std::exp(-(centre - n).squaredNorm() / (2. * width * width));
        }
  }

  Voxel_grid<Dkernel> grid_;
  std::vector<Eigen::Vector3d> probes_;
  double self_ = 0.;
};

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_ROTATION_NORMAL_DENSITY_H
