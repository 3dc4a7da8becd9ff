#include "ide/studio/view/viewport.h"

#include "ide/studio/view/scene_geometry.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QExposeEvent>
#include <QFile>
#include <QMetaMethod>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLBuffer>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLPaintDevice>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QPainter>
#include <QTimer>
#include <QWheelEvent>
#include <QWindow>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <limits>
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
bool g_cullFaces = true;  // Viewport::setBackFaceCulling
std::atomic<Viewport::Lighting> g_lighting{Viewport::Lighting::Automatic};  // Viewport::setLighting

Matrix4f scaled(const Isometry3d& pose, const Vector3d& scale)
{
    Eigen::Affine3d a(pose);
    a.scale(scale);
    return a.matrix().cast<float>();
}

const QColor kUnderColor(51, 54, 59);  // the view's widget under its window (seen before it first draws)

}  // namespace

// ---- the native window ---------------------------------------------------------------

/// The view's native window: draws the frames (Viewport::renderNow) when exposed and
/// at update requests, and hands its mouse, wheel and key events to the view (the
/// widget), as if they had come to it. It never takes the keyboard focus: the view
/// (ClickFocus) does, so the keys go through the widget's event filters as before.
class Viewport::Surface : public QWindow {
public:
    explicit Surface(Viewport* view) : m_view(view)
    {
        setSurfaceType(QSurface::OpenGLSurface);
        setFormat(Viewport::surfaceFormat());
        setFlag(Qt::WindowDoesNotAcceptFocus);
    }

protected:
    bool event(QEvent* event) override
    {
        switch (event->type()) {
        case QEvent::UpdateRequest:
            m_view->renderNow();
            return true;
        case QEvent::MouseButtonPress:
        case QEvent::MouseButtonDblClick:
            if (m_view->focusPolicy() & Qt::ClickFocus) m_view->setFocus(Qt::MouseFocusReason);
            if (!m_view->isActiveWindow()) m_view->activateWindow();
            [[fallthrough]];
        case QEvent::MouseButtonRelease:
        case QEvent::MouseMove:
        case QEvent::Wheel:
        case QEvent::KeyPress:
        case QEvent::KeyRelease:
            // this window fills the view, so its coordinates are the view's
            QCoreApplication::sendEvent(m_view, event);
            return true;
        default:
            return QWindow::event(event);
        }
    }
    void exposeEvent(QExposeEvent*) override
    {
        if (isExposed()) m_view->renderNow();
    }

private:
    Viewport* m_view;
};

Viewport::Viewport(QWidget* parent) : QWidget(parent)
{
    static const bool resources = (initStudioResources(), true);
    Q_UNUSED(resources);
    setMinimumSize(160, 120);
    setFocusPolicy(Qt::ClickFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);
    m_surface = new Surface(this);
    m_container = QWidget::createWindowContainer(m_surface, this);
    m_container->setFocusPolicy(Qt::NoFocus);
    m_container->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_container->setGeometry(rect());
    m_frameTimer.setSingleShot(true);
    m_frameTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_frameTimer, &QTimer::timeout, this, &Viewport::renderNow);
    setBundle(nullptr);
}

Viewport::~Viewport()
{
    for (const QPointer<QWidget>& o : m_overlays) {
        if (o) watchOverlay(o, false);
    }
    releaseGl();
    m_context.reset();  // before its window (m_container's) goes
    m_offscreen.reset();
}

