#include "ide/studio/view/view_window.h"

#include <QCoreApplication>
#include <QExposeEvent>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QWidget>

#include <algorithm>

namespace studio {

ViewWindow::ViewWindow(QWidget* view, const QSurfaceFormat& format) : m_view(view)
{
    setSurfaceType(QSurface::OpenGLSurface);
    setFormat(format);
    setFlag(Qt::WindowDoesNotAcceptFocus);
    m_frameTimer.setSingleShot(true);
    m_frameTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_frameTimer, &QTimer::timeout, this, &ViewWindow::renderNow);
}

ViewWindow::~ViewWindow()
{
    destroyContext();
}

bool ViewWindow::event(QEvent* event)
{
    switch (event->type()) {
    case QEvent::UpdateRequest:
        renderNow();
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

void ViewWindow::exposeEvent(QExposeEvent*)
{
    if (isExposed()) renderNow();
}

QOpenGLContext* ViewWindow::context() const
{
    return m_context.get();
}

bool ViewWindow::makeCurrent()
{
    if (!m_context) {
        m_context = std::make_unique<QOpenGLContext>();
        m_context->setFormat(requestedFormat());
        if (!m_context->create()) {
            m_context.reset();
            noOpenGl();
            return false;
        }
        m_initialized = false;
    }
    if (handle()) return m_context->makeCurrent(this);
    // no native window yet (the view was never shown): an offscreen surface
    if (!m_offscreen) {
        m_offscreen = std::make_unique<QOffscreenSurface>();
        m_offscreen->setFormat(m_context->format());
        m_offscreen->create();
    }
    return m_context->makeCurrent(m_offscreen.get());
}

void ViewWindow::doneCurrent()
{
    if (m_context) m_context->doneCurrent();
}

void ViewWindow::destroyContext()
{
    m_context.reset();
    m_offscreen.reset();
}

bool ViewWindow::prepare()
{
    if (!makeCurrent()) return false;
    if (!m_initialized) {
        m_initialized = true;
        initialize();
    }
    return true;
}

void ViewWindow::requestFrame()
{
    // not exposed: the expose event draws. Else at once, or kMinFramePeriodMs after the
    // last frame began, whichever is later: QWindow::requestUpdate would wait for the
    // platform's next update tick (1000 / refresh rate ms, a whole frame at 60 Hz), so
    // that a frame asked for by the 60 Hz poll was drawn up to 16 ms late, and a frame
    // that takes 14 ms to draw came every 22 ms instead of every 16.7
    if (!isExposed() || m_frameTimer.isActive()) return;
    const qint64 since = m_frameClock.isValid() ? m_frameClock.elapsed() : kMinFramePeriodMs;
    m_frameTimer.start(static_cast<int>(std::max<qint64>(0, kMinFramePeriodMs - since)));
}

void ViewWindow::renderNow()
{
    if (!isExposed() || !prepare()) return;
    const qreal dpr = devicePixelRatio();
    const QSize pixels = (QSizeF(size()) * dpr).toSize();
    if (pixels.isEmpty()) return;
    m_frameTimer.stop();  // this frame shows what was asked for
    m_frameClock.start();
    m_context->functions()->glBindFramebuffer(GL_FRAMEBUFFER, m_context->defaultFramebufferObject());
    draw(pixels.width(), pixels.height(), true);
    m_context->swapBuffers(this);
}

QImage ViewWindow::grabFramebuffer()
{
    if (!prepare()) return {};
    const qreal dpr = m_view->devicePixelRatioF();
    const QSize pixels = (QSizeF(m_view->size()) * dpr).toSize().expandedTo(QSize(1, 1));
    QOpenGLFramebufferObjectFormat format;
    format.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);
    format.setSamples(m_context->format().samples() > 0 ? m_context->format().samples() : 0);
    QOpenGLFramebufferObject fbo(pixels, format);
    if (!fbo.isValid() || !fbo.bind()) return {};
    draw(pixels.width(), pixels.height(), false);
    QImage image = fbo.toImage();
    fbo.release();
    image.setDevicePixelRatio(dpr);
    return image;
}

}  // namespace studio
