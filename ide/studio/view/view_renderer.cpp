#include "ide/studio/view/view_renderer.h"

#include "ide/studio/view/scene_geometry.h"

#include <QElapsedTimer>
#include <QFile>
#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QVector3D>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace studio {

using Eigen::Isometry3d;
using Eigen::Matrix4f;
using Eigen::Vector3d;
using Eigen::Vector3f;

namespace {

const Vector3f kHighlight(1.0f, 0.86f, 0.10f);
const Vector3f kContactPoint(0.95f, 0.15f, 0.10f);  // contacts: red discs,
const Vector3f kContactForce(1.0f, 0.55f, 0.05f);   // orange force arrows
const Vector3f kRodSilver(0.82f, 0.83f, 0.86f);
const Vector3f kPushRed(0.95f, 0.15f, 0.12f);  // the push's line (Ctrl + drag)
constexpr float kOverlayAlpha = 0.6f;
const Eigen::Vector3f kGhostTint(0.55f, 0.8f, 1.0f);  // the ghost: a pale blue

// lighting inside a scene (an interior): the daylight dimmed, the scene's lamps lit
constexpr float kInteriorDaylight = 0.45f;
const Vector3f kLampLight(1.0f, 0.90f, 0.72f);  // warm white
constexpr float kLampRange = 4.0f;          // [m]: a lamp lights half as much this far away

bool g_cullFaces = true;  // ViewRenderer::setBackFaceCulling
std::atomic<Lighting> g_lighting{Lighting::Automatic};  // ViewRenderer::setLighting

Matrix4f scaled(const Isometry3d& pose, const Vector3d& scale)
{
    Eigen::Affine3d a(pose);
    a.scale(scale);
    return a.matrix().cast<float>();
}

}  // namespace

ViewRenderer::ViewRenderer(std::function<void(Problem, const QString&)> report) : m_report(std::move(report)) {}

ViewRenderer::~ViewRenderer() = default;

void ViewRenderer::setBackFaceCulling(bool on)
{
    g_cullFaces = on;
}

bool ViewRenderer::backFaceCulling()
{
    return g_cullFaces;
}

void ViewRenderer::setLighting(Lighting lighting)
{
    g_lighting = lighting;
}

Lighting ViewRenderer::lighting()
{
    return g_lighting;
}

bool ViewRenderer::lightsPerVertex() const
{
    const Lighting l = g_lighting;
    return l == Lighting::PerVertex || (l == Lighting::Automatic && m_softwareGl);
}

// ---- GL objects ------------------------------------------------------------------------

