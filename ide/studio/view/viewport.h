#pragma once
// Viewport: the 3D view of a model (OpenGL 3.3 core profile; runs on Mesa llvmpipe).
//
// It draws the bundle's bodies at the poses it is given (by tree index; before any,
// at the model's initial state), in one of three display modes:
//  - Schematic: PADROB's generic mode (thesis §2.3): purple bars for bodies, green
//    cylinders for revolute joints, grey rails and sliders for prismatic joints,
//    T 1 actuators as a cylinder between CL1 and CL2 (see scene_geometry.h);
//  - Dressed: the G graphics in their COLOR (bodies without any are drawn as bars);
//  - Both: dressed, with the schematic drawn over it.
// Plus a ground grid (1 m cells, every 10 m brighter), the world axes (x red, y green,
// z blue), the bodies' frames on demand, and a highlighted body and joint.
//
// A scene (setScene: the ground graphics of another model file, e.g. the SAG mill the
// liner manipulator works in) is drawn around the model, dressed in every display mode,
// never highlighted and never framed by Fit All. With a scene the ground grid is not
// drawn (the scene has its floor), the daylight is dimmed to an interior's and the
// scene's lamps light the model and the scene; the scene is cut away between the eye
// and the model (a plane across the view through the model's box corner nearest the
// eye; for the seat, across its heading), so an orbit camera outside the mill's shell
// looks into it and the seat's screens see past the wall behind the machine.
//
// Geometry is built once per bundle (shared between viewports) and uploaded once per
// GL context; a frame only sets one model matrix per body. Made for a software
// renderer (Mesa llvmpipe), whose cost is per fragment: the solids are drawn twice,
// depth alone and then colour where nearest (each pixel shaded once), and the shader
// is built per number of lamps (its loop over them unrolled).
//
// It is a QWidget holding a native window (QWidget::createWindowContainer) that does
// the GL work: a frame goes from its own OpenGL context straight to swapBuffers, not
// through Qt's widget composition (on llvmpipe under X, composing a QOpenGLWidget into
// its window and flushing it took longer than drawing the mill). So that widgets over
// the view still show, they are drawn into the frame (addOverlay); grabFramebuffer()
// draws a frame offscreen, and QWidget::grab()/render() of the window show it.
//
// Mouse: left drag orbits, middle drag or Shift + left drag pans, the wheel zooms
// towards the cursor, a double click frames the whole model. Ctrl + left drag on a body
// pushes it (as MuJoCo's `simulate` perturbs one): the press picks the body and its
// point under the cursor (pickBody), the drag moves the target — the cursor's point in
// the plane through the grabbed point facing the camera — and pushMoved() says where,
// the release ends it (pushReleased()); meanwhile a red line joins the grabbed point
// (as the body moves) to the target. Ctrl + drag off the bodies does nothing. Only a
// view whose pushMoved() is connected pushes (the Model workspace's screens, wired to
// the simulation); in the others Ctrl + drag orbits as a plain drag. Cameras: orbit views
// "Iso", "Front" (from −y), "Side" (from +x), "Top", and "Operator seat" (a fixed
// eye, see setOperatorSeat); dragging in the seat view turns it into an orbit view.

#include "ide/studio/model/model_bundle.h"
#include "ide/studio/sim/snapshot.h"
#include "ide/studio/view/camera.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QElapsedTimer>
#include <QHash>
#include <QImage>
#include <QList>
#include <QOpenGLFunctions_3_3_Core>
#include <QPoint>
#include <QPointF>
#include <QPointer>
#include <QSurfaceFormat>
#include <QTimer>
#include <QWidget>

#include <array>
#include <memory>
#include <vector>

class QOffscreenSurface;
class QOpenGLBuffer;
class QOpenGLContext;
class QOpenGLShaderProgram;
class QOpenGLVertexArrayObject;

