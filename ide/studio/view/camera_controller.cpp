#include "ide/studio/view/camera_controller.h"

#include "ide/studio/view/scene_geometry.h"

#include <QMouseEvent>
#include <QWheelEvent>
#include <QWidget>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace studio {

using Eigen::Vector3d;

namespace {

constexpr double kDeg = std::numbers::pi / 180;

struct NamedView {
    const char* name;
    double yaw, pitch;  // orbit angles [rad]
};
// Front looks from −y (at the back of a machine whose arm points along +y), Side from +x
const NamedView kViews[] = {
    {"Iso", -40 * kDeg, 30 * kDeg},
    {"Front", -90 * kDeg, 0},
    {"Side", 0, 0},
    {"Top", -90 * kDeg, 90 * kDeg},
};
const char* const kSeat = "Operator seat";

}  // namespace

CameraController::CameraController(ViewState& state, const QWidget& view) : m_state(state), m_view(view) {}

// ---- named cameras ---------------------------------------------------------------------

QStringList CameraController::names()
{
    QStringList names;
    for (const NamedView& v : kViews) names << QString::fromLatin1(v.name);
    names << seatName();
    return names;
}

QString CameraController::seatName()
{
    return QString::fromLatin1(kSeat);
}

void CameraController::setCameraState(const Camera& camera)
{
    m_state.camera = camera;
    m_name.clear();
}

bool CameraController::setCamera(const QString& name)
{
    if (!names().contains(name)) return false;
    m_name = name;
    applyNamedCamera();
    return true;
}

void CameraController::applyNamedCamera()
{
    Camera& camera = m_state.camera;
    if (m_name == QLatin1String(kSeat)) {
        camera.mode = Camera::Mode::Seat;
        return;
    }
    for (const NamedView& v : kViews) {
        if (m_name != QLatin1String(v.name)) continue;
        camera.mode = Camera::Mode::Orbit;
        camera.yaw = v.yaw;
        camera.pitch = v.pitch;
        camera.frame(m_state.box(), aspect());
    }
}

void CameraController::leaveNamedCamera()
{
    Camera& camera = m_state.camera;
    if (camera.mode == Camera::Mode::Seat) {
        Vector3d c;
        double r = 0;
        m_state.sphere(c, r);
        const double ahead = (c - camera.eye()).dot(camera.forward());
        camera.toOrbit(std::max(ahead, 0.5 * r));
    }
    m_name.clear();
}

void CameraController::fitAll()
{
    if (m_state.camera.mode == Camera::Mode::Seat) leaveNamedCamera();
    m_state.camera.frame(m_state.box(), aspect());
}

void CameraController::modelChanged(bool sameModel)
{
    if (!m_seatSet) {
        m_state.camera.seatEye = m_state.geometry->seatEye;
        m_state.camera.seatHeading = 0;
        m_state.camera.seatPitch = m_state.geometry->seatPitch;
    }
    // an edited model (same file) keeps the view the modeler chose
    if (!sameModel) {
        if (m_name.isEmpty()) fitAll();
        else applyNamedCamera();
    }
}

void CameraController::resized()
{
    if (!m_name.isEmpty() && m_state.camera.mode == Camera::Mode::Orbit) applyNamedCamera();
}

void CameraController::setOperatorSeat(const Vector3d& eye, double yawRad, double pitchRad)
{
    m_seatSet = true;
    m_state.camera.seatEye = eye;
    m_state.camera.seatHeading = yawRad;
    m_state.camera.seatPitch = std::clamp(pitchRad, -std::numbers::pi / 2, std::numbers::pi / 2);
}

void CameraController::resetOperatorSeat()
{
    m_seatSet = false;
    m_state.camera.seatEye = m_state.geometry->seatEye;
    m_state.camera.seatHeading = 0;
    m_state.camera.seatPitch = m_state.geometry->seatPitch;
}

void CameraController::setSeatFieldOfView(double radians)
{
    m_state.camera.seatFieldOfView = std::clamp(radians, 5 * kDeg, 170 * kDeg);
}

double CameraController::aspect() const
{
    return m_view.height() > 0 ? static_cast<double>(m_view.width()) / m_view.height() : 1.0;
}

// ---- mouse -------------------------------------------------------------------------------

bool CameraController::pick(const QPointF& pixel, int& body, Vector3d& point) const
{
    if (!m_state.geometry) return false;
    const Camera& camera = m_state.camera;
    const Vector3d dir = camera.rayThrough(pixel.x(), pixel.y(), m_view.width(), m_view.height());
    return pickBody(*m_state.geometry, m_state.poses, camera.eye(), dir, m_state.mode != DisplayMode::Dressed,
                    m_state.mode != DisplayMode::Schematic, body, point);
}

CameraController::Change CameraController::press(QMouseEvent* event, bool canPush)
{
    m_lastMouse = event->position().toPoint();
    event->accept();
    if (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ControlModifier) && canPush) {
        // a push: the body under the cursor, or nothing (no orbit either)
        m_dragging = false;
        int body = -1;
        Vector3d hit;
        if (!pick(event->position(), body, hit)) return Change::None;
        m_state.pushBody = body;
        m_state.pushPoint = m_state.bodyPose(body).inverse() * hit;
        m_state.pushTarget = m_pushPlane = hit;
        return Change::Push;
    }
    m_dragging = m_state.pushBody < 0;
    return Change::None;
}

CameraController::Change CameraController::move(QMouseEvent* event)
{
    Camera& camera = m_state.camera;
    if (m_state.pushBody >= 0) {
        // the target: the cursor's point in the plane through the grabbed point facing the camera
        const Vector3d eye = camera.eye(), n = camera.forward();
        const QPointF p = event->position();
        const Vector3d dir = camera.rayThrough(p.x(), p.y(), m_view.width(), m_view.height());
        const double along = dir.dot(n);
        event->accept();
        if (!(along > 1e-9)) return Change::None;
        m_state.pushTarget = eye + ((m_pushPlane - eye).dot(n) / along) * dir;
        return Change::Push;
    }
    if (!m_dragging) return Change::None;
    const QPoint pos = event->position().toPoint();
    const QPoint d = pos - m_lastMouse;
    m_lastMouse = pos;
    if (d.isNull()) return Change::None;
    const bool pan = (event->buttons() & Qt::MiddleButton) ||
                     ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ShiftModifier));
    const bool orbit = !pan && (event->buttons() & Qt::LeftButton);
    if (!pan && !orbit) return Change::None;
    leaveNamedCamera();
    if (pan) camera.pan(d.x(), d.y(), m_view.height());
    else camera.orbit(d.x(), d.y());
    event->accept();
    return Change::Camera;
}

CameraController::Change CameraController::release(QMouseEvent* event)
{
    m_dragging = false;
    event->accept();
    return event->button() == Qt::LeftButton ? endPush() : Change::None;
}

CameraController::Change CameraController::endPush()
{
    if (m_state.pushBody < 0) return Change::None;
    m_state.pushBody = -1;
    return Change::PushEnded;
}

CameraController::Change CameraController::wheel(QWheelEvent* event)
{
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0) return Change::None;
    leaveNamedCamera();
    const QPointF p = event->position();
    m_state.camera.zoom(std::pow(0.85, steps), p.x(), p.y(), m_view.width(), m_view.height());
    event->accept();
    return Change::Camera;
}

}  // namespace studio
