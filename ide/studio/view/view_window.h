#pragma once
// ViewWindow: the native window a Viewport holds (QWidget::createWindowContainer), its
// OpenGL context and the pacing of its frames. A frame goes from the context straight
// to swapBuffers, not through Qt's widget composition (on llvmpipe under X, composing a
// QOpenGLWidget into its window and flushing it took longer than drawing the mill).
// Before the window has a native surface (the view was never shown) the context is
// made current on an offscreen surface, where grabFramebuffer() draws into a
// framebuffer object.
//
// What the frames show is the view's: the window calls `initialize` once per context
// and `draw` for every frame. It hands its mouse, wheel and key events to the view (the
// widget), as if they had come to it, and never takes the keyboard focus: the view
// (ClickFocus) does, so the keys go through the widget's event filters.

#include <QElapsedTimer>
#include <QImage>
#include <QSurfaceFormat>
#include <QTimer>
#include <QWindow>

#include <functional>
#include <memory>

class QOffscreenSurface;
class QOpenGLContext;
class QWidget;

namespace studio {

class ViewWindow : public QWindow {
public:
    /// A window for `view` (the widget it fills), of this surface format.
    ViewWindow(QWidget* view, const QSurfaceFormat& format);
    ~ViewWindow() override;

    /// Called with a new context current, before its first frame.
    std::function<void()> initialize;
    /// Draws a frame into the bound framebuffer of w × h device pixels: on screen with
    /// the overlays (true), offscreen without (false).
    std::function<void(int w, int h, bool overlays)> draw;
    /// Called when no OpenGL 3.3 context can be made.
    std::function<void()> noOpenGl;

    /// The context (nullptr before the first makeCurrent()).
    QOpenGLContext* context() const;
    /// Makes the context current (created the first time), on this window, or offscreen
    /// before it has a native one; false when there is no OpenGL 3.3.
    bool makeCurrent();
    void doneCurrent();
    /// Destroys the context and the offscreen surface (before the window goes).
    void destroyContext();

    /// Schedules a frame (drawn at once, or kMinFramePeriodMs after the last one began),
    /// when the window is exposed; else the expose event draws it.
    void requestFrame();
    /// Draws a frame now and shows it (swapBuffers) before returning, when exposed.
    void renderNow();
    /// A frame drawn now, offscreen, at the view's size (`draw` without the overlays);
    /// a null image when there is no OpenGL 3.3.
    QImage grabFramebuffer();

protected:
    bool event(QEvent* event) override;
    void exposeEvent(QExposeEvent* event) override;

private:
    /// The context current, initialized the first time; false without OpenGL 3.3.
    bool prepare();

    QWidget* m_view;
    std::unique_ptr<QOpenGLContext> m_context;
    std::unique_ptr<QOffscreenSurface> m_offscreen;  ///< before the window has a native one
    bool m_initialized = false;                      ///< `initialize` ran in m_context

    // frames: drawn when asked for (requestFrame), at most one per kMinFramePeriodMs
    static constexpr qint64 kMinFramePeriodMs = 15;
    QTimer m_frameTimer;         ///< single shot: the next frame asked for
    QElapsedTimer m_frameClock;  ///< since the last frame on screen began
};

}  // namespace studio