namespace studio {

class MeshBuilder;
struct SceneGeometry;
struct SceneDressing;
struct DrawRange;
struct CullPart;

enum class DisplayMode { Schematic, Dressed, Both };

class Viewport : public QWidget, protected QOpenGLFunctions_3_3_Core {
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
    enum class Lighting { Automatic, PerPixel, PerVertex };
    static void setLighting(Lighting lighting);
    static Lighting lighting();
    /// "auto", "pixel", "vertex" (for command lines and settings), and back; false for
    /// another word.
    static QString lightingName(Lighting lighting);
    static bool lightingFromName(const QString& name, Lighting& lighting);
    /// This viewport lights at the vertices (lighting() resolved against its OpenGL,
    /// known once it has drawn).
    bool lightsPerVertex() const;
    /// Its OpenGL's renderer (GL_RENDERER), once it has drawn ("" before).
    QString renderer() const { return m_renderer; }

    /// The model to draw (nullptr: an empty scene). Builds its meshes (once per bundle)
    /// and draws it at its initial pose until setPoses; frames the camera on a new
    /// model. Meshes that cannot be drawn are reported through problem(), once.
    void setBundle(std::shared_ptr<const ModelBundle> bundle);
    std::shared_ptr<const ModelBundle> bundle() const { return m_bundle; }
    /// The scene drawn around the model (scene_file.h; its ground graphics only), or
    /// nullptr for none. Its meshes that cannot be drawn are reported through problem().
    void setScene(std::shared_ptr<const ModelBundle> scene);
    std::shared_ptr<const ModelBundle> scene() const { return m_scene; }

    /// Body poses X_wb by tree index (size Model::nb; other sizes are ignored).
    void setPoses(const std::vector<Eigen::Isometry3d>& X_wb);
    const std::vector<Eigen::Isometry3d>& poses() const { return m_poses; }
    /// The snapshot's poses (and its bundle, when it is another one).
    void setSnapshot(std::shared_ptr<const Snapshot> snapshot);

    /// A ghost: a second machine of the same bundle at the snapshot's poses, drawn
    /// translucent (kGhostAlpha, tinted, without depth writes) over the scene, e.g.
    /// the expert's run beside the operator's. A snapshot of another bundle (or other
    /// body count) is not drawn. clearGhost() removes it.
    void setGhost(std::shared_ptr<const Snapshot> ghost);
    void clearGhost();
    std::shared_ptr<const Snapshot> ghost() const { return m_ghost; }
    static constexpr float kGhostAlpha = 0.35f;

    void setDisplayMode(DisplayMode mode);
    DisplayMode displayMode() const { return m_mode; }

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
    QString camera() const { return m_cameraName; }
    const Camera& cameraState() const { return m_camera; }
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
    double yawOffset() const { return m_camera.yawOffset; }
    /// Horizontal field of view of the seat camera [rad] (default 60°).
    void setSeatFieldOfView(double radians);

    void setShowFrames(bool show);
    bool showFrames() const { return m_showFrames; }
    /// CONTACT: the contact points of the snapshot shown (a disc on each point, across its
    /// normal) with their forces as arrows (length in proportion to the machine's weight).
    void setShowContacts(bool show);
    bool showContacts() const { return m_showContacts; }
    void setShowGrid(bool show);
    bool showGrid() const { return m_showGrid; }
    /// Highlights a body and a joint (tree indices; −1 none), e.g. the model tree's selection.
    void setHighlight(int body, int joint);
    int highlightedBody() const { return m_highlightBody; }
    int highlightedJoint() const { return m_highlightJoint; }

    /// Median time to draw a frame over the last 31 frames [ms] (0 before the first).
    double frameMillis() const;

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
    void addOverlay(QWidget* widget);
    void removeOverlay(QWidget* widget);

