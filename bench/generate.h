#pragma once
// Model text generators for scaling studies (`padrob bench --scaling`, the
// benchmark suite): models of any size in the model language (docs/model-language.md),
// loaded like any file, so a benchmark pays for nothing a real model does not.
//
// chain(n): n links hanging from the ground in a line, joint i between link i−1
//   (0 = the ground) and link i. Joints are revolute about x and y in turn, so the
//   chain moves in 3-D.
// tree(n): a binary tree of n links: link k hangs from link ⌊k/2⌋ (link 1 from the
//   ground), link 2k on the +x side of its parent's lower end and 2k+1 on the −x side;
//   joints about x at even depths and about y at odd ones.
// Links: length `linkLength` [m] along −z at the initial pose (all coordinates 0:
// hanging straight down), mass `linkMass` [kg], the inertia of a solid rod of radius
// linkLength/10 about its centre of mass (its frame's origin). Every
// `driveEvery`-th joint (1, 1 + k, 1 + 2k, …) has a HYD drive with VMAX `driveSpeed`
// [rad/s], the limits ±driveLimit [rad] (near enough for a commanded drive to reach
// them) and a relief torque FMAX = FMIN = m·g·L·c·h (c links below the joint, h the
// longest chain of links below it, itself included), several times the static torque
// at the limit, so the relief valves are watched but rarely open. The other joints
// are passive with the limits ±limit [rad]. Bodies and joints have ids 1 … n.

#include <string>

namespace bench {

struct GeneratedModelOptions {
    double linkLength = 0.1;  ///< [m]
    double linkMass = 1.0;    ///< [kg]
    int driveEvery = 3;       ///< a HYD drive on every k-th joint (from joint 1); 0: passive
    double driveSpeed = 0.5;  ///< VMAX = VMIN of the drives [rad/s]
    double driveLimit = 0.2;  ///< LL −driveLimit, UL +driveLimit on the driven joints [rad]; 0: none
    double limit = 0.5;       ///< LL −limit, UL +limit on the passive joints [rad]; 0: none
};

/// A chain of n ≥ 1 links (above).
std::string chainModelText(int n, const GeneratedModelOptions& options = {});
/// A binary tree of n ≥ 1 links (above).
std::string treeModelText(int n, const GeneratedModelOptions& options = {});

}  // namespace bench