bool ViewRenderer::initialize()
{
    m_glReady = false;
    m_modelMesh.uploaded = false;
    m_sceneMesh.uploaded = false;
    if (!initializeOpenGLFunctions()) {
        m_report(Problem::NoOpenGl, {});
        return false;
    }
    // a software rasteriser (Mesa's llvmpipe, softpipe; the classic swrast) lights at the
    // vertices when the lighting is Automatic
    m_renderer = QString::fromLatin1(reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
    m_softwareGl = m_renderer.contains(QLatin1String("llvmpipe"), Qt::CaseInsensitive) ||
                   m_renderer.contains(QLatin1String("softpipe"), Qt::CaseInsensitive) ||
                   m_renderer.contains(QLatin1String("software rasterizer"), Qt::CaseInsensitive) ||
                   m_renderer.contains(QLatin1String("swrast"), Qt::CaseInsensitive);
    // the background, and the solids' program without lamps (the others when a scene needs them)
    m_background = std::make_unique<QOpenGLShaderProgram>();
    const bool background =
        m_background->addShaderFromSourceFile(QOpenGLShader::Vertex,
                                              QStringLiteral(":/studio/shaders/background.vert")) &&
        m_background->addShaderFromSourceFile(QOpenGLShader::Fragment,
                                              QStringLiteral(":/studio/shaders/background.frag")) &&
        m_background->link();
    if (!background) {
        m_report(Problem::Shaders, m_background->log());
        return false;
    }
    m_backgroundBottom = m_background->uniformLocation("uBottom");
    m_backgroundTop = m_background->uniformLocation("uTop");
    if (!buildProgram(m_programs[0], 0, false)) return false;
    createMesh(m_modelMesh);
    createMesh(m_sceneMesh);
    m_glReady = true;
    return true;
}

bool ViewRenderer::buildProgram(Program& p, int lamps, bool perVertex)
{
    auto read = [](const QString& name) {
        QFile file(QStringLiteral(":/studio/shaders/") + name);
        return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    };
    // lighting.glsl, with LAMP_COUNT defined, after the #version line of the stage that
    // lights: the fragment shader, or the vertex shader
    const QByteArray lighting = "#define LAMP_COUNT " + QByteArray::number(lamps) + '\n' + read("lighting.glsl");
    QByteArray vertex = read(perVertex ? "viewport_vertex.vert" : "viewport.vert");
    QByteArray fragment = read(perVertex ? "viewport_vertex.frag" : "viewport.frag");
    QByteArray& lit = perVertex ? vertex : fragment;
    const qsizetype eol = lit.indexOf('\n');
    lit.insert(eol < 0 ? 0 : eol + 1, lighting);
    p.program = std::make_unique<QOpenGLShaderProgram>();
    const bool ok = p.program->addShaderFromSourceCode(QOpenGLShader::Vertex, vertex) &&
                    p.program->addShaderFromSourceCode(QOpenGLShader::Fragment, fragment) && p.program->link();
    if (!ok) {
        m_report(Problem::Shaders, p.program->log());
        p.program.reset();
        return false;
    }
    QOpenGLShaderProgram& g = *p.program;
    p.u.model = g.uniformLocation("uModel");
    p.u.view = g.uniformLocation("uView");
    p.u.projection = g.uniformLocation("uProjection");
    p.u.normalMatrix = g.uniformLocation("uNormalMatrix");
    p.u.lit = g.uniformLocation("uLit");
    p.u.tint = g.uniformLocation("uTint");
    p.u.alpha = g.uniformLocation("uAlpha");
    p.u.upEye = g.uniformLocation("uUpEye");
    p.u.fadeCentre = g.uniformLocation("uFadeCentre");
    p.u.fadeRadius = g.uniformLocation("uFadeRadius");
    p.u.clipPlane = g.uniformLocation("uClipPlane");
    p.u.daylight = g.uniformLocation("uDaylight");
    p.u.lightEye = g.uniformLocation("uLightEye");
    p.u.lightColor = g.uniformLocation("uLightColor");
    p.u.lightRange = g.uniformLocation("uLightRange");
    return true;
}

void ViewRenderer::createMesh(GlMesh& mesh)
{
    mesh.vao = std::make_unique<QOpenGLVertexArrayObject>();
    mesh.vao->create();
    mesh.vertices = std::make_unique<QOpenGLBuffer>(QOpenGLBuffer::VertexBuffer);
    mesh.vertices->create();
    mesh.indices = std::make_unique<QOpenGLBuffer>(QOpenGLBuffer::IndexBuffer);
    mesh.indices->create();
    mesh.uploaded = false;
}

bool ViewRenderer::holdsGl() const
{
    return m_background || m_modelMesh.vao;
}

void ViewRenderer::release()
{
    for (GlMesh* mesh : {&m_modelMesh, &m_sceneMesh}) {
        mesh->indices.reset();
        mesh->vertices.reset();
        mesh->vao.reset();
        mesh->uploaded = false;
    }
    for (Program& p : m_programs) p.program.reset();
    for (Program& p : m_vertexPrograms) p.program.reset();
    m_program = nullptr;
    m_background.reset();
    m_glReady = false;
}

void ViewRenderer::upload(GlMesh& gl, const MeshBuilder& mesh)
{
    gl.vao->bind();
    gl.vertices->bind();
    gl.vertices->allocate(mesh.vertices.data(), static_cast<int>(mesh.vertices.size() * sizeof(MeshVertex)));
    gl.indices->bind();  // part of the VAO's state
    gl.indices->allocate(mesh.indices.data(), static_cast<int>(mesh.indices.size() * sizeof(std::uint32_t)));
    const auto stride = static_cast<GLsizei>(sizeof(MeshVertex));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(MeshVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(MeshVertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(MeshVertex, color)));
    gl.vao->release();
    gl.uploaded = true;
}


// ---- a frame ----------------------------------------------------------------------------

void ViewRenderer::setTint(const Vector3f& rgb, float amount)
{
    glUniform4f(m_u.tint, rgb.x(), rgb.y(), rgb.z(), amount);
}

void ViewRenderer::setAlpha(float alpha)
{
    glUniform1f(m_u.alpha, alpha);
}

void ViewRenderer::drawRange(const DrawRange& range, const Matrix4f& model, unsigned mode)
{
    if (range.empty()) return;
    const Eigen::Matrix3f normal = (m_view * model).topLeftCorner<3, 3>().inverse().transpose();
    glUniformMatrix4fv(m_u.model, 1, GL_FALSE, model.data());
    glUniformMatrix3fv(m_u.normalMatrix, 1, GL_FALSE, normal.data());
    glDrawElements(mode, static_cast<GLsizei>(range.count), GL_UNSIGNED_INT,
                   reinterpret_cast<void*>(static_cast<std::uintptr_t>(range.first) * sizeof(std::uint32_t)));
}

void ViewRenderer::drawSlots(bool schematic, bool dressed)
{
    const SceneGeometry& g = *m_state->geometry;
    for (int s = 0; s < g.slotCount(); ++s) {
        const auto k = static_cast<std::size_t>(s);
        const bool lit = s > 0 && s - 1 == m_state->highlightBody;
        if (lit) setTint(kHighlight, 0.85f);
        if (dressed) {
            if (g.dressed[k].empty()) drawRange(g.bars[k], m_slotMatrices[k]);
            else drawParts(g.mesh, g.dressedParts[k], m_slotMatrices[k], nullptr);
        }
        if (schematic) drawRange(g.schematic[k], m_slotMatrices[k]);
        if (lit) setTint(Vector3f::Zero(), 0.0f);
    }
}

void ViewRenderer::drawParts(const MeshBuilder& mesh, const std::vector<CullPart>& parts, const Matrix4f& model,
                             const Eigen::Vector4d* cut)
{
    // per part: 0 both sides drawn, +1 / −1 back / front faces culled, 2 not drawn
    const Eigen::Matrix4d world = model.cast<double>();
    // the near plane's visible rectangle and the cut, in the parts' frame
    const Eigen::Matrix4d toPart = world.inverse();
    std::array<Vector3d, 4> quad;
    for (std::size_t c = 0; c < 4; ++c) quad[c] = (toPart * m_nearQuad[c].homogeneous()).head<3>();
    const Eigen::Vector4d plane = cut ? Eigen::Vector4d(world.transpose() * *cut) : Eigen::Vector4d::Zero();
    m_partModes.resize(parts.size());
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const CullPart& p = parts[k];
        signed char mode = 0;
        if (g_cullFaces && (p.winding != 0 || cut)) {
            int side = 1;  // +1 whole, −1 all cut away, 0 cut open (its inside shows)
            if (cut) {
                int kept = 0;
                for (int c = 0; c < 8; ++c) {
                    const Vector3d x = p.box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
                    if (plane.head<3>().dot(x) + plane.w() >= -1e-6) ++kept;
                }
                side = kept == 8 ? 1 : kept == 0 ? -1 : planeSide(mesh, p, plane);
            }
            if (side < 0) mode = 2;  // it would draw nothing
            else if (side > 0 && p.winding != 0 && solidClearOf(mesh, p, quad, 0.25 * m_near + 1e-4)) {
                mode = static_cast<signed char>(p.winding);
            }
        }
        m_partModes[k] = mode;
    }
    // consecutive parts of the same mode in one call
    for (std::size_t k = 0; k < parts.size();) {
        const signed char mode = m_partModes[k];
        DrawRange run = parts[k].range;
        std::size_t next = k + 1;
        while (next < parts.size() && m_partModes[next] == mode && parts[next].range.first == run.first + run.count) {
            run.count += parts[next].range.count;
            ++next;
        }
        k = next;
        if (mode == 2) continue;
        if (mode != 0) {
            glEnable(GL_CULL_FACE);
            glCullFace(mode > 0 ? GL_BACK : GL_FRONT);  // +1: counter-clockwise seen from outside
        }
        drawRange(run, model);
        if (mode != 0) glDisable(GL_CULL_FACE);
    }
}

