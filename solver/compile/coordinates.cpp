#include "solver/compile/coordinates.h"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>

namespace solver {

int numericalRank(const Eigen::MatrixXd& m, double relTol)
{
    if (m.size() == 0) return 0;
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(m);
    const Eigen::VectorXd& s = svd.singularValues();
    const double threshold = relTol * std::max(s.size() > 0 ? s[0] : 0.0, 1.0);
    return static_cast<int>((s.array() > threshold).count());
}

CoordinatePartition partitionCoordinates(const Eigen::MatrixXd& jacobian,
                                         const std::vector<int>& preference, double relTol)
{
    CoordinatePartition part;
    part.rank = numericalRank(jacobian, relTol);

    // greedy: a column is dependent when it raises the rank of those taken
    Eigen::MatrixXd taken(jacobian.rows(), 0);
    for (int col : preference) {
        if (static_cast<int>(part.dependent.size()) >= part.rank) break;
        Eigen::MatrixXd trial(jacobian.rows(), taken.cols() + 1);
        trial << taken, jacobian.col(col);
        if (numericalRank(trial, relTol) > static_cast<int>(part.dependent.size())) {
            taken = std::move(trial);
            part.dependent.push_back(col);
        }
    }
    for (int col = 0; col < jacobian.cols(); ++col) {
        if (std::find(part.dependent.begin(), part.dependent.end(), col) == part.dependent.end()) {
            part.independent.push_back(col);
        }
    }
    return part;
}

Eigen::MatrixXd nullSpaceBasis(const Eigen::MatrixXd& jacobian, const std::vector<int>& independent,
                               const std::vector<int>& dependent)
{
    const auto ni = static_cast<Eigen::Index>(independent.size());
    const auto nd = static_cast<Eigen::Index>(dependent.size());
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(jacobian.cols(), ni);
    for (Eigen::Index i = 0; i < ni; ++i) g(independent[i], i) = 1;
    if (nd == 0 || ni == 0) return g;

    Eigen::MatrixXd jd(jacobian.rows(), nd), ji(jacobian.rows(), ni);
    for (Eigen::Index k = 0; k < nd; ++k) jd.col(k) = jacobian.col(dependent[k]);
    for (Eigen::Index k = 0; k < ni; ++k) ji.col(k) = jacobian.col(independent[k]);
    const Eigen::MatrixXd gd = -jd.colPivHouseholderQr().solve(ji);
    for (Eigen::Index k = 0; k < nd; ++k) g.row(dependent[k]) = gd.row(k);
    return g;
}

}  // namespace solver
