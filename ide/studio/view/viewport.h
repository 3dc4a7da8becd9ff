#pragma once
// Viewport: the 3D view of a model (OpenGL 3.3 core profile; runs on Mesa llvmpipe).
//
// It draws the bundle's bodies at the poses it is given (by tree index; before any,
// at the model's initial state), in one of three display modes (Schematic, Dressed,
// Both), with a ground grid, the world axes, the bodies' frames on demand, and a
// highlighted body and joint; a scene (setScene: the ground graphics of another model
// file, e.g. the SAG mill the liner manipulator works in) is drawn around the model,
// never highlighted and never framed by Fit All. How: view_renderer.h.
//
// It is a QWidget assembled from four parts, each in its own file:
//  - ViewState (view_state.h): what it shows, as plain data;
//  - ViewRenderer (view_renderer.h): draws a frame of it in any current OpenGL 3.3
//    context: the view's frames on screen, grabFramebuffer() and the frame bench;
//  - ViewWindow (view_window.h): a native window (QWidget::createWindowContainer) with
//    its own OpenGL context, from which a frame goes straight to swapBuffers, not
//    through Qt's widget composition, and the pacing of its frames;
//  - OverlayCompositor (overlay_compositor.h): so that widgets over the view still
//    show, they are drawn into the frame (addOverlay); grabFramebuffer() draws a frame
//    offscreen without them, and QWidget::grab()/render() of the window show it;
//  - CameraController (camera_controller.h): named cameras and the mouse: left drag
//    orbits, middle drag or Shift + left drag pans, the wheel zooms towards the cursor,
//    a double click frames the whole model, Ctrl + left drag on a body pushes it. Only
//    a view whose pushMoved() is connected pushes (the Model workspace's screens, wired
//    to the simulation); in the others Ctrl + drag orbits as a plain drag.

#include "ide/studio/model/model_bundle.h"
#include "ide/studio/sim/snapshot.h"
#include "ide/studio/view/camera.h"
#include "ide/studio/view/camera_controller.h"
#include "ide/studio/view/overlay_compositor.h"
#include "ide/studio/view/view_renderer.h"
#include "ide/studio/view/view_state.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QImage>
#include <QPointF>
#include <QSurfaceFormat>
#include <QWidget>

#include <memory>
#include <vector>

class QOpenGLContext;

namespace studio {

class ViewWindow;

class Viewport : public QWidget {
    Q_OBJECT
public:
    explicit Viewport(QWidget* parent = nullptr);
    ~Viewport() override;

    /// The surface format every viewport asks for: OpenGL 3.3 core, depth 24, samples().
    /// Best also set as the default format before QApplication exists
    /// (QSurfaceFormat::setDefaultFormat), so all of a window's GL widgets agree.
    static QSurfaceFormat surfaceFormat();
    /// Multisampling (antialiasing) of the viewports created from now on: 0 (the
    /// default) or 2, 4, 8. A software renderer (Mesa llvmpipe) draws a 4× multisampled
    /// frame about three times slower, so turn it on only with a GPU.
    static void setSamples(int samples);
    static int samples();
    /// Back-face culling of closed solids that nothing cuts open (on by default; the
    /// pictures are the same either way, culling only skips triangles that cannot show).
    static void setBackFaceCulling(bool on);
    static bool backFaceCulling();
    /// Where the light is computed: at every pixel (the finer picture: highlights and
    /// lamps' pools exact across every face), at the vertices (Gouraud shading: a pixel
    /// takes its triangle's blend, large faces being cut into a grid for it, and one
    /// pass instead of a depth pass and a colour pass), or Automatic (the default): at
    /// the vertices on a software OpenGL (Mesa llvmpipe, softpipe), where a frame's cost
    /// is its pixels', at every pixel on a GPU. Every viewport follows a change at its
    /// next frame.
    using Lighting = studio::Lighting;
    static void setLighting(Lighting lighting);
    static Lighting lighting();
    /// "auto", "pixel", "vertex" (for command lines and settings), and back; false for
    /// another word.
    static QString lightingName(Lighting lighting);
    static bool lightingFromName(const QString& name, Lighting& lighting);
    /// This viewport lights at the vertices (lighting() resolved against its OpenGL,
    /// known once it has drawn).
    bool lightsPerVertex() const { return m_renderer.lightsPerVertex(); }
    /// Its OpenGL's renderer (GL_RENDERER), once it has drawn ("" before).
    QString renderer() const { return m_renderer.glRenderer(); }

