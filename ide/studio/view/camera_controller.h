#pragma once
// CameraController: moves a view's camera and push (ViewState::camera, push*) by name
// and by mouse. Mouse: left drag orbits, middle drag or Shift + left drag pans, the
// wheel zooms towards the cursor, a double click frames the whole model. Ctrl + left
// drag on a body pushes it (as MuJoCo's `simulate` perturbs one): the press picks the
// body and its point under the cursor (pickBody), the drag moves the target — the
// cursor's point in the plane through the grabbed point facing the camera — and the
// release ends it; the view says so (Viewport::pushMoved, pushReleased) and draws a
// red line joining the grabbed point (as the body moves) to the target. Ctrl + drag
// off the bodies does nothing; where the view cannot push, Ctrl + drag orbits as a
// plain drag. Cameras: orbit views "Iso", "Front" (from −y), "Side" (from +x), "Top",
// and "Operator seat" (a fixed eye, see setOperatorSeat); dragging in the seat view
// turns it into an orbit view.

#include "ide/studio/view/view_state.h"

#include <Eigen/Core>

#include <QPoint>
#include <QPointF>
#include <QString>
#include <QStringList>

class QMouseEvent;
class QWheelEvent;
class QWidget;

namespace studio {

class CameraController {
public:
    /// Moves `state`'s camera for `view` (the widget whose pixels the mouse is in).
    CameraController(ViewState& state, const QWidget& view);

    /// Names accepted by setCamera: "Iso", "Front", "Side", "Top", "Operator seat".
    static QStringList names();
    /// The seat's name ("Operator seat").
    static QString seatName();
    /// Switches to a named camera (orbit views frame the whole model). False for an
    /// unknown name.
    bool setCamera(const QString& name);
    /// The current named camera, or "" after the view was moved by hand.
    const QString& name() const { return m_name; }
    /// Puts the camera where `camera` says; the view then has no name.
    void setCameraState(const Camera& camera);
    /// Frames the whole model, keeping the view direction; the seat becomes an orbit camera.
    void fitAll();
    /// A new model: the default seat (unless one was set), and, for another model file
    /// (not `sameModel`, an edit), its named camera or the whole of it framed.
    void modelChanged(bool sameModel);
    /// The view was resized: named orbit views keep the whole model framed.
    void resized();

    /// The operator seat (Viewport::setOperatorSeat), kept across models until
    /// resetOperatorSeat().
    void setOperatorSeat(const Eigen::Vector3d& eye, double yawRad, double pitchRad);
    void resetOperatorSeat();
    /// Horizontal field of view of the seat camera [rad], within 5° to 170°.
    void setSeatFieldOfView(double radians);

    /// The body and its point under pixel (x, y) of the view (Viewport::pick).
    bool pick(const QPointF& pixel, int& body, Eigen::Vector3d& point) const;

    /// What a mouse event did: nothing, moved the camera, began or moved the push, ended it.
    enum class Change { None, Camera, Push, PushEnded };
    /// A press; `canPush`: Ctrl + left press pushes the body under the cursor.
    Change press(QMouseEvent* event, bool canPush);
    Change move(QMouseEvent* event);
    Change release(QMouseEvent* event);
    Change wheel(QWheelEvent* event);
    /// Ends the push (the button released, or a new model): PushEnded when there was one.
    Change endPush();

private:
    void applyNamedCamera();
    void leaveNamedCamera();
    double aspect() const;

    ViewState& m_state;
    const QWidget& m_view;
    QString m_name = QStringLiteral("Iso");
    bool m_seatSet = false;  ///< setOperatorSeat was called (else the model's default)
    QPoint m_lastMouse;
    bool m_dragging = false;
    /// The plane the push's target moves in: through the grabbed point as picked (world
    /// [m]), facing the camera.
    Eigen::Vector3d m_pushPlane = Eigen::Vector3d::Zero();
};

}  // namespace studio
