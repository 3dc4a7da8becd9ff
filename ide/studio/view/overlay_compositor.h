#pragma once
// OverlayCompositor: the widgets shown over a view (siblings or children of an
// ancestor, e.g. a HUD label) drawn into its frames. The view's native window
// (ViewWindow) would hide them, so their pictures are drawn into each frame, where the
// widgets lie, whenever they are visible; an overlay is rendered to an image again when
// it (or a child) paints, shows, hides, moves or resizes. Their on-screen geometry
// stays Qt's (layouts, tests and grab() see them as before).

#include <QHash>
#include <QImage>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QWidget>

namespace studio {

class OverlayCompositor : public QObject {
    Q_OBJECT
public:
    /// The compositor of `view`'s frames.
    explicit OverlayCompositor(QWidget* view);
    ~OverlayCompositor() override;

    void add(QWidget* widget);
    void remove(QWidget* widget);
    /// Draws the visible overlays into the bound framebuffer of w × h device pixels
    /// (the view's frame, the current OpenGL context's) at `dpr` device pixels per pixel.
    void draw(int w, int h, qreal dpr);

signals:
    /// An overlay was added, removed, or changed: the view needs a new frame.
    void changed();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void watch(QWidget* widget, bool on);

    QWidget* m_view;
    QList<QPointer<QWidget>> m_overlays;
    QHash<QWidget*, QImage> m_images;  ///< each overlay's last picture
    bool m_dirty = true;               ///< the pictures are to be rendered again
    bool m_rendering = false;          ///< rendering them (their paint events are ours)
};

}  // namespace studio