QSurfaceFormat Viewport::surfaceFormat()
{
    QSurfaceFormat f;
    f.setRenderableType(QSurfaceFormat::OpenGL);
    f.setVersion(3, 3);
    f.setProfile(QSurfaceFormat::CoreProfile);
    f.setDepthBufferSize(24);
    f.setStencilBufferSize(0);  // none used (llvmpipe's depth test is a little cheaper without)
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

void Viewport::setBackFaceCulling(bool on)
{
    g_cullFaces = on;
}

bool Viewport::backFaceCulling()
{
    return g_cullFaces;
}

void Viewport::setLighting(Lighting lighting)
{
    g_lighting = lighting;
}

Viewport::Lighting Viewport::lighting()
{
    return g_lighting;
}

QString Viewport::lightingName(Lighting lighting)
{
    switch (lighting) {
    case Lighting::PerPixel: return QStringLiteral("pixel");
    case Lighting::PerVertex: return QStringLiteral("vertex");
    case Lighting::Automatic: break;
    }
    return QStringLiteral("auto");
}

bool Viewport::lightingFromName(const QString& name, Lighting& lighting)
{
    for (Lighting l : {Lighting::Automatic, Lighting::PerPixel, Lighting::PerVertex}) {
        if (name == lightingName(l)) {
            lighting = l;
            return true;
        }
    }
    return false;
}

bool Viewport::lightsPerVertex() const
{
    const Lighting l = g_lighting;
    return l == Lighting::PerVertex || (l == Lighting::Automatic && m_softwareGl);
}

// ---- model and poses ---------------------------------------------------------------

void Viewport::setBundle(std::shared_ptr<const ModelBundle> bundle)
{
    if (bundle && bundle == m_bundle && m_geometry) return;
    // an edited model (same file) keeps the view the modeler chose
    const bool sameModel = bundle && m_bundle && bundle->filePath == m_bundle->filePath;
    m_bundle = std::move(bundle);
    endPush();  // the body pushed is another model's
    m_geometry = sceneGeometry(m_bundle);
    m_poses = m_bundle && m_bundle->model ? initialPoses(*m_bundle->model) : std::vector<Isometry3d>{};
    m_slotMatrices.assign(static_cast<std::size_t>(m_geometry->slotCount()), Matrix4f::Identity());
    m_modelMesh.uploaded = false;
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
    requestFrame();
}

void Viewport::setScene(std::shared_ptr<const ModelBundle> scene)
{
    if (scene == m_scene) return;
    m_scene = std::move(scene);
    m_dressing = sceneDressing(m_scene);
    m_sceneMesh.uploaded = false;
    if (m_dressing) {
        for (const QString& message : m_dressing->problems) emit problem(message);
    }
    requestFrame();
}

void Viewport::setPoses(const std::vector<Isometry3d>& X_wb)
{
    if (!m_geometry || static_cast<int>(X_wb.size()) != m_geometry->nb) return;
    m_poses = X_wb;  // same size: no reallocation
    requestFrame();
}

void Viewport::setSnapshot(std::shared_ptr<const Snapshot> snapshot)
{
    if (!snapshot) return;
    if (snapshot->bundle && snapshot->bundle != m_bundle) setBundle(snapshot->bundle);
    m_contactsOf = snapshot;
    setPoses(snapshot->bodyPoses);
}

void Viewport::setGhost(std::shared_ptr<const Snapshot> ghost)
{
    if (ghost == m_ghost) return;
    m_ghost = std::move(ghost);
    requestFrame();
}

void Viewport::clearGhost()
{
    if (!m_ghost) return;
    m_ghost.reset();
    requestFrame();
}

void Viewport::setDisplayMode(DisplayMode mode)
{
    if (m_mode == mode) return;
    m_mode = mode;
    requestFrame();
}

void Viewport::setShowContacts(bool show)
{
    m_showContacts = show;
    requestFrame();
}

void Viewport::setShowFrames(bool show)
{
    m_showFrames = show;
    requestFrame();
}

void Viewport::setShowGrid(bool show)
{
    m_showGrid = show;
    requestFrame();
}

void Viewport::setHighlight(int body, int joint)
{
    const int nb = m_geometry ? m_geometry->nb : 0;
    m_highlightBody = body >= 0 && body < nb ? body : -1;
    m_highlightJoint = joint >= 0 && joint < nb ? joint : -1;
    requestFrame();
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

void Viewport::setCameraState(const Camera& camera)
{
    m_camera = camera;
    m_cameraName.clear();
    requestFrame();
}

bool Viewport::setCamera(const QString& name)
{
    if (!cameraNames().contains(name)) return false;
    m_cameraName = name;
    applyNamedCamera();
    requestFrame();
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
    requestFrame();
}

void Viewport::setOperatorSeat(const Vector3d& eye, double yawRad, double pitchRad)
{
    m_seatSet = true;
    m_camera.seatEye = eye;
    m_camera.seatHeading = yawRad;
    m_camera.seatPitch = std::clamp(pitchRad, -std::numbers::pi / 2, std::numbers::pi / 2);
    requestFrame();
}

void Viewport::resetOperatorSeat()
{
    m_seatSet = false;
    m_camera.seatEye = m_geometry->seatEye;
    m_camera.seatHeading = 0;
    m_camera.seatPitch = m_geometry->seatPitch;
    requestFrame();
}

void Viewport::setYawOffset(double radians)
{
    m_camera.yawOffset = radians;
    requestFrame();
}

void Viewport::setSeatFieldOfView(double radians)
{
    m_camera.seatFieldOfView = std::clamp(radians, 5 * kDeg, 170 * kDeg);
    requestFrame();
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
    m_modelMesh.uploaded = false;
    m_sceneMesh.uploaded = false;
    if (!initializeOpenGLFunctions()) {
        if (!m_glFailed) emit problem(tr("The 3D view needs OpenGL 3.3, which this system does not provide."));
        m_glFailed = true;
        return;
    }
    connect(m_context.get(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGl, Qt::UniqueConnection);
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
        if (!m_glFailed) emit problem(tr("The 3D view's shaders do not build: %1").arg(m_background->log()));
        m_glFailed = true;
        return;
    }
    m_backgroundBottom = m_background->uniformLocation("uBottom");
    m_backgroundTop = m_background->uniformLocation("uTop");
    if (!buildProgram(m_programs[0], 0, false)) return;
    createMesh(m_modelMesh);
    createMesh(m_sceneMesh);
    m_glReady = true;
}

bool Viewport::buildProgram(Program& p, int lamps, bool perVertex)
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
        if (!m_glFailed) emit problem(tr("The 3D view's shaders do not build: %1").arg(p.program->log()));
        m_glFailed = true;
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

void Viewport::createMesh(GlMesh& mesh)
{
    mesh.vao = std::make_unique<QOpenGLVertexArrayObject>();
    mesh.vao->create();
    mesh.vertices = std::make_unique<QOpenGLBuffer>(QOpenGLBuffer::VertexBuffer);
    mesh.vertices->create();
    mesh.indices = std::make_unique<QOpenGLBuffer>(QOpenGLBuffer::IndexBuffer);
    mesh.indices->create();
    mesh.uploaded = false;
}

void Viewport::releaseGl()
{
    if (!m_context || (!m_background && !m_modelMesh.vao)) return;
    makeCurrent();
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
    doneCurrent();
}

void Viewport::upload(GlMesh& gl, const MeshBuilder& mesh)
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

// ---- the context, frames on screen and offscreen --------------------------------------

QOpenGLContext* Viewport::context() const
{
    return m_context.get();
}

bool Viewport::makeCurrent()
{
    if (!m_context) {
        m_context = std::make_unique<QOpenGLContext>();
        m_context->setFormat(m_surface->requestedFormat());
        if (!m_context->create()) {
            m_context.reset();
            if (!m_glFailed) emit problem(tr("The 3D view needs OpenGL 3.3, which this system does not provide."));
            m_glFailed = true;
            return false;
        }
        m_glInitialized = false;
    }
    if (m_surface->handle()) return m_context->makeCurrent(m_surface);
    // no native window yet (the view was never shown): an offscreen surface
    if (!m_offscreen) {
        m_offscreen = std::make_unique<QOffscreenSurface>();
        m_offscreen->setFormat(m_context->format());
        m_offscreen->create();
    }
    return m_context->makeCurrent(m_offscreen.get());
}

void Viewport::doneCurrent()
{
    if (m_context) m_context->doneCurrent();
}

bool Viewport::prepareGl()
{
    if (!makeCurrent()) return false;
    if (!m_glInitialized) {
        m_glInitialized = true;
        initializeGL();
        resizeGL(width(), height());
    }
    return true;
}

void Viewport::requestFrame()
{
    // not exposed: the expose event draws. Else at once, or kMinFramePeriodMs after the
    // last frame began, whichever is later: QWindow::requestUpdate would wait for the
    // platform's next update tick (1000 / refresh rate ms, a whole frame at 60 Hz), so
    // that a frame asked for by the 60 Hz poll was drawn up to 16 ms late, and a frame
    // that takes 14 ms to draw came every 22 ms instead of every 16.7
    if (!m_surface || !m_surface->isExposed() || m_frameTimer.isActive()) return;
    const qint64 since = m_frameClock.isValid() ? m_frameClock.elapsed() : kMinFramePeriodMs;
    m_frameTimer.start(static_cast<int>(std::max<qint64>(0, kMinFramePeriodMs - since)));
}

void Viewport::renderNow()
{
    if (!m_surface || !m_surface->isExposed() || !prepareGl()) return;
    const qreal dpr = m_surface->devicePixelRatio();
    const QSize size = (QSizeF(m_surface->size()) * dpr).toSize();
    if (size.isEmpty()) return;
    m_frameTimer.stop();  // this frame shows what was asked for
    m_frameClock.start();
    glBindFramebuffer(GL_FRAMEBUFFER, m_context->defaultFramebufferObject());
    drawFrame(size.width(), size.height(), true);
    m_context->swapBuffers(m_surface);
}

QImage Viewport::grabFramebuffer()
{
    if (!prepareGl()) return {};
    const qreal dpr = devicePixelRatioF();
    const QSize size = (QSizeF(this->size()) * dpr).toSize().expandedTo(QSize(1, 1));
    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);
    format.setSamples(m_context->format().samples() > 0 ? m_context->format().samples() : 0);
    QOpenGLFramebufferObject fbo(size, format);
    if (!fbo.isValid() || !fbo.bind()) return {};
    drawFrame(size.width(), size.height(), false);
    QImage image = fbo.toImage();
    fbo.release();
    image.setDevicePixelRatio(dpr);
    return image;
}

void Viewport::drawFrame(int w, int h, bool overlays)
{
    glViewport(0, 0, w, h);
    paintGL();
    if (overlays) drawOverlays(w, h);
}

void Viewport::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    // painted somewhere else than on screen (QWidget::grab() or render() of a window
    // that holds the view): a frame drawn offscreen, the overlays are painted over it
    if (redirected(nullptr)) {
        const QImage frame = grabFramebuffer();
        if (frame.isNull()) painter.fillRect(rect(), kUnderColor);
        else painter.drawImage(rect(), frame);
        return;
    }
    // on screen the native window covers this; an update() of the widget is a new frame
    painter.fillRect(rect(), kUnderColor);
    requestFrame();
}

