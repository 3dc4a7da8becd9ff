#pragma once
// ViewRenderer: draws a ViewState into the bound framebuffer of the current OpenGL 3.3
// core context (a window's or an offscreen one); no widget, no window. A Viewport
// draws its frames on screen, its grabFramebuffer() and the frame bench through it.
//
// The display modes:
//  - Schematic: PADROB's generic mode (thesis §2.3): purple bars for bodies, green
//    cylinders for revolute joints, grey rails and sliders for prismatic joints,
//    T 1 actuators as a cylinder between CL1 and CL2 (see scene_geometry.h);
//  - Dressed: the G graphics in their COLOR (bodies without any are drawn as bars);
//  - Both: dressed, with the schematic drawn over it.
// Plus a ground grid (1 m cells, every 10 m brighter), the world axes (x red, y green,
// z blue), the bodies' frames on demand, a highlighted body and joint, a ghost (the
// same machine at other poses, translucent), contacts on demand, and the push's line.
//
// A scene (the ground graphics of another model file, e.g. the SAG mill the liner
// manipulator works in) is drawn around the model, dressed in every display mode, never
// highlighted. With a scene the ground grid is not drawn (the scene has its floor), the
// daylight is dimmed to an interior's and the scene's lamps light the model and the
// scene; the scene is cut away between the eye and the model (a plane across the view
// through the model's box corner nearest the eye; for the seat, across its heading), so
// an orbit camera outside the mill's shell looks into it and the seat's screens see past
// the wall behind the machine.
//
// Geometry is built once per bundle (shared between viewports) and uploaded once per
// GL context; a frame only sets one model matrix per body. Made for a software
// renderer (Mesa llvmpipe), whose cost is per fragment: the solids are drawn twice,
// depth alone and then colour where nearest (each pixel shaded once), and the shader
// is built per number of lamps (its loop over them unrolled).

#include "ide/studio/view/view_state.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QOpenGLFunctions_3_3_Core>
#include <QString>

#include <array>
#include <functional>
#include <memory>
#include <vector>

class QOpenGLBuffer;
class QOpenGLShaderProgram;
class QOpenGLVertexArrayObject;

namespace studio {

class MeshBuilder;
struct DrawRange;
struct CullPart;

/// Where the light is computed (Viewport::setLighting).
enum class Lighting { Automatic, PerPixel, PerVertex };

class ViewRenderer : protected QOpenGLFunctions_3_3_Core {
public:
    /// What cannot be drawn: no OpenGL 3.3 in the context, or shaders that do not build
    /// (with the compiler's log).
    enum class Problem { NoOpenGl, Shaders };
    /// `report` hears of every problem, when it happens (the viewport words it).
    explicit ViewRenderer(std::function<void(Problem problem, const QString& log)> report);
    ~ViewRenderer();
    ViewRenderer(const ViewRenderer&) = delete;
    ViewRenderer& operator=(const ViewRenderer&) = delete;

    /// Back-face culling of closed solids that nothing cuts open, for every renderer
    /// (Viewport::setBackFaceCulling).
    static void setBackFaceCulling(bool on);
    static bool backFaceCulling();
    /// Where every renderer computes the light, from its next frame (Viewport::setLighting).
    static void setLighting(Lighting lighting);
    static Lighting lighting();

    /// Sets up the GL objects in the current context (once per context, before its first
    /// frame): false, and a problem reported, when they cannot be.
    bool initialize();
    /// Whether GL objects are held (made by initialize(), not yet released).
    bool holdsGl() const;
    /// Releases the GL objects (the context they were made in current).
    void release();
    /// The model's geometry (ViewState::geometry) or the scene's dressing changed: it is
    /// uploaded again before the next frame.
    void modelChanged() { m_modelMesh.uploaded = false; }
    void sceneChanged() { m_sceneMesh.uploaded = false; }

    /// Lights at the vertices (lighting() resolved against its OpenGL, known once
    /// initialize() ran).
    bool lightsPerVertex() const;
    /// The OpenGL's renderer (GL_RENDERER), once initialize() ran ("" before).
    QString glRenderer() const { return m_renderer; }

    /// Draws `view` into the bound framebuffer of w × h device pixels, for a view of
    /// this `aspect` (width / height). The time it took [ms] (until the GL finished),
    /// or −1 when nothing was drawn (initialize() failed, or a program did not build).
    double draw(const ViewState& view, int w, int h, double aspect);
    /// Median time to draw a frame over the last 31 frames [ms] (0 before the first).
    double frameMillis() const;

    static constexpr float kGhostAlpha = 0.35f;

private:
    /// One mesh's GL objects (the model's, the scene's).
    struct GlMesh {
        std::unique_ptr<QOpenGLVertexArrayObject> vao;
        std::unique_ptr<QOpenGLBuffer> vertices;
        std::unique_ptr<QOpenGLBuffer> indices;
        bool uploaded = false;
    };
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
    void drawContacts();
    void drawPush();
    void setTint(const Eigen::Vector3f& rgb, float amount);
    void setAlpha(float alpha);

    std::function<void(Problem, const QString&)> m_report;
    const ViewState* m_state = nullptr;  ///< this frame's (during draw())

    bool m_glReady = false;
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
    /// and a problem reported, when it does not build).
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

    // timing
    std::array<double, 31> m_frameTimes{};
    int m_frameCount = 0;
};

}  // namespace studio