void ViewRenderer::drawActuators(int onlyJoint)
{
    const SceneGeometry& g = *m_state->geometry;
    const double w = g.schematicWidth;
    for (const ActuatorLine& a : g.actuators) {
        if (onlyJoint >= 0 && a.joint != onlyJoint) continue;
        const Vector3d p1 = m_state->bodyPose(a.body1) * a.cl1;
        const Vector3d p2 = m_state->bodyPose(a.body2) * a.cl2;
        const double len = (p2 - p1).norm();
        if (!(len > 1e-9)) continue;
        const Isometry3d frame(frameAlong(p1, p2).matrix());
        // the barrel from CL1, the rod all the way to CL2
        if (onlyJoint < 0) setTint(Vector3f::Zero(), 0.0f);
        drawRange(g.unitCylinder, scaled(frame, Vector3d(0.55 * w, 0.55 * w, 0.55 * len)));
        if (onlyJoint < 0) setTint(kRodSilver, 1.0f);
        drawRange(g.unitCylinder, scaled(frame, Vector3d(0.28 * w, 0.28 * w, len)));
    }
    if (onlyJoint < 0) setTint(Vector3f::Zero(), 0.0f);
}

void ViewRenderer::drawContacts()
{
    if (!m_state->contactsOf || m_state->contactsOf->contacts.empty()) return;
    const SceneGeometry& g = *m_state->geometry;
    const double w = g.schematicWidth;
    // an arrow half as long as the machine's size for a force of its whole weight
    double weight = 0;
    if (m_state->bundle && m_state->bundle->model) {
        for (double m : m_state->bundle->model->mass) weight += m * m_state->bundle->model->gravity.norm();
    }
    const double size = w / 0.04;  // the machine's size (scene_geometry.cpp: w = 0.04 of it)
    const double perNewton = weight > 0 ? 0.5 * size / weight : 0.0;
    glClear(GL_DEPTH_BUFFER_BIT);
    for (const ContactSnapshot& c : m_state->contactsOf->contacts) {
        setTint(kContactPoint, 1.0f);
        const Vector3d n = c.normal.normalized();
        drawRange(g.unitCylinder,
                  scaled(Isometry3d(frameAlong(c.point - 0.3 * w * n, c.point + 0.3 * w * n).matrix()),
                         Vector3d(2.5 * w, 2.5 * w, 0.6 * w)));
        const double len = std::min(c.force.norm() * perNewton, 2.0 * size);
        if (!(len > 0.5 * w)) continue;
        setTint(kContactForce, 1.0f);
        const Vector3d end = c.point + len * c.force.normalized();
        drawRange(g.unitCylinder, scaled(Isometry3d(frameAlong(c.point, end).matrix()), Vector3d(0.5 * w, 0.5 * w, len)));
        // the head: a short fat cylinder at the tip
        const Vector3d dir = c.force.normalized();
        drawRange(g.unitCylinder, scaled(Isometry3d(frameAlong(end, end + 3 * w * dir).matrix()),
                                         Vector3d(1.4 * w, 1.4 * w, 3 * w)));
    }
    setTint(Vector3f::Zero(), 0.0f);
}

