#pragma once
// Can a REACH goal be reached? Inverse kinematics over the tutorial's enabled drives
// (solver/kinematics/inverse.h), from the tutorial's initial pose, joint limits kept.

#include "solver/core/model.h"
#include "trainer/training/tutorial.h"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace trainer {

struct ReachCheck {
    bool reachable = false;
    double positionError = 0.0;  ///< [m] of the nearest pose found
    double angleError = 0.0;     ///< [rad] the worst alignment's excess over its tolerance
};

/// Whether `point` on `body` (tree index, body frame) can be brought within `tolerance`
/// of `target` with its alignments kept, moving only the joints whose drive is enabled
/// (`enabled`, per tree joint), the others at `initial` (tree joint → θ) or their QI.
ReachCheck checkReach(const solver::Model& model, const std::vector<char>& enabled,
                      const std::vector<std::pair<int, double>>& initial, int body, const Eigen::Vector3d& point,
                      const Eigen::Vector3d& target, double tolerance, const std::vector<Alignment>& align);

}  // namespace trainer
