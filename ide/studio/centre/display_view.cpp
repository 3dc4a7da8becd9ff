#include "ide/studio/centre/display_view.h"

#include "ide/studio/view/viewport.h"
#include "ide/studio/view/viewport_layout.h"
#include "solver/core/data.h"
#include "solver/kinematics/kinematics.h"

#include <QElapsedTimer>
#include <QEvent>
#include <QLabel>
#include <QLocale>
#include <QScreen>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace studio {

double centreClock()
{
    static QElapsedTimer clock = [] {
        QElapsedTimer t;
        t.start();
        return t;
    }();
    return double(clock.nsecsElapsed()) * 1e-9;
}

DisplayView::DisplayView(const DisplayFeed* feed, Screen screen, QWidget* parent)
    : QWidget(parent), m_feed(feed), m_screen(screen), m_view(new Viewport(this)), m_overlay(new QLabel(m_view)),
      m_timer(new QTimer(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_view);
    m_view->setObjectName("DisplayViewport");
    m_view->setSeatFieldOfView(60 * std::numbers::pi / 180);
    m_view->setYawOffset(ViewportLayout::yawOffset(int(screen), 3));
    m_view->setCamera(QStringLiteral("Operator seat"));
    m_overlay->setObjectName("DisplayNotice");
    m_overlay->setAlignment(Qt::AlignCenter);
    m_overlay->setWordWrap(true);
    m_overlay->setStyleSheet(QStringLiteral("QLabel { background: rgba(20, 20, 24, 200); color: white; "
                                            "border-radius: 8px; padding: 16px; font-size: 16pt; }"));
    m_overlay->hide();
    // the view is a native window: a widget over it shows only drawn into its frames
    m_view->addOverlay(m_overlay);
    // at the monitor's rate (the poses between two states are interpolated)
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, [this] { frame(centreClock()); });
    m_timer->start(16);
}

DisplayView::~DisplayView() = default;

void DisplayView::setFeed(const DisplayFeed* feed)
{
    m_feed = feed;
    m_q.clear();
}

void DisplayView::setProblem(const QString& text)
{
    m_problem = text;
    frame(centreClock());
}

QString DisplayView::overlayText() const { return m_overlay->text(); }

void DisplayView::frame(double nowS)
{
    m_lastNow = nowS;
    if (!m_problem.isEmpty() || !m_feed) {
        setOverlay(m_problem);
        return;
    }
    const DisplayFeed& f = *m_feed;
    // the model and the scene, when the feed has others
    if (f.bundle() != m_bundle) {
        m_bundle = f.bundle();
        m_data.reset();
        m_q.clear();
        m_view->setBundle(m_bundle);
        if (m_bundle) {
            m_data = std::make_unique<solver::Data>(*m_bundle->model);
            m_view->resetOperatorSeat();
            m_view->setCamera(QStringLiteral("Operator seat"));
        }
    }
    if (f.scene() != m_scene) {
        m_scene = f.scene();
        m_view->setScene(m_scene);
    }
    // the pose: forward kinematics of the interpolated θ (only when it moved)
    std::vector<double> q;
    if (m_bundle && m_data && f.pose(nowS, q) && q != m_q) {
        const solver::Model& m = *m_bundle->model;
        const Eigen::VectorXd theta = Eigen::Map<const Eigen::VectorXd>(q.data(), Eigen::Index(q.size()));
        solver::forwardKinematics(m, theta, Eigen::VectorXd::Zero(m.nb), *m_data);
        m_view->setPoses(m_data->X_wb);
        m_q = std::move(q);
    }
    // what keeps the picture from being live
    const QString name = QString::fromStdString(f.station());
    QString notice;
    if (!f.problem().isEmpty()) {
        notice = f.problem();
    } else {
        switch (f.presence(nowS)) {
        case DisplayFeed::Presence::Waiting:
            notice = tr("Waiting for station %1…").arg(name);
            break;
        case DisplayFeed::Presence::Silent:
            notice = tr("Station %1 is silent: no state for %2 s.")
                         .arg(name, QLocale().toString(std::floor(nowS - f.buffer().lastArrival()), 'f', 0));
            break;
        case DisplayFeed::Presence::Left:
            notice = tr("Station %1 has left the centre.").arg(name);
            break;
        case DisplayFeed::Presence::Up:
            if (!m_bundle) notice = tr("Waiting for station %1 to announce its model…").arg(name);
            break;
        }
    }
    setOverlay(notice);
}

void DisplayView::setOverlay(const QString& text)
{
    if (text.isEmpty()) {
        if (!m_overlay->isHidden()) m_overlay->hide();
        m_overlay->clear();
        return;
    }
    if (m_overlay->text() != text) {
        m_overlay->setText(text);
        placeOverlay();
    }
    if (m_overlay->isHidden()) {
        m_overlay->show();
        m_overlay->raise();
    }
}

void DisplayView::placeOverlay()
{
    const int w = std::min(m_view->width() - 40, std::max(320, m_view->width() * 2 / 3));
    m_overlay->setFixedWidth(std::max(100, w));
    m_overlay->adjustSize();
    m_overlay->move((m_view->width() - m_overlay->width()) / 2, (m_view->height() - m_overlay->height()) / 2);
}

void DisplayView::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    placeOverlay();
}

void DisplayView::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    // the monitor's rate
    const double rate = screen() ? screen()->refreshRate() : 60.0;
    m_timer->setInterval(std::clamp(int(std::lround(1000.0 / std::clamp(rate, 24.0, 240.0))), 4, 42));
    placeOverlay();
}

void DisplayView::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange) {
        m_overlay->clear();
        frame(m_lastNow);
    }
}

}  // namespace studio
