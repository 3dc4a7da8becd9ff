#pragma once
// Independent and dependent coordinates: which tree coordinates a set of
// loop-closure equations determines, chosen greedily by preference.

#include <Eigen/Core>

#include <vector>

namespace solver {

/// Numerical rank of `m` by singular values: the number of σ > relTol · max(σ_max, 1).
/// Pass a matrix scaled so that its entries are dimensionless and of order 1.
int numericalRank(const Eigen::MatrixXd& m, double relTol = 1e-9);

struct CoordinatePartition {
    std::vector<int> dependent;  ///< column indices, in the order they were chosen
    std::vector<int> independent;  ///< the other column indices, increasing
    int rank = 0;  ///< rank of the whole matrix
};

/// Splits the columns of a constraint Jacobian Φ_θ (rows: equations, columns: tree
/// coordinates) into dependent and independent ones. `preference` lists column
/// indices, most wanted as dependent first; each is taken as dependent when its
/// column increases the rank of the columns already taken, until the rank of the
/// whole matrix is reached. Columns not in `preference` are independent.
/// The dependent columns then have full column rank, so θ̇_dep = −Φ_dep⁺ Φ_ind θ̇_ind.
CoordinatePartition partitionCoordinates(const Eigen::MatrixXd& jacobian,
                                         const std::vector<int>& preference, double relTol = 1e-9);

/// Basis G (dim ncols × independent.size()) of the constraint null space in terms of
/// the independent rates: θ̇ = G θ̇_ind, rows of independent columns the identity,
/// rows of dependent columns −Φ_dep⁺ Φ_ind (least squares; Φ_dep has full column
/// rank). Columns of `jacobian` not listed in either set get zero rows.
Eigen::MatrixXd nullSpaceBasis(const Eigen::MatrixXd& jacobian, const std::vector<int>& independent,
                               const std::vector<int>& dependent);

}  // namespace solver