    /// The model to draw (nullptr: an empty scene). Builds its meshes (once per bundle)
    /// and draws it at its initial pose until setPoses; frames the camera on a new
    /// model. Meshes that cannot be drawn are reported through problem(), once.
    void setBundle(std::shared_ptr<const ModelBundle> bundle);
    std::shared_ptr<const ModelBundle> bundle() const { return m_state.bundle; }
    /// The scene drawn around the model (scene_file.h; its ground graphics only), or
    /// nullptr for none. Its meshes that cannot be drawn are reported through problem().
    void setScene(std::shared_ptr<const ModelBundle> scene);
    std::shared_ptr<const ModelBundle> scene() const { return m_state.scene; }

    /// Body poses X_wb by tree index (size Model::nb; other sizes are ignored).
    void setPoses(const std::vector<Eigen::Isometry3d>& X_wb);
    const std::vector<Eigen::Isometry3d>& poses() const { return m_state.poses; }
    /// The snapshot's poses (and its bundle, when it is another one).
    void setSnapshot(std::shared_ptr<const Snapshot> snapshot);

    /// A ghost: a second machine of the same bundle at the snapshot's poses, drawn
    /// translucent (kGhostAlpha, tinted, without depth writes) over the scene, e.g.
    /// the expert's run beside the operator's. A snapshot of another bundle (or other
    /// body count) is not drawn. clearGhost() removes it.
    void setGhost(std::shared_ptr<const Snapshot> ghost);
    void clearGhost();
    std::shared_ptr<const Snapshot> ghost() const { return m_state.ghost; }
    static constexpr float kGhostAlpha = ViewRenderer::kGhostAlpha;

    void setDisplayMode(DisplayMode mode);
    DisplayMode displayMode() const { return m_state.mode; }

    /// Frames the whole model (all of its bounding box at the current poses, which
    /// holds its bounding sphere's content), keeping the view direction; the seat
    /// camera becomes an orbit camera.
    void fitAll();
    /// Names accepted by setCamera: "Iso", "Front", "Side", "Top", "Operator seat".
    static QStringList cameraNames();
    /// The translated label of a camera name, for menus.
    static QString cameraLabel(const QString& name);
    /// Switches to a named camera (orbit views frame the whole model). False for an
    /// unknown name.
    bool setCamera(const QString& name);
    /// The current named camera, or "" after the view was moved by hand.
    QString camera() const { return m_controller.name(); }
    const Camera& cameraState() const { return m_state.camera; }
    /// Puts the camera where `camera` says (a demonstration's recorded camera); the view
    /// then has no name, as after a move by hand.
    void setCameraState(const Camera& camera);

    /// The operator seat: eye [m, world] and view direction (yaw: 0 = +y, positive turns
    /// right; pitch: positive up) [rad]. Kept across models until resetOperatorSeat().
    void setOperatorSeat(const Eigen::Vector3d& eye, double yawRad, double pitchRad);
    /// Back to the default seat: behind and above the model's base, looking along +y.
    void resetOperatorSeat();
    /// Turns the seat camera's view by `radians` (positive right), for side screens.
    void setYawOffset(double radians);
    double yawOffset() const { return m_state.camera.yawOffset; }
    /// Horizontal field of view of the seat camera [rad] (default 60°).
    void setSeatFieldOfView(double radians);

