#include "solver/dynamics/mass_matrix.h"

#include "solver/core/spatial.h"
#include "solver/kinematics/kinematics.h"

#include <vector>

namespace solver {

void massMatrixFromInertias(const Model& model, const Data& data, std::vector<Matrix6d>& composite,
                            Eigen::MatrixXd& M)
{
    const int nb = model.nb;
    M.setZero(nb, nb);  // bodies on different branches do not couple
    // composite inertias, leaves first (children have higher tree indices)
    for (int i = nb - 1; i >= 0; --i) {
        if (model.parent[i] >= 0) composite[model.parent[i]] += composite[i];
    }
    for (int i = 0; i < nb; ++i) {
        const Vector6d f = composite[i] * data.S[i];
        M(i, i) = data.S[i].dot(f);
        for (int j = model.parent[i]; j >= 0; j = model.parent[j]) M(j, i) = M(i, j) = data.S[j].dot(f);
    }
}

void massMatrix(const Model& model, const Data& data, Eigen::MatrixXd& M)
{
    std::vector<Matrix6d> composite(static_cast<std::size_t>(model.nb));
    for (int i = 0; i < model.nb; ++i) {
        const Eigen::Matrix3d R = data.X_wb[i].linear();
        const Eigen::Vector3d com = data.X_wb[i] * model.com[i];
        RigidInertia I;
        rigidInertiaAt(model.mass[i], com, R * model.inertia[i] * R.transpose(), I);
        I.toMatrix(composite[i]);
    }
    massMatrixFromInertias(model, data, composite, M);
}

Eigen::MatrixXd massMatrixAt(const Model& model, const State& state, Data& data)
{
    forwardKinematics(model, state, data);
    Eigen::MatrixXd M;
    massMatrix(model, data, M);
    return M;
}

}  // namespace solver
