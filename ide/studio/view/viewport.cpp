#include "ide/studio/view/viewport.h"

#include "ide/studio/view/scene_geometry.h"

#include <QElapsedTimer>
#include <QMouseEvent>
#include <QOpenGLBuffer>
#include <QOpenGLContext>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

// the shaders are in studio.qrc, compiled into this static library: register them
// explicitly (a static library's resource initialiser is otherwise never linked in)
static void initStudioResources()
{
    Q_INIT_RESOURCE(studio);
}

namespace studio {

using Eigen::Isometry3d;
using Eigen::Matrix4f;
using Eigen::Vector3d;
using Eigen::Vector3f;

namespace {

constexpr double kDeg = std::numbers::pi / 180;
const Vector3f kHighlight(1.0f, 0.86f, 0.10f);
const Vector3f kRodSilver(0.82f, 0.83f, 0.86f);
constexpr float kOverlayAlpha = 0.6f;

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

int g_samples = 0;  // multisampling of new viewports (Viewport::setSamples)

Matrix4f scaled(const Isometry3d& pose, const Vector3d& scale)
{
    Eigen::Affine3d a(pose);
    a.scale(scale);
    return a.matrix().cast<float>();
}

}  // namespace

Viewport::Viewport(QWidget* parent) : QOpenGLWidget(parent)
{
    static const bool resources = (initStudioResources(), true);
    Q_UNUSED(resources);
    setFormat(surfaceFormat());
    setMinimumSize(160, 120);
    setFocusPolicy(Qt::ClickFocus);
    setBundle(nullptr);
}

Viewport::~Viewport()
{
    releaseGl();
}

QSurfaceFormat Viewport::surfaceFormat()
{
    QSurfaceFormat f;
    f.setRenderableType(QSurfaceFormat::OpenGL);
    f.setVersion(3, 3);
    f.setProfile(QSurfaceFormat::CoreProfile);
    f.setDepthBufferSize(24);
    f.setStencilBufferSize(8);
    f.setSamples(g_samples);
    return f;
}

void Viewport::setSamples(int samples)
{
    g_samples = std::clamp(samples, 0, 16);
}

int Viewport::samples()
{
    return g_samples;
}

// ---- model and poses ---------------------------------------------------------------

void Viewport::setBundle(std::shared_ptr<const ModelBundle> bundle)
{
    if (bundle && bundle == m_bundle && m_geometry) return;
    // an edited model (same file) keeps the view the modeler chose
    const bool sameModel = bundle && m_bundle && bundle->filePath == m_bundle->filePath;
    m_bundle = std::move(bundle);
    m_geometry = sceneGeometry(m_bundle);
    m_poses = m_bundle && m_bundle->model ? initialPoses(*m_bundle->model) : std::vector<Isometry3d>{};
    m_slotMatrices.assign(static_cast<std::size_t>(m_geometry->slotCount()), Matrix4f::Identity());
    m_uploaded = false;
    if (m_highlightBody >= m_geometry->nb) m_highlightBody = -1;
    if (m_highlightJoint >= m_geometry->nb) m_highlightJoint = -1;
    if (!m_seatSet) {
        m_camera.seatEye = m_geometry->seatEye;
        m_camera.seatHeading = 0;
        m_camera.seatPitch = m_geometry->seatPitch;
    }
    if (!sameModel) {
        if (m_cameraName.isEmpty()) fitAll();
        else applyNamedCamera();
    }
    for (const QString& message : m_geometry->problems) emit problem(message);
    update();
}

void Viewport::setPoses(const std::vector<Isometry3d>& X_wb)
{
    if (!m_geometry || static_cast<int>(X_wb.size()) != m_geometry->nb) return;
    m_poses = X_wb;  // same size: no reallocation
    update();
}

void Viewport::setSnapshot(std::shared_ptr<const Snapshot> snapshot)
{
    if (!snapshot) return;
    if (snapshot->bundle && snapshot->bundle != m_bundle) setBundle(snapshot->bundle);
    setPoses(snapshot->bodyPoses);
}

void Viewport::setDisplayMode(DisplayMode mode)
{
    if (m_mode == mode) return;
    m_mode = mode;
    update();
}

void Viewport::setShowFrames(bool show)
{
    m_showFrames = show;
    update();
}

void Viewport::setShowGrid(bool show)
{
    m_showGrid = show;
    update();
}

void Viewport::setHighlight(int body, int joint)
{
    const int nb = m_geometry ? m_geometry->nb : 0;
    m_highlightBody = body >= 0 && body < nb ? body : -1;
    m_highlightJoint = joint >= 0 && joint < nb ? joint : -1;
    update();
}

// ---- cameras -------------------------------------------------------------------------

QStringList Viewport::cameraNames()
{
    QStringList names;
    for (const NamedView& v : kViews) names << QString::fromLatin1(v.name);
    names << QString::fromLatin1(kSeat);
    return names;
}

QString Viewport::cameraLabel(const QString& name)
{
    if (name == QLatin1String("Iso")) return tr("Iso");
    if (name == QLatin1String("Front")) return tr("Front");
    if (name == QLatin1String("Side")) return tr("Side");
    if (name == QLatin1String("Top")) return tr("Top");
    if (name == QLatin1String(kSeat)) return tr("Operator seat");
    return name;
}

bool Viewport::setCamera(const QString& name)
{
    if (!cameraNames().contains(name)) return false;
    m_cameraName = name;
    applyNamedCamera();
    update();
    return true;
}

void Viewport::applyNamedCamera()
{
    if (m_cameraName == QLatin1String(kSeat)) {
        m_camera.mode = Camera::Mode::Seat;
        return;
    }
    for (const NamedView& v : kViews) {
        if (m_cameraName != QLatin1String(v.name)) continue;
        m_camera.mode = Camera::Mode::Orbit;
        m_camera.yaw = v.yaw;
        m_camera.pitch = v.pitch;
        m_camera.frame(sceneBox(), aspect());
    }
}

void Viewport::leaveNamedCamera()
{
    if (m_camera.mode == Camera::Mode::Seat) {
        Vector3d c;
        double r = 0;
        sceneSphere(c, r);
        const double ahead = (c - m_camera.eye()).dot(m_camera.forward());
        m_camera.toOrbit(std::max(ahead, 0.5 * r));
    }
    m_cameraName.clear();
}

void Viewport::fitAll()
{
    if (m_camera.mode == Camera::Mode::Seat) leaveNamedCamera();
    m_camera.frame(sceneBox(), aspect());
    update();
}

void Viewport::setOperatorSeat(const Vector3d& eye, double yawRad, double pitchRad)
{
    m_seatSet = true;
    m_camera.seatEye = eye;
    m_camera.seatHeading = yawRad;
    m_camera.seatPitch = std::clamp(pitchRad, -std::numbers::pi / 2, std::numbers::pi / 2);
    update();
}

void Viewport::resetOperatorSeat()
{
    m_seatSet = false;
    m_camera.seatEye = m_geometry->seatEye;
    m_camera.seatHeading = 0;
    m_camera.seatPitch = m_geometry->seatPitch;
    update();
}

void Viewport::setYawOffset(double radians)
{
    m_camera.yawOffset = radians;
    update();
}

void Viewport::setSeatFieldOfView(double radians)
{
    m_camera.seatFieldOfView = std::clamp(radians, 5 * kDeg, 170 * kDeg);
    update();
}

double Viewport::aspect() const
{
    return height() > 0 ? static_cast<double>(width()) / height() : 1.0;
}

Isometry3d Viewport::bodyPose(int body) const
{
    return body < 0 || body >= static_cast<int>(m_poses.size()) ? Isometry3d::Identity()
                                                                : m_poses[static_cast<std::size_t>(body)];
}

Eigen::AlignedBox3d Viewport::sceneBox() const
{
    Eigen::AlignedBox3d box = worldBounds(*m_geometry, m_poses, m_mode == DisplayMode::Schematic);
    if (box.isEmpty()) box = Eigen::AlignedBox3d(Vector3d::Constant(-3), Vector3d::Constant(3));  // the grid's middle
    return box;
}

void Viewport::sceneSphere(Vector3d& centre, double& radius) const
{
    const Eigen::AlignedBox3d box = sceneBox();
    centre = box.center();
    radius = std::max(0.5 * box.diagonal().norm(), 0.05);
}

// ---- GL ------------------------------------------------------------------------------

void Viewport::initializeGL()
{
    m_glReady = false;
    m_uploaded = false;
    if (!initializeOpenGLFunctions()) {
        if (!m_glFailed) emit problem(tr("The 3D view needs OpenGL 3.3, which this system does not provide."));
        m_glFailed = true;
        return;
    }
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGl, Qt::UniqueConnection);
    auto build = [this](std::unique_ptr<QOpenGLShaderProgram>& program, const QString& vert, const QString& frag) {
        program = std::make_unique<QOpenGLShaderProgram>();
        const bool ok = program->addShaderFromSourceFile(QOpenGLShader::Vertex, vert) &&
                        program->addShaderFromSourceFile(QOpenGLShader::Fragment, frag) && program->link();
        if (!ok && !m_glFailed) {
            emit problem(tr("The 3D view's shaders do not build: %1").arg(program->log()));
            m_glFailed = true;
        }
        return ok;
    };
    if (!build(m_program, QStringLiteral(":/studio/shaders/viewport.vert"),
               QStringLiteral(":/studio/shaders/viewport.frag")) ||
        !build(m_background, QStringLiteral(":/studio/shaders/background.vert"),
               QStringLiteral(":/studio/shaders/background.frag"))) {
        return;
    }
    m_u.model = m_program->uniformLocation("uModel");
    m_u.view = m_program->uniformLocation("uView");
    m_u.projection = m_program->uniformLocation("uProjection");
    m_u.normalMatrix = m_program->uniformLocation("uNormalMatrix");
    m_u.lit = m_program->uniformLocation("uLit");
    m_u.tint = m_program->uniformLocation("uTint");
    m_u.alpha = m_program->uniformLocation("uAlpha");
    m_u.upEye = m_program->uniformLocation("uUpEye");
    m_u.fadeCentre = m_program->uniformLocation("uFadeCentre");
    m_u.fadeRadius = m_program->uniformLocation("uFadeRadius");
    m_vao = std::make_unique<QOpenGLVertexArrayObject>();
    m_vao->create();
    m_vertexBuffer = std::make_unique<QOpenGLBuffer>(QOpenGLBuffer::VertexBuffer);
    m_vertexBuffer->create();
    m_indexBuffer = std::make_unique<QOpenGLBuffer>(QOpenGLBuffer::IndexBuffer);
    m_indexBuffer->create();
    m_glReady = true;
}

