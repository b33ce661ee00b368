#pragma once
// The two dense linear-algebra kernels of the implicit and processed methods, on fixed-size
// matrices: x = A^{-1} b by LU with partial pivoting (Eigen's PartialPivLU) and the largest
// eigenvalue of a symmetric matrix (Eigen's SelfAdjointEigenSolver, eigenvalues only). The sizes
// the systems of the papers use (1, 2 and 18 = LennardJones<9>) are compiled once, in
// dense_solve.cpp; lu_solve instantiates itself for any other size, largest_symmetric_eigenvalue
// needs a line there.
#include <Eigen/LU>

#include "geomint/core/state.hpp"

namespace geomint {

template <int D>
Vec<D> lu_solve(const Mat<D>& A, const Vec<D>& b) {
  return A.partialPivLu().solve(b);
}
extern template Vec<1> lu_solve<1>(const Mat<1>&, const Vec<1>&);
extern template Vec<2> lu_solve<2>(const Mat<2>&, const Vec<2>&);
extern template Vec<18> lu_solve<18>(const Mat<18>&, const Vec<18>&);

template <int D>
double largest_symmetric_eigenvalue(const Mat<D>& A);  // for D = 1, 2, 18

}  // namespace geomint
