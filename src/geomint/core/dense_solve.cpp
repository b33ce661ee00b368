// The fixed-size dense kernels of core/dense_solve.hpp, compiled once per size.
#include "geomint/core/dense_solve.hpp"

#include <Eigen/Eigenvalues>

namespace geomint {

template Vec<1> lu_solve<1>(const Mat<1>&, const Vec<1>&);
template Vec<2> lu_solve<2>(const Mat<2>&, const Vec<2>&);
template Vec<18> lu_solve<18>(const Mat<18>&, const Vec<18>&);

template <int D>
double largest_symmetric_eigenvalue(const Mat<D>& A) {
  return Eigen::SelfAdjointEigenSolver<Mat<D>>(A, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
}
template double largest_symmetric_eigenvalue<1>(const Mat<1>&);
template double largest_symmetric_eigenvalue<2>(const Mat<2>&);
template double largest_symmetric_eigenvalue<18>(const Mat<18>&);

}  // namespace geomint
