#pragma once
// ViewState: what a 3D view shows, as plain data (no GL, no widgets): the model at its
// poses, the scene around it, the camera, and what is drawn over them (ghost, frames,
// contacts, highlight, the push's line). A Viewport holds one; its ViewRenderer draws
// it, its CameraController moves the camera and the push.

#include "ide/studio/model/model_bundle.h"
#include "ide/studio/sim/snapshot.h"
#include "ide/studio/view/camera.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <vector>

namespace studio {

struct SceneGeometry;
struct SceneDressing;

enum class DisplayMode { Schematic, Dressed, Both };

struct ViewState {
    std::shared_ptr<const ModelBundle> bundle;
    std::shared_ptr<const SceneGeometry> geometry;  ///< sceneGeometry(bundle)
    std::shared_ptr<const ModelBundle> scene;
    std::shared_ptr<const SceneDressing> dressing;  ///< sceneDressing(scene)
    std::vector<Eigen::Isometry3d> poses;           ///< X_wb by tree index (size nb)
    std::shared_ptr<const Snapshot> ghost;
    DisplayMode mode = DisplayMode::Dressed;
    Camera camera;
    bool showFrames = false;
    bool showContacts = false;
    std::shared_ptr<const Snapshot> contactsOf;  ///< the snapshot whose contacts are drawn
    bool showGrid = true;
    int highlightBody = -1;
    int highlightJoint = -1;
    // the push (Ctrl + drag): the body (−1 none), its grabbed point (body frame [m]) and
    // the target (world [m])
    int pushBody = -1;
    Eigen::Vector3d pushPoint = Eigen::Vector3d::Zero();
    Eigen::Vector3d pushTarget = Eigen::Vector3d::Zero();

    /// Body `body`'s pose X_wb (identity for the ground, −1, or an index out of range).
    Eigen::Isometry3d bodyPose(int body) const;
    /// The model's box as drawn in this mode at the current poses (the grid's middle,
    /// 6 m wide, when nothing is drawn): what the cameras frame.
    Eigen::AlignedBox3d box() const;
    /// The sphere around box() (radius at least 5 cm).
    void sphere(Eigen::Vector3d& centre, double& radius) const;
};

}  // namespace studio
