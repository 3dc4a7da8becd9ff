#include "ide/studio/view/viewport_layout.h"

#include <QEvent>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QPalette>
#include <QLabel>
#include <QScreen>

#include <algorithm>
#include <numbers>

namespace studio {

namespace {
constexpr double kScreenAngle = 60 * std::numbers::pi / 180;  // between neighbouring screens
}

ViewportLayout::ViewportLayout(QWidget* parent) : QWidget(parent)
{
    m_row = new QHBoxLayout(this);
    m_row->setContentsMargins(0, 0, 0, 0);
    // screens side by side: a dark separator between them, as the monitors' bezels
    m_row->setSpacing(6);
    QPalette dark = palette();
    dark.setColor(QPalette::Window, QColor(0x15, 0x18, 0x1b));
    dark.setColor(QPalette::WindowText, QColor(0xd0, 0xd4, 0xd8));
    setPalette(dark);
    setAutoFillBackground(true);
    m_elsewhere = new QLabel(this);
    m_elsewhere->setAlignment(Qt::AlignCenter);
    m_elsewhere->hide();
    setScreens(1);
    retranslate();
}

void ViewportLayout::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void ViewportLayout::retranslate()
{
    m_elsewhere->setText(tr("The operator's screens are shown in separate windows."));
    const int count = static_cast<int>(m_windows.size());
    for (int i = 0; i < count; ++i)
        m_windows[static_cast<std::size_t>(i)]->setWindowTitle(tr("Operator screen %1 of %2").arg(i + 1).arg(count));
}

ViewportLayout::~ViewportLayout()
{
    // the viewports go before their windows (both are children of this widget)
    for (Viewport* v : m_views) delete v;
    m_views.clear();
    for (QWidget* w : m_windows) delete w;
    m_windows.clear();
}

double ViewportLayout::yawOffset(int index, int count)
{
    return (index - 0.5 * (count - 1)) * kScreenAngle;
}

Viewport* ViewportLayout::viewport(int index) const
{
    return index >= 0 && index < screens() ? m_views[static_cast<std::size_t>(index)] : nullptr;
}

Viewport* ViewportLayout::makeViewport(int index, int count)
{
    auto* v = new Viewport(this);
    v->setDisplayMode(m_mode);
    v->setBundle(m_bundle);
    v->setScene(m_scene);
    if (!m_poses.empty()) v->setPoses(m_poses);
    if (m_seat) v->setOperatorSeat(m_seat->eye, m_seat->yaw, m_seat->pitch);
    v->setSeatFieldOfView(kScreenAngle);
    v->setYawOffset(yawOffset(index, count));
    v->setCamera(count == 1 ? m_camera : QStringLiteral("Operator seat"));
    v->setShowFrames(m_showFrames);
    v->setShowContacts(m_showContacts);
    v->setHighlight(m_highlightBody, m_highlightJoint);
    if (index == 0) connect(v, &Viewport::problem, this, &ViewportLayout::problem);
    connect(v, &Viewport::pushMoved, this, &ViewportLayout::pushMoved);
    connect(v, &Viewport::pushReleased, this, &ViewportLayout::pushReleased);
    for (const QPointer<QWidget>& o : m_overlays) {
        if (o) v->addOverlay(o);
    }
    return v;
}

void ViewportLayout::setScreens(int count)
{
    count = std::clamp(count, 1, 3);
    if (count == screens()) return;
    bool pushing = false;
    for (Viewport* v : m_views) pushing = pushing || v->pushedBody() >= 0;
    if (pushing) emit pushReleased();  // its view goes
    for (Viewport* v : m_views) delete v;
    m_views.clear();
    for (int i = 0; i < count; ++i) m_views.push_back(makeViewport(i, count));
    placeViews();
}

void ViewportLayout::setSeparateWindows(bool separate)
{
    if (separate == m_separate) return;
    m_separate = separate;
    placeViews();
}

void ViewportLayout::placeViews()
{
    // take the views out of wherever they are, then put them in the row or in windows
    for (Viewport* v : m_views) {
        m_row->removeWidget(v);
        v->setParent(this);
    }
    m_row->removeWidget(m_elsewhere);
    for (QWidget* w : m_windows) delete w;
    m_windows.clear();
    if (!m_separate) {
        m_elsewhere->hide();
        for (Viewport* v : m_views) {
            m_row->addWidget(v, 1);
            v->show();
        }
        return;
    }
    m_row->addWidget(m_elsewhere);
    m_elsewhere->show();
    const QList<QScreen*> monitors = QGuiApplication::screens();
    const int count = screens();
    for (int i = 0; i < count; ++i) {
        auto* window = new QWidget(this, Qt::Window);
        auto* layout = new QHBoxLayout(window);
        layout->setContentsMargins(0, 0, 0, 0);
        Viewport* v = m_views[static_cast<std::size_t>(i)];
        v->setParent(window);
        layout->addWidget(v);
        v->show();
        m_windows.push_back(window);
        if (monitors.size() >= count) {
            window->setGeometry(monitors[i]->geometry());
            window->showFullScreen();
        } else {
            window->resize(640, 480);
            window->move(i * 660, 0);
            window->show();
        }
    }
    retranslate();  // the windows' titles
}

void ViewportLayout::setBundle(std::shared_ptr<const ModelBundle> bundle)
{
    m_bundle = std::move(bundle);
    m_poses.clear();
    for (Viewport* v : m_views) v->setBundle(m_bundle);
}

void ViewportLayout::setScene(std::shared_ptr<const ModelBundle> scene)
{
    m_scene = std::move(scene);
    for (Viewport* v : m_views) v->setScene(m_scene);
}

void ViewportLayout::setPoses(const std::vector<Eigen::Isometry3d>& X_wb)
{
    m_poses = X_wb;
    for (Viewport* v : m_views) v->setPoses(X_wb);
}

void ViewportLayout::setSnapshot(std::shared_ptr<const Snapshot> snapshot)
{
    if (!snapshot) return;
    if (snapshot->bundle && snapshot->bundle != m_bundle) setBundle(snapshot->bundle);
    setPoses(snapshot->bodyPoses);
}

void ViewportLayout::setDisplayMode(DisplayMode mode)
{
    m_mode = mode;
    for (Viewport* v : m_views) v->setDisplayMode(mode);
}

void ViewportLayout::setOperatorSeat(const Eigen::Vector3d& eye, double yawRad, double pitchRad)
{
    m_seat = Seat{eye, yawRad, pitchRad};
    for (Viewport* v : m_views) v->setOperatorSeat(eye, yawRad, pitchRad);
}

void ViewportLayout::setShowContacts(bool show)
{
    m_showContacts = show;
    for (Viewport* v : m_views) v->setShowContacts(show);
}

void ViewportLayout::setShowFrames(bool show)
{
    m_showFrames = show;
    for (Viewport* v : m_views) v->setShowFrames(show);
}

bool ViewportLayout::setCamera(const QString& name)
{
    if (!Viewport::cameraNames().contains(name)) return false;
    m_camera = name;
    for (Viewport* v : m_views) v->setCamera(name);
    return true;
}

void ViewportLayout::fitAll()
{
    for (Viewport* v : m_views) v->fitAll();
}

double ViewportLayout::frameMillis() const
{
    double slowest = 0;
    for (const Viewport* v : m_views) slowest = std::max(slowest, v->frameMillis());
    return slowest;
}

void ViewportLayout::renderNow()
{
    for (Viewport* v : m_views) v->renderNow();
}

void ViewportLayout::addOverlay(QWidget* widget)
{
    if (!widget || m_overlays.contains(widget)) return;
    m_overlays.append(widget);
    for (Viewport* v : m_views) v->addOverlay(widget);
}

void ViewportLayout::setHighlight(int body, int joint)
{
    m_highlightBody = body;
    m_highlightJoint = joint;
    for (Viewport* v : m_views) v->setHighlight(body, joint);
}

}  // namespace studio