    /// The body and its point under pixel (x, y) of the view (Camera::rayThrough and
    /// pickBody, the shapes as the display mode draws them): false when none is there.
    bool pick(const QPointF& pixel, int& body, Eigen::Vector3d& point) const;
    /// The body being pushed with Ctrl + drag (tree index), −1 when none.
    int pushedBody() const { return m_pushBody; }
    /// The grabbed point, in the pushed body's frame [m].
    const Eigen::Vector3d& pushPoint() const { return m_pushPoint; }
    /// Where the drag pulls it, world [m].
    const Eigen::Vector3d& pushTarget() const { return m_pushTarget; }

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
    void initializeGL();
    void resizeGL(int w, int h);
    void paintGL();
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    class Surface;
    friend class Surface;
    /// Schedules a frame on the native window (drawn at its next update request).
    void requestFrame();
    /// The context current (creating it and the GL objects the first time); false
    /// when there is no OpenGL 3.3.
    bool prepareGl();
    /// Draws a frame into the bound framebuffer of w × h device pixels.
    void drawFrame(int w, int h, bool overlays);
    void drawOverlays(int w, int h);
    void watchOverlay(QWidget* widget, bool watch);

    /// One mesh's GL objects (the model's, the scene's).
    struct GlMesh {
        std::unique_ptr<QOpenGLVertexArrayObject> vao;
        std::unique_ptr<QOpenGLBuffer> vertices;
        std::unique_ptr<QOpenGLBuffer> indices;
        bool uploaded = false;
    };
    void releaseGl();
    void createMesh(GlMesh& mesh);
    void upload(GlMesh& gl, const MeshBuilder& mesh);
    void drawSolids(bool schematic);
    void drawScene();
    void setLights(int lamps);
    int lampCount() const;
    void drawRange(const DrawRange& range, const Eigen::Matrix4f& model, unsigned mode = 0x0004 /*GL_TRIANGLES*/);
    void drawSlots(bool schematic, bool dressed);
    /// Draws `parts` (consecutive ranges of `mesh`) with `model`, culling the back faces
    /// of the closed solids that the near plane and `cut` (a world plane, kept where
    /// n·x + d ≥ 0; nullptr for none) do not cut open, and not drawing those it cuts
    /// away. Whether they are cut is found from their boxes, and for the boxes that the
    /// near plane's rectangle or the cut meets, from their triangles (solidClearOf,
    /// planeSide): a mill's shell around the eye, its head and floor are culled.
    void drawParts(const MeshBuilder& mesh, const std::vector<CullPart>& parts, const Eigen::Matrix4f& model,
                   const Eigen::Vector4d* cut);
    void drawActuators(int onlyJoint);
    void setTint(const Eigen::Vector3f& rgb, float amount);
    void setAlpha(float alpha);
    Eigen::Isometry3d bodyPose(int body) const;
    void sceneSphere(Eigen::Vector3d& centre, double& radius) const;
    Eigen::AlignedBox3d sceneBox() const;
    void applyNamedCamera();
    void leaveNamedCamera();
    double aspect() const;

    std::shared_ptr<const ModelBundle> m_bundle;
    std::shared_ptr<const SceneGeometry> m_geometry;
    std::shared_ptr<const ModelBundle> m_scene;
    std::shared_ptr<const SceneDressing> m_dressing;
    std::vector<Eigen::Isometry3d> m_poses;
    std::shared_ptr<const Snapshot> m_ghost;
    DisplayMode m_mode = DisplayMode::Dressed;
    Camera m_camera;
    QString m_cameraName = QStringLiteral("Iso");
    bool m_seatSet = false;  ///< setOperatorSeat was called (else the model's default)
    bool m_showFrames = false;
    bool m_showContacts = false;
    std::shared_ptr<const Snapshot> m_contactsOf;  // the snapshot whose contacts are drawn
    void drawContacts();
    bool m_showGrid = true;
    int m_highlightBody = -1;
    int m_highlightJoint = -1;