    void setShowFrames(bool show);
    bool showFrames() const { return m_state.showFrames; }
    /// CONTACT: the contact points of the snapshot shown (a disc on each point, across its
    /// normal) with their forces as arrows (length in proportion to the machine's weight).
    void setShowContacts(bool show);
    bool showContacts() const { return m_state.showContacts; }
    void setShowGrid(bool show);
    bool showGrid() const { return m_state.showGrid; }
    /// Highlights a body and a joint (tree indices; −1 none), e.g. the model tree's selection.
    void setHighlight(int body, int joint);
    int highlightedBody() const { return m_state.highlightBody; }
    int highlightedJoint() const { return m_state.highlightJoint; }

    /// Median time to draw a frame over the last 31 frames [ms] (0 before the first).
    double frameMillis() const { return m_renderer.frameMillis(); }

    /// Draws a frame now and shows it (swapBuffers) before returning, when the view is
    /// on screen; else it is drawn when it shows.
    void renderNow();
    /// A frame drawn now, offscreen, at the view's size: the 3D view alone (without
    /// the overlays). A null image when OpenGL 3.3 is not available.
    QImage grabFramebuffer();
    /// The view's OpenGL context (nullptr before the view first drew or was made current).
    QOpenGLContext* context() const;
    /// Makes the view's context current (on its window, or offscreen before it has one);
    /// false when there is no OpenGL 3.3.
    bool makeCurrent();
    void doneCurrent();

    /// A widget shown over the view (a sibling or a child of an ancestor, e.g. a HUD
    /// label): the view's native window would hide it, so the view draws it into its
    /// frames, where it lies, whenever it is visible, and again when it repaints.
    /// Its on-screen geometry stays Qt's (layouts, tests and grab() see it as before).
    void addOverlay(QWidget* widget) { m_overlays.add(widget); }
    void removeOverlay(QWidget* widget) { m_overlays.remove(widget); }

    /// The body and its point under pixel (x, y) of the view (Camera::rayThrough and
    /// pickBody, the shapes as the display mode draws them): false when none is there.
    bool pick(const QPointF& pixel, int& body, Eigen::Vector3d& point) const;
    /// The body being pushed with Ctrl + drag (tree index), −1 when none.
    int pushedBody() const { return m_state.pushBody; }
    /// The grabbed point, in the pushed body's frame [m].
    const Eigen::Vector3d& pushPoint() const { return m_state.pushPoint; }
    /// Where the drag pulls it, world [m].
    const Eigen::Vector3d& pushTarget() const { return m_state.pushTarget; }

signals:
    /// Ctrl + drag: body `body`'s point `localPoint` (its frame) is pulled toward the
    /// world point `target` (on the press and at every move of the drag).
    void pushMoved(int body, const Eigen::Vector3d& localPoint, const Eigen::Vector3d& target);
    /// The Ctrl + drag ended (the button released, or a new model).
    void pushReleased();
    /// Something in the model cannot be drawn as written (a mesh file missing or
    /// unreadable). Emitted once per bundle and message.
    void problem(const QString& message);
    /// After every frame: the time it took to draw [ms].
    void frameTimed(double ms);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    /// Schedules a frame on the native window (drawn at its next update request).
    void requestFrame();
    /// With a new context current: the renderer's GL objects, the named camera kept framed.
    void initializeGl();
    /// Draws a frame into the bound framebuffer of w × h device pixels.
    void drawFrame(int w, int h, bool overlays);
    /// The renderer's GL objects released (in its context).
    void releaseGl();
    /// Says (problem()) that the view cannot draw, the first time only.
    void glProblem(ViewRenderer::Problem problem, const QString& log);
    /// What the controller's change asks of the view: a frame, and the push's signals.
    void follow(CameraController::Change change);

    ViewState m_state;
    ViewRenderer m_renderer;
    OverlayCompositor m_overlays;
    CameraController m_controller;
    ViewWindow* m_window = nullptr;  ///< owned by m_container
    QWidget* m_container = nullptr;  ///< createWindowContainer(m_window), a child
    bool m_glFailed = false;         ///< problem() said that the view cannot draw
};

}  // namespace studio
