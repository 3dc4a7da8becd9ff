#include "ide/studio/view/viewport.h"

#include "ide/studio/view/scene_geometry.h"
#include "ide/studio/view/view_window.h"

#include <QMetaMethod>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>

// the shaders are in studio.qrc, compiled into this static library: register them
// explicitly (a static library's resource initialiser is otherwise never linked in)
static void initStudioResources()
{
    Q_INIT_RESOURCE(studio);
}

namespace studio {

namespace {

int g_samples = 0;  // multisampling of new viewports (Viewport::setSamples)

const QColor kUnderColor(51, 54, 59);  // the view's widget under its window (seen before it first draws)

}  // namespace

Viewport::Viewport(QWidget* parent)
    : QWidget(parent),
      m_renderer([this](ViewRenderer::Problem problem, const QString& log) { glProblem(problem, log); }),
      m_overlays(this),
      m_controller(m_state, *this)
{
    static const bool resources = (initStudioResources(), true);
    Q_UNUSED(resources);
    setMinimumSize(160, 120);
    setFocusPolicy(Qt::ClickFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);
    m_window = new ViewWindow(this, surfaceFormat());
    m_window->initialize = [this] { initializeGl(); };
    m_window->draw = [this](int w, int h, bool overlays) { drawFrame(w, h, overlays); };
    m_window->noOpenGl = [this] { glProblem(ViewRenderer::Problem::NoOpenGl, {}); };
    m_container = QWidget::createWindowContainer(m_window, this);
    m_container->setFocusPolicy(Qt::NoFocus);
    m_container->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_container->setGeometry(rect());
    connect(&m_overlays, &OverlayCompositor::changed, this, &Viewport::requestFrame);
    setBundle(nullptr);
}

Viewport::~Viewport()
{
    releaseGl();
    m_window->destroyContext();  // before its window (m_container's) goes
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
    ViewRenderer::setBackFaceCulling(on);
}

bool Viewport::backFaceCulling()
{
    return ViewRenderer::backFaceCulling();
}

void Viewport::setLighting(Lighting lighting)
{
    ViewRenderer::setLighting(lighting);
}

Viewport::Lighting Viewport::lighting()
{
    return ViewRenderer::lighting();
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

// ---- model and poses ---------------------------------------------------------------

void Viewport::setBundle(std::shared_ptr<const ModelBundle> bundle)
{
    if (bundle && bundle == m_state.bundle && m_state.geometry) return;
    // an edited model (same file) keeps the view the modeler chose
    const bool sameModel = bundle && m_state.bundle && bundle->filePath == m_state.bundle->filePath;
    m_state.bundle = std::move(bundle);
    follow(m_controller.endPush());  // the body pushed is another model's
    m_state.geometry = sceneGeometry(m_state.bundle);
    m_state.poses = m_state.bundle && m_state.bundle->model ? initialPoses(*m_state.bundle->model)
                                                            : std::vector<Eigen::Isometry3d>{};
    m_renderer.modelChanged();
    if (m_state.highlightBody >= m_state.geometry->nb) m_state.highlightBody = -1;
    if (m_state.highlightJoint >= m_state.geometry->nb) m_state.highlightJoint = -1;
    m_controller.modelChanged(sameModel);
    for (const QString& message : m_state.geometry->problems) emit problem(message);
    requestFrame();
}

void Viewport::setScene(std::shared_ptr<const ModelBundle> scene)
{
    if (scene == m_state.scene) return;
    m_state.scene = std::move(scene);
    m_state.dressing = sceneDressing(m_state.scene);
    m_renderer.sceneChanged();
    if (m_state.dressing) {
        for (const QString& message : m_state.dressing->problems) emit problem(message);
    }
    requestFrame();
}

void Viewport::setPoses(const std::vector<Eigen::Isometry3d>& X_wb)
{
    if (!m_state.geometry || static_cast<int>(X_wb.size()) != m_state.geometry->nb) return;
    m_state.poses = X_wb;  // same size: no reallocation
    requestFrame();
}

void Viewport::setSnapshot(std::shared_ptr<const Snapshot> snapshot)
{
    if (!snapshot) return;
    if (snapshot->bundle && snapshot->bundle != m_state.bundle) setBundle(snapshot->bundle);
    m_state.contactsOf = snapshot;
    setPoses(snapshot->bodyPoses);
}

void Viewport::setGhost(std::shared_ptr<const Snapshot> ghost)
{
    if (ghost == m_state.ghost) return;
    m_state.ghost = std::move(ghost);
    requestFrame();
}

void Viewport::clearGhost()
{
    if (!m_state.ghost) return;
    m_state.ghost.reset();
    requestFrame();
}

void Viewport::setDisplayMode(DisplayMode mode)
{
    if (m_state.mode == mode) return;
    m_state.mode = mode;
    requestFrame();
}

void Viewport::setShowContacts(bool show)
{
    m_state.showContacts = show;
    requestFrame();
}

void Viewport::setShowFrames(bool show)
{
    m_state.showFrames = show;
    requestFrame();
}

void Viewport::setShowGrid(bool show)
{
    m_state.showGrid = show;
    requestFrame();
}

void Viewport::setHighlight(int body, int joint)
{
    const int nb = m_state.geometry ? m_state.geometry->nb : 0;
    m_state.highlightBody = body >= 0 && body < nb ? body : -1;
    m_state.highlightJoint = joint >= 0 && joint < nb ? joint : -1;
    requestFrame();
}

// ---- cameras -------------------------------------------------------------------------

QStringList Viewport::cameraNames()
{
    return CameraController::names();
}

QString Viewport::cameraLabel(const QString& name)
{
    if (name == QLatin1String("Iso")) return tr("Iso");
    if (name == QLatin1String("Front")) return tr("Front");
    if (name == QLatin1String("Side")) return tr("Side");
    if (name == QLatin1String("Top")) return tr("Top");
    if (name == CameraController::seatName()) return tr("Operator seat");
    return name;
}

void Viewport::setCameraState(const Camera& camera)
{
    m_controller.setCameraState(camera);
    requestFrame();
}

bool Viewport::setCamera(const QString& name)
{
    if (!m_controller.setCamera(name)) return false;
    requestFrame();
    return true;
}

void Viewport::fitAll()
{
    m_controller.fitAll();
    requestFrame();
}

void Viewport::setOperatorSeat(const Eigen::Vector3d& eye, double yawRad, double pitchRad)
{
    m_controller.setOperatorSeat(eye, yawRad, pitchRad);
    requestFrame();
}

void Viewport::resetOperatorSeat()
{
    m_controller.resetOperatorSeat();
    requestFrame();
}

void Viewport::setYawOffset(double radians)
{
    m_state.camera.yawOffset = radians;
    requestFrame();
}

void Viewport::setSeatFieldOfView(double radians)
{
    m_controller.setSeatFieldOfView(radians);
    requestFrame();
}

// ---- frames ----------------------------------------------------------------------------

void Viewport::requestFrame()
{
    m_window->requestFrame();
}

void Viewport::renderNow()
{
    m_window->renderNow();
}

QImage Viewport::grabFramebuffer()
{
    return m_window->grabFramebuffer();
}

QOpenGLContext* Viewport::context() const
{
    return m_window->context();
}

bool Viewport::makeCurrent()
{
    return m_window->makeCurrent();
}

void Viewport::doneCurrent()
{
    m_window->doneCurrent();
}

void Viewport::initializeGl()
{
    connect(m_window->context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGl,
            Qt::UniqueConnection);
    m_renderer.initialize();
    m_controller.resized();
}

void Viewport::drawFrame(int w, int h, bool overlays)
{
    const double aspect = height() > 0 ? static_cast<double>(width()) / height() : 1.0;
    const double ms = m_renderer.draw(m_state, w, h, aspect);
    if (ms >= 0) emit frameTimed(ms);
    if (overlays) m_overlays.draw(w, h, m_window->devicePixelRatio());
}

void Viewport::releaseGl()
{
    if (!m_window->context() || !m_renderer.holdsGl()) return;
    m_window->makeCurrent();
    m_renderer.release();
    m_window->doneCurrent();
}

void Viewport::glProblem(ViewRenderer::Problem problem, const QString& log)
{
    if (!m_glFailed) {
        emit this->problem(problem == ViewRenderer::Problem::NoOpenGl
                               ? tr("The 3D view needs OpenGL 3.3, which this system does not provide.")
                               : tr("The 3D view's shaders do not build: %1").arg(log));
    }
    m_glFailed = true;
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
    m_controller.resized();
}

// ---- mouse ---------------------------------------------------------------------------

bool Viewport::pick(const QPointF& pixel, int& body, Eigen::Vector3d& point) const
{
    return m_controller.pick(pixel, body, point);
}

void Viewport::follow(CameraController::Change change)
{
    switch (change) {
    case CameraController::Change::None: return;
    case CameraController::Change::Camera: break;
    case CameraController::Change::Push: emit pushMoved(m_state.pushBody, m_state.pushPoint, m_state.pushTarget); break;
    case CameraController::Change::PushEnded: emit pushReleased(); break;
    }
    requestFrame();
}

void Viewport::mousePressEvent(QMouseEvent* event)
{
    follow(m_controller.press(event, isSignalConnected(QMetaMethod::fromSignal(&Viewport::pushMoved))));
}

void Viewport::mouseMoveEvent(QMouseEvent* event)
{
    follow(m_controller.move(event));
}

void Viewport::mouseReleaseEvent(QMouseEvent* event)
{
    follow(m_controller.release(event));
}

void Viewport::mouseDoubleClickEvent(QMouseEvent* event)
{
    fitAll();
    event->accept();
}

void Viewport::wheelEvent(QWheelEvent* event)
{
    follow(m_controller.wheel(event));
}

}  // namespace studio
