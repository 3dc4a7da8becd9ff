#pragma once
// ViewportLayout: the 3D view area, and the operator's screens (thesis §2.3: three
// screens side by side give the operator a feeling of immersion). One, two or three
// Viewports, all showing the same model at the same poses:
//  - one screen (the default): an ordinary viewport, in the camera last chosen with
//    setCamera ("Iso" at first);
//  - two or three: the "Operator seat" camera, each screen turned by its yaw offset
//    (three: −60°, 0°, +60°; two: −30°, +30°; left to right) with a 60° horizontal
//    field of view, so that neighbouring screens join edge to edge, a dark separator
//    between them.
// They sit side by side in this widget, or each in a top-level window of its own (one
// per monitor).

#include "ide/studio/model/model_bundle.h"
#include "ide/studio/sim/snapshot.h"
#include "ide/studio/view/viewport.h"

#include <QList>
#include <QPointer>
#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

class QHBoxLayout;
class QLabel;

namespace studio {

class ViewportLayout : public QWidget {
    Q_OBJECT
public:
    explicit ViewportLayout(QWidget* parent = nullptr);
    ~ViewportLayout() override;

    /// Number of screens, 1 … 3 (clamped). Two or three screens start in the seat camera.
    void setScreens(int count);
    int screens() const { return static_cast<int>(m_views.size()); }
    /// Each screen in a window of its own (full screen on monitor i when there are
    /// enough monitors), or all side by side in this widget.
    void setSeparateWindows(bool separate);
    bool separateWindows() const { return m_separate; }

    /// Screen `index`'s viewport (0 = leftmost), or nullptr.
    Viewport* viewport(int index) const;
    /// The yaw offset of screen `index` of `count` [rad]: 60° apart, centred on 0.
    static double yawOffset(int index, int count);

    // forwarded to every screen
    void setBundle(std::shared_ptr<const ModelBundle> bundle);
    /// The scene drawn around the model on every screen (Viewport::setScene; a bundle
    /// from loadSceneFile), nullptr for none. Kept when the model changes.
    void setScene(std::shared_ptr<const ModelBundle> scene);
    std::shared_ptr<const ModelBundle> scene() const { return m_scene; }
    void setPoses(const std::vector<Eigen::Isometry3d>& X_wb);
    void setSnapshot(std::shared_ptr<const Snapshot> snapshot);
    void setDisplayMode(DisplayMode mode);
    void setOperatorSeat(const Eigen::Vector3d& eye, double yawRad, double pitchRad);
    void setShowFrames(bool show);
    void setShowContacts(bool show);
    void setHighlight(int body, int joint);
    /// A named camera (Viewport::cameraNames()) on every screen; the yaw offsets turn
    /// only the seat camera. False for an unknown name.
    bool setCamera(const QString& name);
    void fitAll();

    /// The slowest screen's median frame time [ms] (Viewport::frameMillis).
    double frameMillis() const;
    /// Every screen draws a frame now and shows it (Viewport::renderNow).
    void renderNow();
    /// A widget over the screens (e.g. a HUD label, a child of this widget), drawn
    /// into the frames of every screen it lies on (Viewport::addOverlay), new ones too.
    void addOverlay(QWidget* widget);

signals:
    /// A problem drawing the model (reported once, by the first screen).
    void problem(const QString& message);
    /// A screen's Ctrl + drag pushes a body (Viewport::pushMoved), or ended (also when
    /// its screen goes).
    void pushMoved(int body, const Eigen::Vector3d& localPoint, const Eigen::Vector3d& target);
    void pushReleased();

protected:
    /// A language change: the texts of this widget and of the separate windows again.
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    Viewport* makeViewport(int index, int count);
    void placeViews();

    std::vector<Viewport*> m_views;
    std::vector<QWidget*> m_windows;  ///< separate windows (empty when side by side)
    QHBoxLayout* m_row = nullptr;
    QLabel* m_elsewhere = nullptr;
    bool m_separate = false;

    // what every new screen gets
    std::shared_ptr<const ModelBundle> m_bundle;
    std::shared_ptr<const ModelBundle> m_scene;
    std::vector<Eigen::Isometry3d> m_poses;
    DisplayMode m_mode = DisplayMode::Dressed;
    struct Seat {
        Eigen::Vector3d eye;
        double yaw, pitch;
    };
    std::optional<Seat> m_seat;
    bool m_showFrames = false;
    bool m_showContacts = false;
    QString m_camera = QStringLiteral("Iso");  ///< of a single screen
    int m_highlightBody = -1, m_highlightJoint = -1;
    QList<QPointer<QWidget>> m_overlays;
};

}  // namespace studio