void ViewRenderer::drawPush()
{
    if (m_state->pushBody < 0 || m_state->pushBody >= static_cast<int>(m_state->poses.size())) return;
    // a red line from the grabbed point to the target, over everything, a dot at each end
    const Vector3d p1 = m_state->bodyPose(m_state->pushBody) * m_state->pushPoint;
    const double w = m_state->geometry->schematicWidth;
    glClear(GL_DEPTH_BUFFER_BIT);
    setTint(kPushRed, 1.0f);
    const double len = (m_state->pushTarget - p1).norm();
    if (len > 1e-9)
        drawRange(m_state->geometry->unitCylinder,
                  scaled(Isometry3d(frameAlong(p1, m_state->pushTarget).matrix()), Vector3d(0.2 * w, 0.2 * w, len)));
    for (const Vector3d& end : {p1, m_state->pushTarget}) {
        const Vector3d a = end - Vector3d(0, 0, 0.5 * w);
        drawRange(m_state->geometry->unitCylinder,
                  scaled(Isometry3d(frameAlong(a, a + Vector3d(0, 0, w)).matrix()), Vector3d(0.6 * w, 0.6 * w, w)));
    }
    setTint(Vector3f::Zero(), 0.0f);
}

double ViewRenderer::draw(const ViewState& view, int w, int h, double aspect)
{
    glViewport(0, 0, w, h);
    QElapsedTimer timer;
    timer.start();
    glClearColor(0.2f, 0.21f, 0.23f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!m_glReady) return -1;
    m_state = &view;
    if (!m_modelMesh.uploaded) upload(m_modelMesh, view.geometry->mesh);
    const bool scene = view.dressing && !view.dressing->mesh.indices.empty();
    if (scene && !m_sceneMesh.uploaded) upload(m_sceneMesh, view.dressing->mesh);
    const SceneGeometry& g = *view.geometry;
    m_lamps = lampCount();
    const bool perVertex = lightsPerVertex();
    Program* solids = program(m_lamps, perVertex);
    if (!solids) return -1;

    m_modelMesh.vao->bind();
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glDisable(GL_BLEND);

    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LEQUAL);

    // camera
    Vector3d centre;
    double radius = 0;
    view.sphere(centre, radius);
    m_view = view.camera.viewMatrix().cast<float>();
    // far enough for the grid, and for all of the scene
    double farthest = 1.5 * g.gridExtent;
    if (scene) {
        for (int c = 0; c < 8; ++c) {
            const Vector3d corner = view.dressing->bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
            farthest = std::max(farthest, (corner - centre).norm());
        }
    }
    const Eigen::Matrix4d projection64 = view.camera.projectionMatrix(aspect, centre, radius, farthest);
    m_projection = projection64.cast<float>();
    m_near = projection64(2, 3) / (projection64(2, 2) - 1);  // (p23 = −2fn/(f−n), p22 = −(f+n)/(f−n))
    // the near plane's visible rectangle, in the world: (±1, ±1, −1) of the clip cube
    const Eigen::Matrix4d unproject = (projection64 * m_view.cast<double>()).inverse();
    for (std::size_t c = 0; c < 4; ++c) {
        const Eigen::Vector4d x = unproject * Eigen::Vector4d(c == 1 || c == 2 ? 1 : -1, c >= 2 ? 1 : -1, -1, 1);
        m_nearQuad[c] = x.head<3>() / x.w();
    }
    useProgram(*solids);

    m_slotMatrices.resize(static_cast<std::size_t>(g.slotCount()));
    for (int s = 0; s < g.slotCount(); ++s) {
        m_slotMatrices[static_cast<std::size_t>(s)] = view.bodyPose(s - 1).matrix().cast<float>();
    }

    // the solids (the model, the scene, the world axes). Lit at every pixel: first their
    // depth alone, then their colour, without depth writes, where they are nearest, so
    // that every pixel is shaded once instead of once per layer of the mill (liners, the
    // shell behind): with the same program and state in both passes the depths are the
    // same, and with GL_LEQUAL the same fragment wins as in a single pass (the last one
    // drawn at the nearest depth). Lit at the vertices, a pixel costs little more than
    // its depth test: one pass.
    const bool schematic = view.mode == DisplayMode::Schematic;
    if (!perVertex) {
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        drawSolids(schematic);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthMask(GL_FALSE);
    }
    drawSolids(schematic);

    // background, a vertical gradient, after the solids: only where none was drawn
    // (it lies on the far plane; a scene that fills the view then costs a depth test a
    // pixel, 1 ms of a 1920 × 1080 frame on llvmpipe, and drawn first, twice that)
    glDepthMask(GL_FALSE);
    m_background->bind();
    m_background->setUniformValue(m_backgroundBottom, QVector3D(0.12f, 0.13f, 0.15f));
    m_background->setUniformValue(m_backgroundTop, QVector3D(0.31f, 0.33f, 0.37f));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_TRUE);
    m_program->program->bind();

    // ground grid: transparent lines fading out, after the solids (a scene has its floor);
    // the fade is per pixel (a line spans the grid): viewport.frag's
    Program* flat = view.showGrid && !scene ? program(m_lamps, false) : nullptr;
    if (flat) {
        if (flat != solids) useProgram(*flat);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        glUniform1i(m_u.lit, 0);
        glUniform1f(m_u.fadeRadius, static_cast<float>(g.gridExtent));
        setAlpha(0.8f);
        drawRange(g.grid, Matrix4f::Identity(), GL_LINES);
        glUniform1f(m_u.fadeRadius, 0.0f);
        glUniform1i(m_u.lit, 1);
        setAlpha(1.0f);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
        if (flat != solids) useProgram(*solids);
    }

    // the ghost: the same machine at other poses, translucent, tinted blue; no depth
    // writes, so the real machine and the scene show through it
    if (view.ghost && view.ghost->bundle == view.bundle && view.ghost->bodyPoses.size() == view.poses.size()) {
        glEnable(GL_BLEND);
        // the frame's alpha stays 1: a translucent alpha would make the widget itself
        // translucent when composed (garish colours in grabs and under a compositor)
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        glDepthMask(GL_FALSE);
        setTint(kGhostTint, 0.45f);
        setAlpha(kGhostAlpha);
        for (int s = 1; s < g.slotCount(); ++s) {  // not slot 0: the ground's graphics do not move
            const auto k = static_cast<std::size_t>(s);
            const Matrix4f X = view.ghost->bodyPoses[k - 1].matrix().cast<float>();
            if (schematic) drawRange(g.schematic[k], X);
            else drawRange(g.dressed[k].empty() ? g.bars[k] : g.dressed[k], X);
        }
        setAlpha(1.0f);
        setTint(Vector3f::Zero(), 0.0f);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }

    // Both: the schematic over the dressed model
    if (view.mode == DisplayMode::Both) {
        glClear(GL_DEPTH_BUFFER_BIT);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        setAlpha(kOverlayAlpha);
        drawSlots(true, false);
        drawActuators(-1);
        setAlpha(1.0f);
        glDisable(GL_BLEND);
    }

    // body frames on demand, over the model (they are inside its dressing)
    if (view.showFrames) {
        glClear(GL_DEPTH_BUFFER_BIT);
        for (int b = 0; b < g.nb; ++b) {
            drawRange(g.unitTriad, scaled(view.bodyPose(b), Vector3d::Constant(5 * g.schematicWidth)));
        }
    }

    // contacts on demand, over the model (they are where solids meet, inside both)
    if (view.showContacts) drawContacts();

    // the highlighted joint, over everything
    if (view.highlightJoint >= 0) {
        glClear(GL_DEPTH_BUFFER_BIT);
        setTint(kHighlight, 1.0f);
        for (const JointPiece& p : g.jointPieces[static_cast<std::size_t>(view.highlightJoint)]) {
            drawRange(p.range, m_slotMatrices[static_cast<std::size_t>(p.body + 1)]);
        }
        drawActuators(view.highlightJoint);
        setTint(Vector3f::Zero(), 0.0f);
    }

    drawPush();

    m_program->program->release();
    m_modelMesh.vao->release();

    // frame time: until the frame is drawn (software renderers draw at the finish)
    glFinish();
    const double ms = 1e-6 * static_cast<double>(timer.nsecsElapsed());
    m_frameTimes[static_cast<std::size_t>(m_frameCount % static_cast<int>(m_frameTimes.size()))] = ms;
    ++m_frameCount;
    return ms;
}