void Viewport::releaseGl()
{
    if (!m_program && !m_vao) return;
    makeCurrent();
    m_indexBuffer.reset();
    m_vertexBuffer.reset();
    m_vao.reset();
    m_program.reset();
    m_background.reset();
    m_glReady = false;
    m_uploaded = false;
    doneCurrent();
}

void Viewport::upload()
{
    const MeshBuilder& mesh = m_geometry->mesh;
    m_vao->bind();
    m_vertexBuffer->bind();
    m_vertexBuffer->allocate(mesh.vertices.data(), static_cast<int>(mesh.vertices.size() * sizeof(MeshVertex)));
    m_indexBuffer->bind();  // part of the VAO's state
    m_indexBuffer->allocate(mesh.indices.data(), static_cast<int>(mesh.indices.size() * sizeof(std::uint32_t)));
    const auto stride = static_cast<GLsizei>(sizeof(MeshVertex));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(MeshVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(MeshVertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(MeshVertex, color)));
    m_vao->release();
    m_uploaded = true;
}

void Viewport::resizeGL(int, int)
{
    // named orbit views keep the whole model framed
    if (!m_cameraName.isEmpty() && m_camera.mode == Camera::Mode::Orbit) applyNamedCamera();
}

void Viewport::setTint(const Vector3f& rgb, float amount)
{
    glUniform4f(m_u.tint, rgb.x(), rgb.y(), rgb.z(), amount);
}