void Viewport::resizeEvent(QResizeEvent*)
{
    m_container->setGeometry(rect());
    resizeGL(width(), height());
}

// ---- overlays ---------------------------------------------------------------------------

void Viewport::addOverlay(QWidget* widget)
{
    if (!widget || m_overlays.contains(widget)) return;
    m_overlays.append(widget);
    watchOverlay(widget, true);
    m_overlaysDirty = true;
    requestFrame();
}

void Viewport::removeOverlay(QWidget* widget)
{
    if (!widget || !m_overlays.removeOne(widget)) return;
    watchOverlay(widget, false);
    m_overlayImages.remove(widget);
    requestFrame();
}

void Viewport::watchOverlay(QWidget* widget, bool watch)
{
    // the overlay and its children: their paint events say that it changed
    QList<QWidget*> widgets = widget->findChildren<QWidget*>();
    widgets.prepend(widget);
    for (QWidget* w : widgets) {
        if (watch) w->installEventFilter(this);
        else w->removeEventFilter(this);
    }
}

bool Viewport::eventFilter(QObject* watched, QEvent* event)
{
    if (!m_renderingOverlays && watched != this) {
        switch (event->type()) {
        case QEvent::Paint:
        case QEvent::Show:
        case QEvent::Hide:
        case QEvent::Resize:
        case QEvent::Move:
            m_overlaysDirty = true;
            requestFrame();
            break;
        case QEvent::ChildAdded:
            if (auto* child = qobject_cast<QWidget*>(static_cast<QChildEvent*>(event)->child())) {
                child->installEventFilter(this);
                m_overlaysDirty = true;
            }
            break;
        default:
            break;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void Viewport::drawOverlays(int w, int h)
{
    if (m_overlays.isEmpty()) return;
    if (m_overlaysDirty) {
        m_overlayImages.clear();
        m_overlaysDirty = false;
    }
    const qreal dpr = m_surface->devicePixelRatio();
    QWidget* top = window();
    const QPoint origin = mapTo(top, QPoint(0, 0));
    std::vector<std::pair<QPoint, const QImage*>> shown;
    for (const QPointer<QWidget>& o : m_overlays) {
        if (!o || !o->isVisible() || o->window() != top || o->size().isEmpty()) continue;
        const QRect r(o->mapTo(top, QPoint(0, 0)) - origin, o->size());
        if (!r.intersects(rect())) continue;
        QImage& image = m_overlayImages[o.data()];
        const QSize pixels = (QSizeF(o->size()) * dpr).toSize();
        if (image.size() != pixels) {
            // the widget as it paints itself (its style sheet's translucent background
            // included), on a transparent image
            image = QImage(pixels, QImage::Format_ARGB32_Premultiplied);
            image.setDevicePixelRatio(dpr);
            image.fill(Qt::transparent);
            m_renderingOverlays = true;
            o->render(&image, QPoint(), QRegion(), QWidget::DrawChildren);
            m_renderingOverlays = false;
        }
        shown.emplace_back(r.topLeft(), &image);
    }
    if (shown.empty()) return;
    QOpenGLPaintDevice device(w, h);
    device.setDevicePixelRatio(dpr);
    QPainter painter(&device);
    for (const auto& [at, image] : shown) painter.drawImage(at, *image);
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
        if (dressed) {
            if (g.dressed[k].empty()) drawRange(g.bars[k], m_slotMatrices[k]);
            else drawParts(g.mesh, g.dressedParts[k], m_slotMatrices[k], nullptr);
        }
        if (schematic) drawRange(g.schematic[k], m_slotMatrices[k]);
        if (lit) setTint(Vector3f::Zero(), 0.0f);
    }
}

void Viewport::drawParts(const MeshBuilder& mesh, const std::vector<CullPart>& parts, const Matrix4f& model,
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

void Viewport::drawContacts()
{
    if (!m_contactsOf || m_contactsOf->contacts.empty()) return;
    const SceneGeometry& g = *m_geometry;
    const double w = g.schematicWidth;
    // an arrow half as long as the machine's size for a force of its whole weight
    double weight = 0;
    if (m_bundle && m_bundle->model) {
        for (double m : m_bundle->model->mass) weight += m * m_bundle->model->gravity.norm();
    }
    const double size = w / 0.04;  // the machine's size (scene_geometry.cpp: w = 0.04 of it)
    const double perNewton = weight > 0 ? 0.5 * size / weight : 0.0;
    glClear(GL_DEPTH_BUFFER_BIT);
    for (const ContactSnapshot& c : m_contactsOf->contacts) {
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

void Viewport::drawPush()
{
    if (m_pushBody < 0 || m_pushBody >= static_cast<int>(m_poses.size())) return;
    // a red line from the grabbed point to the target, over everything, a dot at each end
    const Vector3d p1 = bodyPose(m_pushBody) * m_pushPoint;
    const double w = m_geometry->schematicWidth;
    glClear(GL_DEPTH_BUFFER_BIT);
    setTint(kPushRed, 1.0f);
    const double len = (m_pushTarget - p1).norm();
    if (len > 1e-9)
        drawRange(m_geometry->unitCylinder,
                  scaled(Isometry3d(frameAlong(p1, m_pushTarget).matrix()), Vector3d(0.2 * w, 0.2 * w, len)));
    for (const Vector3d& end : {p1, m_pushTarget}) {
        const Vector3d a = end - Vector3d(0, 0, 0.5 * w);
        drawRange(m_geometry->unitCylinder,
                  scaled(Isometry3d(frameAlong(a, a + Vector3d(0, 0, w)).matrix()), Vector3d(0.6 * w, 0.6 * w, w)));
    }
    setTint(Vector3f::Zero(), 0.0f);
}

void Viewport::paintGL()
{
    QElapsedTimer timer;
    timer.start();
    glClearColor(0.2f, 0.21f, 0.23f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!m_glReady) return;
    if (!m_modelMesh.uploaded) upload(m_modelMesh, m_geometry->mesh);
    const bool scene = m_dressing && !m_dressing->mesh.indices.empty();
    if (scene && !m_sceneMesh.uploaded) upload(m_sceneMesh, m_dressing->mesh);
    const SceneGeometry& g = *m_geometry;
    m_lamps = lampCount();
    const bool perVertex = lightsPerVertex();
    Program* solids = program(m_lamps, perVertex);
    if (!solids) return;

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
    sceneSphere(centre, radius);
    m_view = m_camera.viewMatrix().cast<float>();
    // far enough for the grid, and for all of the scene
    double farthest = 1.5 * g.gridExtent;
    if (scene) {
        for (int c = 0; c < 8; ++c) {
            const Vector3d corner = m_dressing->bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
            farthest = std::max(farthest, (corner - centre).norm());
        }
    }
    const Eigen::Matrix4d projection64 = m_camera.projectionMatrix(aspect(), centre, radius, farthest);
    m_projection = projection64.cast<float>();
    m_near = projection64(2, 3) / (projection64(2, 2) - 1);  // (p23 = −2fn/(f−n), p22 = −(f+n)/(f−n))
    // the near plane's visible rectangle, in the world: (±1, ±1, −1) of the clip cube
    const Eigen::Matrix4d unproject = (projection64 * m_view.cast<double>()).inverse();
    for (std::size_t c = 0; c < 4; ++c) {
        const Eigen::Vector4d x = unproject * Eigen::Vector4d(c == 1 || c == 2 ? 1 : -1, c >= 2 ? 1 : -1, -1, 1);
        m_nearQuad[c] = x.head<3>() / x.w();
    }
    useProgram(*solids);

    for (int s = 0; s < g.slotCount(); ++s) {
        m_slotMatrices[static_cast<std::size_t>(s)] = bodyPose(s - 1).matrix().cast<float>();
    }

    // the solids (the model, the scene, the world axes). Lit at every pixel: first their
    // depth alone, then their colour, without depth writes, where they are nearest, so
    // that every pixel is shaded once instead of once per layer of the mill (liners, the
    // shell behind): with the same program and state in both passes the depths are the
    // same, and with GL_LEQUAL the same fragment wins as in a single pass (the last one
    // drawn at the nearest depth). Lit at the vertices, a pixel costs little more than
    // its depth test: one pass.
    const bool schematic = m_mode == DisplayMode::Schematic;
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
    Program* flat = m_showGrid && !scene ? program(m_lamps, false) : nullptr;
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
    if (m_ghost && m_ghost->bundle == m_bundle && m_ghost->bodyPoses.size() == m_poses.size()) {
        glEnable(GL_BLEND);
        // the frame's alpha stays 1: a translucent alpha would make the widget itself
        // translucent when composed (garish colours in grabs and under a compositor)
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        glDepthMask(GL_FALSE);
        setTint(kGhostTint, 0.45f);
        setAlpha(kGhostAlpha);
        for (int s = 1; s < g.slotCount(); ++s) {  // not slot 0: the ground's graphics do not move
            const auto k = static_cast<std::size_t>(s);
            const Matrix4f X = m_ghost->bodyPoses[k - 1].matrix().cast<float>();
            if (schematic) drawRange(g.schematic[k], X);
            else drawRange(g.dressed[k].empty() ? g.bars[k] : g.dressed[k], X);
        }
        setAlpha(1.0f);
        setTint(Vector3f::Zero(), 0.0f);
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

    // contacts on demand, over the model (they are where solids meet, inside both)
    if (m_showContacts) drawContacts();

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

    drawPush();

    m_program->program->release();
    m_modelMesh.vao->release();

    // frame time: until the frame is drawn (software renderers draw at the finish)
    glFinish();
    const double ms = 1e-6 * static_cast<double>(timer.nsecsElapsed());
    m_frameTimes[static_cast<std::size_t>(m_frameCount % static_cast<int>(m_frameTimes.size()))] = ms;
    ++m_frameCount;
    emit frameTimed(ms);
}

Viewport::Program* Viewport::program(int lamps, bool perVertex)
{
    Program& p = (perVertex ? m_vertexPrograms : m_programs)[static_cast<std::size_t>(lamps)];
    if (!p.program && !buildProgram(p, lamps, perVertex)) return nullptr;
    return &p;
}

void Viewport::useProgram(Program& p)
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

int Viewport::lampCount() const
{
    return m_dressing ? std::min(static_cast<int>(m_dressing->lights.size()), kMaxLamps) : 0;
}

void Viewport::setLights(int lamps)
{
    // an interior when the scene has lamps: the daylight dimmed, the lamps lit
    glUniform1f(m_u.daylight, lamps > 0 ? kInteriorDaylight : 1.0f);
    if (lamps > 0) {
        std::array<GLfloat, 3 * kMaxLamps> eye{};
        for (int n = 0; n < lamps; ++n) {
            const Vector3d& p = m_dressing->lights[static_cast<std::size_t>(n)];
            const Vector3f e = (m_view * p.cast<float>().homogeneous()).head<3>();
            for (int k = 0; k < 3; ++k) eye[static_cast<std::size_t>(3 * n + k)] = e[k];
        }
        glUniform3fv(m_u.lightEye, lamps, eye.data());
        glUniform3f(m_u.lightColor, kLampLight.x(), kLampLight.y(), kLampLight.z());
        glUniform1f(m_u.lightRange, kLampRange);
    }
}

void Viewport::drawSolids(bool schematic)
{
    const SceneGeometry& g = *m_geometry;
    // the model
    drawSlots(schematic, !schematic);
    if (schematic) drawActuators(-1);

    // the scene around it
    if (m_dressing && !m_dressing->mesh.indices.empty()) drawScene();

    // world axes at the origin
    const double initialRadius =
        g.initialBounds.isEmpty() ? 1.0 : std::max(0.5 * g.initialBounds.diagonal().norm(), 0.05);
    drawRange(g.unitTriad, scaled(Isometry3d::Identity(), Vector3d::Constant(0.25 * initialRadius)));
}

void Viewport::drawScene()
{
    const SceneDressing& d = *m_dressing;
    // cut away the scene between the eye and the model: everything before a plane
    // through the model's box corner nearest the eye, across the view (an orbit camera
    // outside the mill looks into it) or across the seat's heading (one plane for
    // every screen of the seat, so that they join)
    Vector3d normal = m_camera.forward();
    if (m_camera.mode == Camera::Mode::Seat) {
        normal = Vector3d(std::sin(m_camera.seatHeading), std::cos(m_camera.seatHeading), 0);
    }
    const Vector3d eye = m_camera.eye();
    const Eigen::AlignedBox3d box = sceneBox();
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

double Viewport::frameMillis() const
{
    const int n = std::min(m_frameCount, static_cast<int>(m_frameTimes.size()));
    if (n == 0) return 0;
    std::array<double, 31> t = m_frameTimes;
    std::nth_element(t.begin(), t.begin() + n / 2, t.begin() + n);
    return t[static_cast<std::size_t>(n / 2)];
}

// ---- mouse ---------------------------------------------------------------------------

bool Viewport::pick(const QPointF& pixel, int& body, Vector3d& point) const
{
    if (!m_geometry) return false;
    const Vector3d dir = m_camera.rayThrough(pixel.x(), pixel.y(), width(), height());
    return pickBody(*m_geometry, m_poses, m_camera.eye(), dir, m_mode != DisplayMode::Dressed,
                    m_mode != DisplayMode::Schematic, body, point);
}

void Viewport::mousePressEvent(QMouseEvent* event)
{
    m_lastMouse = event->position().toPoint();
    event->accept();
    if (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ControlModifier) &&
        isSignalConnected(QMetaMethod::fromSignal(&Viewport::pushMoved))) {
        // a push: the body under the cursor, or nothing (no orbit either)
        m_dragging = false;
        int body = -1;
        Vector3d hit;
        if (!pick(event->position(), body, hit)) return;
        m_pushBody = body;
        m_pushPoint = bodyPose(body).inverse() * hit;
        m_pushTarget = m_pushPlane = hit;
        emit pushMoved(m_pushBody, m_pushPoint, m_pushTarget);
        requestFrame();
        return;
    }
    m_dragging = m_pushBody < 0;
}

void Viewport::mouseMoveEvent(QMouseEvent* event)
{
    if (m_pushBody >= 0) {
        // the target: the cursor's point in the plane through the grabbed point facing the camera
        const Vector3d eye = m_camera.eye(), n = m_camera.forward();
        const QPointF p = event->position();
        const Vector3d dir = m_camera.rayThrough(p.x(), p.y(), width(), height());
        const double along = dir.dot(n);
        if (along > 1e-9) {
            m_pushTarget = eye + ((m_pushPlane - eye).dot(n) / along) * dir;
            emit pushMoved(m_pushBody, m_pushPoint, m_pushTarget);
            requestFrame();
        }
        event->accept();
        return;
    }
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
    requestFrame();
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event)
{
    m_dragging = false;
    if (event->button() == Qt::LeftButton) endPush();
    event->accept();
}

void Viewport::endPush()
{
    if (m_pushBody < 0) return;
    m_pushBody = -1;
    emit pushReleased();
    requestFrame();
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
    requestFrame();
    event->accept();
}

}  // namespace studio
