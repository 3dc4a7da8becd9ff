#include "solver/dynamics/mass_matrix.h"

#include "solver/core/spatial.h"

#include <vector>

namespace solver {

void massMatrix(const Model& model, const Data& data, Eigen::MatrixXd& M)
{
    const int nb = model.nb;
    M.setZero(nb, nb);
    // composite inertias, leaves first (children have higher tree indices)
    std::vector<Matrix6d> composite(static_cast<std::size_t>(nb));
    for (int i = 0; i < nb; ++i) {
        const Eigen::Matrix3d R = data.X_wb[i].linear();
        const Eigen::Vector3d com = data.X_wb[i] * model.com[i];
        rigidInertiaAt(model.mass[i], com, R * model.inertia[i] * R.transpose()).toMatrix(composite[i]);
    }
    for (int i = nb - 1; i >= 0; --i) {
        if (model.parent[i] >= 0) composite[model.parent[i]] += composite[i];
    }
    for (int i = 0; i < nb; ++i) {
        const Vector6d f = composite[i] * data.S[i];
        M(i, i) = data.S[i].dot(f);
        for (int j = model.parent[i]; j >= 0; j = model.parent[j]) M(j, i) = M(i, j) = data.S[j].dot(f);
    }
}

}  // namespace solver