ViewRenderer::Program* ViewRenderer::program(int lamps, bool perVertex)
{
    Program& p = (perVertex ? m_vertexPrograms : m_programs)[static_cast<std::size_t>(lamps)];
    if (!p.program && !buildProgram(p, lamps, perVertex)) return nullptr;
    return &p;
}

void ViewRenderer::useProgram(Program& p)
{
    m_program = &p;
    m_u = p.u;
    p.program->bind();
    const Vector3f upEye = m_view.topLeftCorner<3, 3>() * Vector3f::UnitZ();
    glUniformMatrix4fv(m_u.view, 1, GL_FALSE, m_view.data());
    glUniformMatrix4fv(m_u.projection, 1, GL_FALSE, m_projection.data());
    glUniform3f(m_u.upEye, upEye.x(), upEye.y(), upEye.z());
    glUniform1i(m_u.lit, 1);
    glUniform1f(m_u.fadeRadius, 0.0f);
    glUniform2f(m_u.fadeCentre, 0.0f, 0.0f);
    glUniform4f(m_u.clipPlane, 0.0f, 0.0f, 0.0f, 1.0f);
    setLights(m_lamps);
    setTint(Vector3f::Zero(), 0.0f);
    setAlpha(1.0f);
}

int ViewRenderer::lampCount() const
{
    return m_state->dressing ? std::min(static_cast<int>(m_state->dressing->lights.size()), kMaxLamps) : 0;
}