    // GL (per context)
    bool m_glReady = false;
    bool m_glFailed = false;
    /// The scene's lamps that light it: at most this many (viewport.frag's uLightEye).
    static constexpr int kMaxLamps = 4;
    /// viewport.frag/.vert built for one number of lamps (LAMP_COUNT: its loop over them
    /// unrolled, which llvmpipe runs far faster than a loop over a uniform count), and
    /// its uniforms' locations.
    struct Program {
        std::unique_ptr<QOpenGLShaderProgram> program;
        struct Uniforms {
            int model = -1, view = -1, projection = -1, normalMatrix = -1, lit = -1, tint = -1, alpha = -1,
                upEye = -1, fadeCentre = -1, fadeRadius = -1, clipPlane = -1, daylight = -1, lightEye = -1,
                lightColor = -1, lightRange = -1;
        } u;
    };
    /// Builds `program` for `lamps` lamps, lit at every pixel or at the vertices (false,
    /// and problem(), when it does not build).
    bool buildProgram(Program& program, int lamps, bool perVertex);
    /// The program for this many lamps, built when first needed (nullptr when it does
    /// not build).
    Program* program(int lamps, bool perVertex);
    /// Binds `p` and sets this frame's uniforms in it (camera, lamps, no tint, opaque).
    void useProgram(Program& p);
    std::array<Program, kMaxLamps + 1> m_programs;        ///< lit at every pixel, by lamp count
    std::array<Program, kMaxLamps + 1> m_vertexPrograms;  ///< lit at the vertices, by lamp count
    QString m_renderer;       ///< GL_RENDERER
    bool m_softwareGl = false;  ///< m_renderer is a software rasteriser
    Eigen::Matrix4f m_projection = Eigen::Matrix4f::Identity();  ///< this frame's
    int m_lamps = 0;                                             ///< this frame's
    Program* m_program = nullptr;                   ///< this frame's
    Program::Uniforms m_u;                          ///< m_program's uniforms
    std::unique_ptr<QOpenGLShaderProgram> m_background;
    int m_backgroundBottom = -1, m_backgroundTop = -1;  ///< its uniforms' locations
    GlMesh m_modelMesh;
    GlMesh m_sceneMesh;
    Eigen::Matrix4f m_view = Eigen::Matrix4f::Identity();
    double m_near = 0;                  ///< this frame's near plane distance [m]
    std::array<Eigen::Vector3d, 4> m_nearQuad;  ///< this frame's near plane's visible rectangle (world)
    std::vector<signed char> m_partModes;  ///< drawParts' scratch
    std::vector<Eigen::Matrix4f> m_slotMatrices;  ///< per slot, this frame

    // the native window and its context
    Surface* m_surface = nullptr;        ///< owned by m_container
    QWidget* m_container = nullptr;      ///< createWindowContainer(m_surface), a child
    std::unique_ptr<QOpenGLContext> m_context;
    std::unique_ptr<QOffscreenSurface> m_offscreen;  ///< before m_surface has a native window
    bool m_glInitialized = false;        ///< initializeGL ran in m_context

    // overlays: widgets drawn into the frames, and their last images
    QList<QPointer<QWidget>> m_overlays;
    QHash<QWidget*, QImage> m_overlayImages;
    bool m_overlaysDirty = true;
    bool m_renderingOverlays = false;

    // interaction
    QPoint m_lastMouse;
    bool m_dragging = false;
    // the push (Ctrl + drag): the body, its grabbed point (body frame), the target, and
    // the plane the target moves in (through the grabbed point as picked, facing the camera)
    int m_pushBody = -1;
    Eigen::Vector3d m_pushPoint = Eigen::Vector3d::Zero();
    Eigen::Vector3d m_pushTarget = Eigen::Vector3d::Zero();
    Eigen::Vector3d m_pushPlane = Eigen::Vector3d::Zero();
    void endPush();
    void drawPush();

    // frames: drawn when asked for (requestFrame), at most one per kMinFramePeriodMs
    static constexpr qint64 kMinFramePeriodMs = 15;
    QTimer m_frameTimer;         ///< single shot: the next frame asked for
    QElapsedTimer m_frameClock;  ///< since the last frame on screen began

    // timing
    std::array<double, 31> m_frameTimes{};
    int m_frameCount = 0;
};

}  // namespace studio
