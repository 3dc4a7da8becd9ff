#include "ide/studio/view/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace studio {

using Eigen::Vector3d;

namespace {
constexpr double kHalfPi = std::numbers::pi / 2;
}

Vector3d Camera::forward() const
{
    if (mode == Mode::Seat) {
        const double h = seatHeading + yawOffset;
        return Vector3d(std::sin(h) * std::cos(seatPitch), std::cos(h) * std::cos(seatPitch), std::sin(seatPitch));
    }
    return -Vector3d(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch));
}

Vector3d Camera::right() const
{
    if (mode == Mode::Seat) {
        const double h = seatHeading + yawOffset;
        return Vector3d(std::cos(h), -std::sin(h), 0);
    }
    return Vector3d(-std::sin(yaw), std::cos(yaw), 0);
}

Vector3d Camera::up() const { return right().cross(forward()).normalized(); }

Vector3d Camera::eye() const
{
    return mode == Mode::Seat ? seatEye : Vector3d(target - distance * forward());
}

double Camera::verticalFieldOfView(double aspect) const
{
    if (mode == Mode::Seat) return 2 * std::atan(std::tan(0.5 * seatFieldOfView) / std::max(aspect, 1e-3));
    return fieldOfViewY;
}

Vector3d Camera::rayThrough(double x, double y, double width, double height) const
{
    const double aspect = width / std::max(height, 1.0);
    const double hh = std::tan(0.5 * verticalFieldOfView(aspect));  // half height at distance 1
    const double nx = 2 * x / std::max(width, 1.0) - 1;
    const double ny = 1 - 2 * y / std::max(height, 1.0);
    return (forward() + right() * (nx * hh * aspect) + up() * (ny * hh)).normalized();
}

Eigen::Matrix4d Camera::viewMatrix() const
{
    const Vector3d f = forward(), r = right(), u = up(), e = eye();
    Eigen::Matrix4d v = Eigen::Matrix4d::Identity();
    v.block<1, 3>(0, 0) = r.transpose();
    v.block<1, 3>(1, 0) = u.transpose();
    v.block<1, 3>(2, 0) = -f.transpose();
    v(0, 3) = -r.dot(e);
    v(1, 3) = -u.dot(e);
    v(2, 3) = f.dot(e);
    return v;
}

bool Camera::pixelOf(const Vector3d& p, double width, double height, Eigen::Vector2d& pixel) const
{
    const double aspect = width / std::max(height, 1.0);
    const Eigen::Vector4d e = viewMatrix() * p.homogeneous();
    if (e.z() >= 0) return false;
    const double t = 1.0 / std::tan(0.5 * verticalFieldOfView(aspect));
    const double x = t / aspect * e.x() / -e.z(), y = t * e.y() / -e.z();
    pixel = Eigen::Vector2d((x + 1) / 2 * width, (1 - y) / 2 * height);
    return true;
}

Eigen::Matrix4d Camera::projectionMatrix(double aspect, const Vector3d& centre, double radius, double farthest) const
{
    const double fovy = verticalFieldOfView(aspect);
    const double ahead = (centre - eye()).dot(forward());
    const double far = std::max({ahead + 1.5 * radius, (centre - eye()).norm() + farthest, 1e-2});
    // near: a small fraction of the distance (the grid may come closer than the model)
    const double nearClamped = std::min(std::max(0.01 * std::max(ahead, radius), far * 1e-5), 0.5 * far);
    const double t = 1.0 / std::tan(0.5 * fovy);
    Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
    p(0, 0) = t / aspect;
    p(1, 1) = t;
    p(2, 2) = -(far + nearClamped) / (far - nearClamped);
    p(2, 3) = -2 * far * nearClamped / (far - nearClamped);
    p(3, 2) = -1;
    return p;
}

void Camera::frame(const Eigen::AlignedBox3d& box, double aspect)
{
    mode = Mode::Orbit;
    target = box.center();
    const double ty = std::tan(0.5 * fieldOfViewY) / 1.08;  // 8 % margin
    const double tx = ty * aspect;
    const Vector3d f = forward(), r = right(), u = up();
    // a corner p (from the target) is at depth distance + p·f: it is in view when
    // |p·r| ≤ (distance + p·f) tx and |p·u| ≤ (distance + p·f) ty
    double d = 1e-3;
    for (int c = 0; c < 8; ++c) {
        const Vector3d p = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)) - target;
        const double z = p.dot(f);
        d = std::max({d, std::abs(p.dot(r)) / tx - z, std::abs(p.dot(u)) / ty - z});
    }
    distance = d;
}

void Camera::toOrbit(double pivotDistance)
{
    if (mode == Mode::Orbit) return;
    const Vector3d f = forward();
    const Vector3d e = seatEye;
    mode = Mode::Orbit;
    distance = std::max(pivotDistance, 1e-3);
    target = e + distance * f;
    pitch = std::asin(std::clamp(-f.z(), -1.0, 1.0));
    yaw = std::atan2(-f.y(), -f.x());
}

void Camera::orbit(double dx, double dy)
{
    yaw -= 0.008 * dx;
    pitch = std::clamp(pitch + 0.008 * dy, -kHalfPi, kHalfPi);
}

void Camera::pan(double dx, double dy, double height)
{
    const double perPixel = 2 * distance * std::tan(0.5 * fieldOfViewY) / std::max(height, 1.0);
    target += -right() * dx * perPixel + up() * dy * perPixel;
}

void Camera::zoom(double factor, double x, double y, double width, double height)
{
    const double aspect = width / std::max(height, 1.0);
    const double hh = distance * std::tan(0.5 * fieldOfViewY);
    const double hw = hh * aspect;
    const double nx = 2 * x / std::max(width, 1.0) - 1;
    const double ny = 1 - 2 * y / std::max(height, 1.0);
    const Vector3d under = target + right() * (nx * hw) + up() * (ny * hh);
    distance *= factor;
    target = under + (target - under) * factor;
}

}  // namespace studio