void ViewRenderer::setLights(int lamps)
{
    // an interior when the scene has lamps: the daylight dimmed, the lamps lit
    glUniform1f(m_u.daylight, lamps > 0 ? kInteriorDaylight : 1.0f);
    if (lamps > 0) {
        std::array<GLfloat, 3 * kMaxLamps> eye{};
        for (int n = 0; n < lamps; ++n) {
            const Vector3d& p = m_state->dressing->lights[static_cast<std::size_t>(n)];
            const Vector3f e = (m_view * p.cast<float>().homogeneous()).head<3>();
            for (int k = 0; k < 3; ++k) eye[static_cast<std::size_t>(3 * n + k)] = e[k];
        }
        glUniform3fv(m_u.lightEye, lamps, eye.data());
        glUniform3f(m_u.lightColor, kLampLight.x(), kLampLight.y(), kLampLight.z());
        glUniform1f(m_u.lightRange, kLampRange);
    }
}

void ViewRenderer::drawSolids(bool schematic)
{
    const SceneGeometry& g = *m_state->geometry;
    // the model
    drawSlots(schematic, !schematic);
    if (schematic) drawActuators(-1);

    // the scene around it
    if (m_state->dressing && !m_state->dressing->mesh.indices.empty()) drawScene();

    // world axes at the origin
    const double initialRadius =
        g.initialBounds.isEmpty() ? 1.0 : std::max(0.5 * g.initialBounds.diagonal().norm(), 0.05);
    drawRange(g.unitTriad, scaled(Isometry3d::Identity(), Vector3d::Constant(0.25 * initialRadius)));
}

