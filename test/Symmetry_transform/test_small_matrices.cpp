// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The small symmetric solvers of the Gauss-Newton steps and moment fits (small_matrices.h):
// solutions of systems with known solutions, the least-norm convention of a zero pivot, NaN
// propagated; eigenvalues and eigenvectors of matrices built from known ones.

#include <CGAL/Symmetry_transform/internal/common/small_matrices.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace {

using CGAL::Symmetry_transform::internal::solve_symmetric;
using CGAL::Symmetry_transform::internal::symmetric_eigen;

// A random rotation (the Q of a Gram-Schmidt of a random matrix, made right-handed).
Eigen::Matrix3d random_rotation(std::mt19937& random)
{
  std::normal_distribution<double> normal;
  Eigen::Vector3d a(normal(random), normal(random), normal(random)), b(normal(random), normal(random), normal(random));
  a.normalize();
  b = (b - b.dot(a) * a).normalized();
  Eigen::Matrix3d q;
  q << a, b, a.cross(b);
  return q;
}

template <int N>
void expect_solves_spd_systems(std::mt19937& random)
{
  std::normal_distribution<double> normal;
  for(int trial = 0; trial < 200; ++trial) {
    Eigen::Matrix<double, N, N> m;
    Eigen::Matrix<double, N, 1> x;
    for(int i = 0; i < N; ++i) {
      x[i] = normal(random);
      for(int j = 0; j < N; ++j) m(i, j) = normal(random);
    }
    const Eigen::Matrix<double, N, N> a = m * m.transpose() + 0.1 * Eigen::Matrix<double, N, N>::Identity();
    const Eigen::Matrix<double, N, 1> solution = solve_symmetric<N>(a, a * x);
    EXPECT_LE((solution - x).norm(), 1e-9 * (1. + x.norm())) << "N = " << N << ", trial " << trial;
  }
}

TEST(SmallMatrices, SolvesSymmetricPositiveDefiniteSystems)
{
  std::mt19937 random(1);
  expect_solves_spd_systems<2>(random);
  expect_solves_spd_systems<3>(random);
  expect_solves_spd_systems<4>(random);
}

// A pivot that is exactly zero leaves its unknown at zero (as Eigen's LDLT): the solution of
// least norm along a direction that the system does not see; the others are solved.
TEST(SmallMatrices, ZeroPivotGivesZeroUnknown)
{
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  a(0, 0) = 2.;
  a(2, 2) = 4.;
  const Eigen::Vector3d x = solve_symmetric<3>(a, Eigen::Vector3d(2., 5., 8.));
  EXPECT_EQ(x, Eigen::Vector3d(1., 0., 2.));
  EXPECT_EQ(solve_symmetric<2>(Eigen::Matrix2d::Zero(), Eigen::Vector2d(1., 1.)), Eigen::Vector2d::Zero());
}

TEST(SmallMatrices, NanPropagates)
{
  Eigen::Matrix3d a = Eigen::Matrix3d::Identity();
  a(1, 1) = std::nan("");
  EXPECT_FALSE(solve_symmetric<3>(a, Eigen::Vector3d(1., 1., 1.)).allFinite());
  EXPECT_FALSE(solve_symmetric<3>(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1., std::nan(""), 1.)).allFinite());
}

// Q diag(values) Q^T for random rotations Q: the values in increasing order, the columns of Q
// (up to sign) as eigenvectors, orthonormal; with two equal values, any orthonormal basis of
// their plane.
TEST(SmallMatrices, EigenvectorsOfSymmetricMatricesBuiltFromThem)
{
  std::mt19937 random(2);
  const double cases[][3] = {{3., -1., 0.5}, {1e-3, 1., 1e3}, {2., 2., 5.}, {0., 0., 0.}, {-4., 7., -4.}};
  for(const auto& values : cases)
    for(int trial = 0; trial < 100; ++trial) {
      const Eigen::Matrix3d q = random_rotation(random);
      const Eigen::Matrix3d m = q * Eigen::Vector3d(values[0], values[1], values[2]).asDiagonal() * q.transpose();
      const auto e = symmetric_eigen(m);
      Eigen::Vector3d sorted(values[0], values[1], values[2]);
      std::sort(sorted.data(), sorted.data() + 3);
      const double scale = 1. + m.norm();
      EXPECT_LE((e.values - sorted).norm(), 1e-13 * scale);
      EXPECT_LE((e.vectors.transpose() * e.vectors - Eigen::Matrix3d::Identity()).norm(), 1e-13);
      EXPECT_LE((m * e.vectors - e.vectors * e.values.asDiagonal()).norm(), 1e-13 * scale);
      for(int c = 0; c < 3; ++c) {
        const int count = int(std::count(sorted.data(), sorted.data() + 3, sorted[c]));
        if(count > 1) continue; // a repeated value: any unit vector of its eigenspace
        for(int k = 0; k < 3; ++k) {
          if(values[k] != sorted[c]) continue;
          EXPECT_NEAR(std::abs(e.vectors.col(c).dot(q.col(k))), 1., 1e-12);
        }
      }
    }
}

} // namespace
