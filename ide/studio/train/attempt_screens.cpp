// AttemptScreen's three screens (thesis §2.3: screens side by side around the operator
// give a feeling of immersion): the seat's view in the middle (the attempt's own view,
// with the HUD and the keys) and a screen on each side turned −60° and +60° (as the Model
// workspace's View ▸ Screens ▸ 3, ViewportLayout::yawOffset), each 60° wide (the seat's
// field of view), so that
// neighbouring screens join edge to edge, with a dark separator between them. The rest
// of the screen is in attempt_screen.cpp.

#include "ide/studio/train/attempt_screen.h"

#include "ide/studio/view/viewport.h"
#include "ide/studio/view/viewport_layout.h"

#include <QFrame>
#include <QHBoxLayout>
#include <QSettings>

namespace studio {

namespace {

constexpr const char* kSeat = "Operator seat";

}  // namespace

void AttemptScreen::buildSideScreens(QHBoxLayout* row, QWidget* viewBox)
{
    const auto separator = [this] {
        auto* line = new QFrame;
        line->setObjectName("ScreenSeparator");
        line->setFixedWidth(6);
        line->setStyleSheet("QFrame#ScreenSeparator { background: #15181b; }");
        m_sideParts << line;
        return line;
    };
    const auto side = [this](const char* name, int index) {
        auto* v = new Viewport;
        v->setObjectName(QString::fromLatin1(name));
        v->setFocusPolicy(Qt::NoFocus);  // the keys stay with the middle screen
        v->setYawOffset(ViewportLayout::yawOffset(index, 3));
        m_sideParts << v;
        return v;
    };
    m_left = side("AttemptLeftScreen", 0);
    m_right = side("AttemptRightScreen", 2);
    const int at = row->indexOf(viewBox);
    row->insertWidget(at, separator());
    row->insertWidget(at, m_left, 1);
    row->insertWidget(at + 3, separator());
    row->insertWidget(at + 4, m_right, 1);
    for (QWidget* w : m_sideParts) w->hide();
    m_three = QSettings().value("trainer/threeScreens", false).toBool();
}

Viewport* AttemptScreen::screen(int i) const
{
    switch (i) {
    case 0: return m_left;
    case 1: return m_view;
    case 2: return m_right;
    default: return nullptr;
    }
}

void AttemptScreen::setThreeScreens(bool on)
{
    m_three = on;
    QSettings().setValue("trainer/threeScreens", on);
    for (QWidget* w : m_sideParts) w->setVisible(on);
    if (on) {
        m_view->setCamera(QString::fromLatin1(kSeat));
        syncSideScreens();
    }
}

void AttemptScreen::syncSideScreens()
{
    if (!m_three) return;
    const Camera& c = m_view->cameraState();
    for (Viewport* v : {m_left, m_right}) {
        if (v->bundle() != m_view->bundle()) v->setBundle(m_view->bundle());
        if (v->scene() != m_view->scene()) v->setScene(m_view->scene());
        v->setDisplayMode(m_view->displayMode());
        v->setOperatorSeat(c.seatEye, c.seatHeading, c.seatPitch);
        if (v->camera() != QLatin1String(kSeat)) v->setCamera(QString::fromLatin1(kSeat));
        v->setPoses(m_view->poses());
        if (m_view->ghost()) v->setGhost(m_view->ghost());
        else v->clearGhost();
    }
}

}  // namespace studio