void Viewport::setAlpha(float alpha)
{
    glUniform1f(m_u.alpha, alpha);
}

void Viewport::drawRange(const DrawRange& range, const Matrix4f& model, unsigned mode)
{
    if (range.empty()) return;
    const Eigen::Matrix3f normal = (m_view * model).topLeftCorner<3, 3>().inverse().transpose();
    glUniformMatrix4fv(m_u.model, 1, GL_FALSE, model.data());
    glUniformMatrix3fv(m_u.normalMatrix, 1, GL_FALSE, normal.data());
    glDrawElements(mode, static_cast<GLsizei>(range.count), GL_UNSIGNED_INT,
                   reinterpret_cast<void*>(static_cast<std::uintptr_t>(range.first) * sizeof(std::uint32_t)));
}

void Viewport::drawSlots(bool schematic, bool dressed)
{
    const SceneGeometry& g = *m_geometry;
    for (int s = 0; s < g.slotCount(); ++s) {
        const auto k = static_cast<std::size_t>(s);
        const bool lit = s > 0 && s - 1 == m_highlightBody;
        if (lit) setTint(kHighlight, 0.85f);
        if (dressed) drawRange(g.dressed[k].empty() ? g.bars[k] : g.dressed[k], m_slotMatrices[k]);
        if (schematic) drawRange(g.schematic[k], m_slotMatrices[k]);
        if (lit) setTint(Vector3f::Zero(), 0.0f);
    }
}