void ViewRenderer::drawScene()
{
    const SceneDressing& d = *m_state->dressing;
    // cut away the scene between the eye and the model: everything before a plane
    // through the model's box corner nearest the eye, across the view (an orbit camera
    // outside the mill looks into it) or across the seat's heading (one plane for
    // every screen of the seat, so that they join)
    Vector3d normal = m_state->camera.forward();
    if (m_state->camera.mode == Camera::Mode::Seat) {
        normal = Vector3d(std::sin(m_state->camera.seatHeading), std::cos(m_state->camera.seatHeading), 0);
    }
    const Vector3d eye = m_state->camera.eye();
    const Eigen::AlignedBox3d box = m_state->box();
    double nearest = std::numeric_limits<double>::infinity();
    for (int c = 0; c < 8; ++c) {
        nearest = std::min(nearest, (box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)) - eye).dot(normal));
    }
    if (nearest > 0) {
        // kept where n·x ≥ n·eye + nearest (world), as a plane in eye space
        const Eigen::Vector4d world(normal.x(), normal.y(), normal.z(), -(normal.dot(eye) + nearest));
        const Eigen::Vector4f plane = (m_view.cast<double>().inverse().transpose() * world).cast<float>();
        glUniform4f(m_u.clipPlane, plane.x(), plane.y(), plane.z(), plane.w());
        glEnable(GL_CLIP_DISTANCE0);
    }
    // pushed back a little: where the model touches the scene (on its floor) the model wins
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 2.0f);
    m_sceneMesh.vao->bind();
    setTint(Vector3f::Zero(), 0.0f);
    glUniform1i(m_u.lit, 0);  // the lamps glow
    drawRange(d.lamps, Matrix4f::Identity());
    glUniform1i(m_u.lit, 1);
    // the scene's closed solids that the plane leaves whole: their back faces culled
    const Eigen::Vector4d cut(normal.x(), normal.y(), normal.z(), -(normal.dot(eye) + nearest));
    drawParts(d.mesh, d.solidParts, Matrix4f::Identity(), nearest > 0 ? &cut : nullptr);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CLIP_DISTANCE0);
    glUniform4f(m_u.clipPlane, 0.0f, 0.0f, 0.0f, 1.0f);
    m_modelMesh.vao->bind();
}

double ViewRenderer::frameMillis() const
{
    const int n = std::min(m_frameCount, static_cast<int>(m_frameTimes.size()));
    if (n == 0) return 0;
    std::array<double, 31> t = m_frameTimes;
    std::nth_element(t.begin(), t.begin() + n / 2, t.begin() + n);
    return t[static_cast<std::size_t>(n / 2)];
}

}  // namespace studio
