#pragma once
// DisplayView: one screen of a station as a display node draws it (docs/studio.md
// "Training centre"): a Viewport in the operator's seat camera of the left, centre or
// right screen (ViewportLayout's yaw offsets for three screens), the machine at the pose
// its DisplayFeed interpolates from the State stream, redrawn at the monitor's rate;
// and over it what stops the picture from being live: no model, waiting for the
// station, the station silent or gone. No solver: the poses come by forward kinematics
// from θ.

#include "ide/studio/centre/display_feed.h"

#include <QWidget>

#include <memory>
#include <vector>

class QLabel;
class QTimer;

namespace solver {
struct Data;
}

namespace studio {

class Viewport;

/// A monotonic clock for the centre's GUI nodes [s] (feeds and views agree on it).
double centreClock();

class DisplayView : public QWidget {
    Q_OBJECT
public:
    enum Screen { Left = 0, Centre = 1, Right = 2 };

    /// Shows `feed` (not owned; it must outlive the view, or be cleared with setFeed).
    DisplayView(const DisplayFeed* feed, Screen screen, QWidget* parent = nullptr);
    ~DisplayView() override;

    void setFeed(const DisplayFeed* feed);
    Screen side() const { return m_screen; }
    Viewport* viewport() const { return m_view; }
    /// θ drawn by the last frame (empty before any).
    const std::vector<double>& theta() const { return m_q; }
    /// What is shown over the view ("" when the picture is live).
    QString overlayText() const;
    /// Something the window wants shown over the view instead (a DDS error); "" none.
    void setProblem(const QString& text);

    /// Draws the frame for `nowS` (centreClock()): the model and scene the feed has,
    /// the pose, the notice. Called at the monitor's rate while visible.
    void frame(double nowS);

protected:
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    void setOverlay(const QString& text);
    void placeOverlay();

    const DisplayFeed* m_feed;
    Screen m_screen;
    Viewport* m_view;
    QLabel* m_overlay;
    QTimer* m_timer;
    QString m_problem;
    std::shared_ptr<const ModelBundle> m_bundle, m_scene;
    std::unique_ptr<solver::Data> m_data;
    std::vector<double> m_q;
    double m_lastNow = 0;
};

}  // namespace studio
