#include "ide/studio/view/overlay_compositor.h"

#include <QChildEvent>
#include <QEvent>
#include <QOpenGLPaintDevice>
#include <QPainter>

#include <utility>
#include <vector>

namespace studio {

OverlayCompositor::OverlayCompositor(QWidget* view) : m_view(view) {}

OverlayCompositor::~OverlayCompositor()
{
    for (const QPointer<QWidget>& o : m_overlays) {
        if (o) watch(o, false);
    }
}

void OverlayCompositor::add(QWidget* widget)
{
    if (!widget || m_overlays.contains(widget)) return;
    m_overlays.append(widget);
    watch(widget, true);
    m_dirty = true;
    emit changed();
}

void OverlayCompositor::remove(QWidget* widget)
{
    if (!widget || !m_overlays.removeOne(widget)) return;
    watch(widget, false);
    m_images.remove(widget);
    emit changed();
}

void OverlayCompositor::watch(QWidget* widget, bool on)
{
    // the overlay and its children: their paint events say that it changed
    QList<QWidget*> widgets = widget->findChildren<QWidget*>();
    widgets.prepend(widget);
    for (QWidget* w : widgets) {
        if (on) w->installEventFilter(this);
        else w->removeEventFilter(this);
    }
}

bool OverlayCompositor::eventFilter(QObject* watched, QEvent* event)
{
    if (!m_rendering && watched != m_view) {
        switch (event->type()) {
        case QEvent::Paint:
        case QEvent::Show:
        case QEvent::Hide:
        case QEvent::Resize:
        case QEvent::Move:
            m_dirty = true;
            emit changed();
            break;
        case QEvent::ChildAdded:
            if (auto* child = qobject_cast<QWidget*>(static_cast<QChildEvent*>(event)->child())) {
                child->installEventFilter(this);
                m_dirty = true;
            }
            break;
        default:
            break;
        }
    }
    return QObject::eventFilter(watched, event);
}

void OverlayCompositor::draw(int w, int h, qreal dpr)
{
    if (m_overlays.isEmpty()) return;
    if (m_dirty) {
        m_images.clear();
        m_dirty = false;
    }
    QWidget* top = m_view->window();
    const QPoint origin = m_view->mapTo(top, QPoint(0, 0));
    std::vector<std::pair<QPoint, const QImage*>> shown;
    for (const QPointer<QWidget>& o : m_overlays) {
        if (!o || !o->isVisible() || o->window() != top || o->size().isEmpty()) continue;
        const QRect r(o->mapTo(top, QPoint(0, 0)) - origin, o->size());
        if (!r.intersects(m_view->rect())) continue;
        QImage& image = m_images[o.data()];
        const QSize pixels = (QSizeF(o->size()) * dpr).toSize();
        if (image.size() != pixels) {
            // the widget as it paints itself (its style sheet's translucent background
            // included), on a transparent image
            image = QImage(pixels, QImage::Format_ARGB32_Premultiplied);
            image.setDevicePixelRatio(dpr);
            image.fill(Qt::transparent);
            m_rendering = true;
            o->render(&image, QPoint(), QRegion(), QWidget::DrawChildren);
            m_rendering = false;
        }
        shown.emplace_back(r.topLeft(), &image);
    }
    if (shown.empty()) return;
    QOpenGLPaintDevice device(w, h);
    device.setDevicePixelRatio(dpr);
    QPainter painter(&device);
    for (const auto& [at, image] : shown) painter.drawImage(at, *image);
}

}  // namespace studio
