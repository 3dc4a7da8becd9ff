#include "tests/solver/dynamics/thesis_oracle.h"

namespace solver::test {

OracleResult solveThesisSystem(const Model& model, const State& state,
                               const std::vector<Vector6d>& fext, const Eigen::VectorXd& tauExt)
{
    return reference::solveNewtonEuler(model, state, fext, tauExt);
}

}  // namespace solver::test
