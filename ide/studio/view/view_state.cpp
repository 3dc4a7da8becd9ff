#include "ide/studio/view/view_state.h"

#include "ide/studio/view/scene_geometry.h"

#include <algorithm>
#include <cstddef>

namespace studio {

Eigen::Isometry3d ViewState::bodyPose(int body) const
{
    return body < 0 || body >= static_cast<int>(poses.size()) ? Eigen::Isometry3d::Identity()
                                                              : poses[static_cast<std::size_t>(body)];
}

Eigen::AlignedBox3d ViewState::box() const
{
    Eigen::AlignedBox3d box = worldBounds(*geometry, poses, mode == DisplayMode::Schematic);
    if (box.isEmpty()) {
        box = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-3), Eigen::Vector3d::Constant(3));  // the grid's middle
    }
    return box;
}

void ViewState::sphere(Eigen::Vector3d& centre, double& radius) const
{
    const Eigen::AlignedBox3d b = box();
    centre = b.center();
    radius = std::max(0.5 * b.diagonal().norm(), 0.05);
}

}  // namespace studio
