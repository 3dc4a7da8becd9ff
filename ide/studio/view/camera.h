#pragma once
// Camera: the viewport's eye, in one of two modes (no GL, no Qt widgets).
//
//  - Orbit: looks at `target` from `distance`, the eye at azimuth `yaw` (from +x,
//    counter-clockwise seen from above) and elevation `pitch` over the target. The
//    named views Iso, Front (from −y), Side (from +x) and Top are orbit poses.
//  - Seat: a fixed eye (the operator's seat) looking at heading `seatHeading` (0 = +y,
//    positive turns right, i.e. clockwise seen from above) plus `yawOffset` (one
//    screen of a three-screen station), and pitch `seatPitch` (positive up), with a
//    horizontal field of view of `seatFieldOfView`, so that screens whose yaw
//    offsets differ by that angle join edge to edge.
//
// World: z up, metres. Matrices are OpenGL's (view: world → eye, looking along −z).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace studio {

class Camera {
public:
    enum class Mode { Orbit, Seat };

    Mode mode = Mode::Orbit;
    // orbit
    Eigen::Vector3d target = Eigen::Vector3d::Zero();
    double distance = 10;    ///< [m]
    double yaw = -1.0;       ///< [rad]
    double pitch = 0.45;     ///< [rad], within ±π/2
    double fieldOfViewY = 0.7;  ///< vertical field of view of the orbit camera [rad]
    // seat
    Eigen::Vector3d seatEye = Eigen::Vector3d(0, -5, 2);
    double seatHeading = 0;     ///< [rad]
    double seatPitch = 0;       ///< [rad]
    double yawOffset = 0;       ///< [rad], added to the heading
    double seatFieldOfView = 60 * 3.14159265358979323846 / 180;  ///< horizontal [rad]

    Eigen::Vector3d eye() const;
    Eigen::Vector3d forward() const;  ///< unit viewing direction
    Eigen::Vector3d right() const;    ///< unit, horizontal
    Eigen::Vector3d up() const;       ///< unit, right × forward
    /// Vertical field of view for a viewport of this aspect ratio (width / height) [rad].
    double verticalFieldOfView(double aspect) const;

    Eigen::Matrix4d viewMatrix() const;
    /// The unit direction from eye() through pixel (x, y) of a width × height viewport
    /// (the inverse of the view and projection matrices: the ray under the cursor).
    Eigen::Vector3d rayThrough(double x, double y, double width, double height) const;
    /// Where world point `p` shows in a width × height viewport (pixels, y down): false
    /// when it is behind the eye.
    bool pixelOf(const Eigen::Vector3d& p, double width, double height, Eigen::Vector2d& pixel) const;
    /// Perspective projection, clip planes chosen so that a sphere (centre, radius)
    /// and the ground grid out to `farthest` metres are inside.
    Eigen::Matrix4d projectionMatrix(double aspect, const Eigen::Vector3d& centre, double radius,
                                     double farthest) const;

    /// Becomes an orbit camera looking at the box's centre from the current yaw and pitch,
    /// just far enough for all of the box to be in view (with a small margin).
    void frame(const Eigen::AlignedBox3d& box, double aspect);
    /// Turns a seat camera into an orbit camera with the same eye and direction,
    /// pivoting at `pivotDistance` ahead of the eye.
    void toOrbit(double pivotDistance);

    /// Orbit by a mouse drag of (dx, dy) pixels.
    void orbit(double dx, double dy);
    /// Moves the target by a drag of (dx, dy) pixels in a viewport `height` pixels high.
    void pan(double dx, double dy, double height);
    /// Zooms by `factor` (< 1 closer) keeping the point under the cursor (pixel x, y of
    /// a width × height viewport) where it is on the screen.
    void zoom(double factor, double x, double y, double width, double height);
};

}  // namespace studio
