// Copyright (c) 2026 The CGAL Symmetry_transform project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): The CGAL Symmetry_transform developers

#ifndef CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_SMALL_MATRICES_H
#define CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_SMALL_MATRICES_H

// Linear systems and eigenvectors of the symmetric 2x2 to 4x4 matrices of the Gauss-Newton steps
// and moment fits, by the textbook algorithms on the coefficients. Eigen's decompositions
// (ldlt(), SelfAdjointEigenSolver) do the same, but each of them costs every program that
// includes the package seconds of compilation and hundreds of megabytes of compiler memory.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace CGAL::Symmetry_transform::internal {

// The solution x of a x = b, a symmetric positive semi-definite, by the LDLT factorisation with
// diagonal pivoting (the largest remaining diagonal first); as Eigen's LDLT, a zero pivot gives
// zero to its unknown (the least-norm solution along it), and NaN in a or b gives NaN.
template <int N>
Eigen::Matrix<double, N, 1> solve_symmetric(Eigen::Matrix<double, N, N> a, const Eigen::Matrix<double, N, 1>& b)
{
  int order[N];
  for(int i = 0; i < N; ++i) order[i] = i;
  for(int k = 0; k < N; ++k) {
    int pivot = k;
    for(int i = k + 1; i < N; ++i)
      if(std::abs(a(i, i)) > std::abs(a(pivot, pivot))) pivot = i;
    if(pivot != k) {
      std::swap(order[k], order[pivot]);
      for(int j = 0; j < N; ++j) std::swap(a(k, j), a(pivot, j));
      for(int i = 0; i < N; ++i) std::swap(a(i, k), a(i, pivot));
    }
    const double d = a(k, k);
    if(std::abs(d) <= (std::numeric_limits<double>::min)()) { // L's column stays zero
      for(int i = k + 1; i < N; ++i) a(i, k) = 0.;
      continue;
    }
    // The Schur complement, kept whole (both triangles) for the next pivot's swaps; row k keeps
    // the column before the division.
    for(int i = k + 1; i < N; ++i)
      for(int j = k + 1; j < N; ++j) a(i, j) -= a(i, k) * a(k, j) / d;
    for(int i = k + 1; i < N; ++i) a(i, k) /= d;
  }
  // a holds L below its diagonal and D on it; solve L D L^T y = P b, then x = P^T y.
  double y[N];
  for(int i = 0; i < N; ++i) {
    y[i] = b[order[i]];
    for(int j = 0; j < i; ++j) y[i] -= a(i, j) * y[j];
  }
  for(int i = 0; i < N; ++i) y[i] = std::abs(a(i, i)) <= (std::numeric_limits<double>::min)() ? 0. : y[i] / a(i, i);
  for(int i = N - 1; i >= 0; --i)
    for(int j = i + 1; j < N; ++j) y[i] -= a(j, i) * y[j];
  Eigen::Matrix<double, N, 1> x;
  for(int i = 0; i < N; ++i) x[order[i]] = y[i];
  return x;
}

// The eigenvalues of a symmetric 3x3 matrix in increasing order, and their unit eigenvectors as
// the columns of `vectors` (in the same order), by cyclic Jacobi rotations.
struct Symmetric_eigen_3
{
  Eigen::Vector3d values;
  Eigen::Matrix3d vectors;
};

// Jacobi sweeps stop once the off-diagonal part is below this fraction of the matrix's norm (a
// few units in the last place); a sweep more than the quadratic convergence needs is the bound.
constexpr double jacobi_off_diagonal_fraction = 1e-15;
constexpr int jacobi_max_sweeps = 32;

inline Symmetric_eigen_3 symmetric_eigen(const Eigen::Matrix3d& m)
{
  double a[3][3];
  double v[3][3] = {{1., 0., 0.}, {0., 1., 0.}, {0., 0., 1.}};
  double norm2 = 0.;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) {
      a[i][j] = 0.5 * (m(i, j) + m(j, i));
      norm2 += a[i][j] * a[i][j];
    }
  const double floor2 = jacobi_off_diagonal_fraction * jacobi_off_diagonal_fraction * norm2;
  for(int sweep = 0; sweep < jacobi_max_sweeps; ++sweep) {
    if(!(2. * (a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2]) > floor2)) break;
    for(int p = 0; p < 2; ++p)
      for(int q = p + 1; q < 3; ++q) {
        if(a[p][q] == 0.) continue;
        // The rotation in the (p, q) plane that zeroes a[p][q] (Golub and Van Loan, 8.5.2).
        const double theta = (a[q][q] - a[p][p]) / (2. * a[p][q]);
        const double t = (theta >= 0. ? 1. : -1.) / (std::abs(theta) + std::sqrt(theta * theta + 1.));
        const double c = 1. / std::sqrt(t * t + 1.), s = t * c;
        for(int k = 0; k < 3; ++k) { // a <- a J
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for(int k = 0; k < 3; ++k) { // a <- J^T a
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for(int k = 0; k < 3; ++k) { // v <- v J
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
  }
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return a[i][i] < a[j][j]; });
  Symmetric_eigen_3 result;
  for(int c = 0; c < 3; ++c) {
    result.values[c] = a[order[c]][order[c]];
    for(int k = 0; k < 3; ++k) result.vectors(k, c) = v[k][order[c]];
  }
  return result;
}

} // namespace CGAL::Symmetry_transform::internal

#endif // CGAL_SYMMETRY_TRANSFORM_INTERNAL_COMMON_SMALL_MATRICES_H