void Viewport::drawActuators(int onlyJoint)
{
    const SceneGeometry& g = *m_geometry;
    const double w = g.schematicWidth;
    for (const ActuatorLine& a : g.actuators) {
        if (onlyJoint >= 0 && a.joint != onlyJoint) continue;
        const Vector3d p1 = bodyPose(a.body1) * a.cl1;
        const Vector3d p2 = bodyPose(a.body2) * a.cl2;
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

void Viewport::paintGL()
{
    QElapsedTimer timer;
    timer.start();
    glClearColor(0.2f, 0.21f, 0.23f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!m_glReady) return;
    if (!m_uploaded) upload();
    const SceneGeometry& g = *m_geometry;

    m_vao->bind();
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);

    // background: a vertical gradient
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    m_background->bind();
    m_background->setUniformValue("uBottom", QVector3D(0.12f, 0.13f, 0.15f));
    m_background->setUniformValue("uTop", QVector3D(0.31f, 0.33f, 0.37f));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LEQUAL);

    // camera
    Vector3d centre;
    double radius = 0;
    sceneSphere(centre, radius);
    m_view = m_camera.viewMatrix().cast<float>();
    const Matrix4f projection = m_camera.projectionMatrix(aspect(), centre, radius, 1.5 * g.gridExtent).cast<float>();
    const Vector3f upEye = m_view.topLeftCorner<3, 3>() * Vector3f::UnitZ();
    m_program->bind();
    glUniformMatrix4fv(m_u.view, 1, GL_FALSE, m_view.data());
    glUniformMatrix4fv(m_u.projection, 1, GL_FALSE, projection.data());
    glUniform3f(m_u.upEye, upEye.x(), upEye.y(), upEye.z());
    glUniform1i(m_u.lit, 1);
    glUniform1f(m_u.fadeRadius, 0.0f);
    glUniform2f(m_u.fadeCentre, 0.0f, 0.0f);
    setTint(Vector3f::Zero(), 0.0f);
    setAlpha(1.0f);

    for (int s = 0; s < g.slotCount(); ++s) {
        m_slotMatrices[static_cast<std::size_t>(s)] = bodyPose(s - 1).matrix().cast<float>();
    }

    // the model
    const bool schematic = m_mode == DisplayMode::Schematic;
    drawSlots(schematic, !schematic);
    if (schematic) drawActuators(-1);

    // world axes at the origin
    const double initialRadius =
        g.initialBounds.isEmpty() ? 1.0 : std::max(0.5 * g.initialBounds.diagonal().norm(), 0.05);
    drawRange(g.unitTriad, scaled(Isometry3d::Identity(), Vector3d::Constant(0.25 * initialRadius)));

    // ground grid: transparent lines fading out, after the solids
    if (m_showGrid) {
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
    }

    // Both: the schematic over the dressed model
    if (m_mode == DisplayMode::Both) {
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
    if (m_showFrames) {
        glClear(GL_DEPTH_BUFFER_BIT);
        for (int b = 0; b < g.nb; ++b) {
            drawRange(g.unitTriad, scaled(bodyPose(b), Vector3d::Constant(5 * g.schematicWidth)));
        }
    }

    // the highlighted joint, over everything
    if (m_highlightJoint >= 0) {
        glClear(GL_DEPTH_BUFFER_BIT);
        setTint(kHighlight, 1.0f);
        for (const JointPiece& p : g.jointPieces[static_cast<std::size_t>(m_highlightJoint)]) {
            drawRange(p.range, m_slotMatrices[static_cast<std::size_t>(p.body + 1)]);
        }
        drawActuators(m_highlightJoint);
        setTint(Vector3f::Zero(), 0.0f);
    }

    m_program->release();
    m_vao->release();

    // frame time: until the frame is drawn (software renderers draw at the finish)
    glFinish();
    const double ms = 1e-6 * static_cast<double>(timer.nsecsElapsed());
    m_frameTimes[static_cast<std::size_t>(m_frameCount % static_cast<int>(m_frameTimes.size()))] = ms;
    ++m_frameCount;
    emit frameTimed(ms);
}

double Viewport::frameMillis() const
{
    const int n = std::min(m_frameCount, static_cast<int>(m_frameTimes.size()));
    if (n == 0) return 0;
    std::array<double, 31> t = m_frameTimes;
    std::nth_element(t.begin(), t.begin() + n / 2, t.begin() + n);
    return t[static_cast<std::size_t>(n / 2)];
}

// ---- mouse ---------------------------------------------------------------------------

void Viewport::mousePressEvent(QMouseEvent* event)
{
    m_lastMouse = event->position().toPoint();
    m_dragging = true;
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent* event)
{
    if (!m_dragging) return;
    const QPoint pos = event->position().toPoint();
    const QPoint d = pos - m_lastMouse;
    m_lastMouse = pos;
    if (d.isNull()) return;
    const bool pan = (event->buttons() & Qt::MiddleButton) ||
                     ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ShiftModifier));
    const bool orbit = !pan && (event->buttons() & Qt::LeftButton);
    if (!pan && !orbit) return;
    leaveNamedCamera();
    if (pan) m_camera.pan(d.x(), d.y(), height());
    else m_camera.orbit(d.x(), d.y());
    update();
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event)
{
    m_dragging = false;
    event->accept();
}

void Viewport::mouseDoubleClickEvent(QMouseEvent* event)
{
    fitAll();
    event->accept();
}

void Viewport::wheelEvent(QWheelEvent* event)
{
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0) return;
    leaveNamedCamera();
    const QPointF p = event->position();
    m_camera.zoom(std::pow(0.85, steps), p.x(), p.y(), width(), height());
    update();
    event->accept();
}

}  // namespace studio
