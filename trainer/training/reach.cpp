#include "trainer/training/reach.h"

namespace trainer {

ReachCheck checkReach(const solver::Model&, const std::vector<char>&, const std::vector<std::pair<int, double>>&, int,
                      const Eigen::Vector3d&, const Eigen::Vector3d&, double, const std::vector<Alignment>&)
{
    ReachCheck r;  // replaced by the IK-based check once solver/kinematics/inverse lands (this session)
    r.reachable = true;
    return r;
}

}  // namespace trainer
