#include "ide/studio/train/attempt_screen.h"

#include "ide/studio/sim/hydraulic_panel.h"
#include "ide/studio/station/live_state.h"
#include "ide/studio/train/drive_controls.h"
#include "ide/studio/train/train_ui.h"
#include "ide/studio/train/training_controller.h"
#include "ide/studio/train/tutorial_runner.h"
#include "ide/studio/view/viewport.h"
#include "trainer/station/station.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFrame>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QShortcut>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace studio {

using trainui::num;

AttemptScreen::AttemptScreen(TrainingController* training, QWidget* parent) : QWidget(parent), m_training(training)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* viewBox = new QWidget;
    auto* grid = new QGridLayout(viewBox);
    grid->setContentsMargins(0, 0, 0, 0);
    m_view = new Viewport;
    m_view->setObjectName("AttemptViewport");
    m_view->setFocusPolicy(Qt::StrongFocus);
    m_view->installEventFilter(this);
    grid->addWidget(m_view, 0, 0);

    const QString panel = "background: rgba(20, 24, 28, 200); color: white; border-radius: 8px; padding: 10px 14px;";
    m_hudPanel = new QFrame;
    m_hudPanel->setObjectName("TrainHud");
    m_hudPanel->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_hudPanel->setStyleSheet("QFrame#TrainHud { background: rgba(20, 24, 28, 200); border-radius: 8px; }");
    auto* hudLayout = new QVBoxLayout(m_hudPanel);
    hudLayout->setContentsMargins(14, 10, 14, 12);
    m_hud = new QLabel;
    m_hud->setObjectName("TrainHudText");
    m_hud->setTextFormat(Qt::RichText);
    m_dwellBar = new QProgressBar;
    m_dwellBar->setRange(0, 1000);
    m_dwellBar->setTextVisible(false);
    m_dwellBar->setFixedHeight(14);
    m_dwellBar->setStyleSheet("QProgressBar { background: rgba(255,255,255,40); border: none; border-radius: 4px; }"
                              "QProgressBar::chunk { background: #4cd964; border-radius: 4px; }");
    hudLayout->addWidget(m_hud);
    hudLayout->addWidget(m_dwellBar);
    grid->addWidget(m_hudPanel, 0, 0, Qt::AlignTop | Qt::AlignLeft);
    m_warningLabel = new QLabel;
    m_warningLabel->setObjectName("TrainWarnings");
    m_warningLabel->setTextFormat(Qt::RichText);
    m_warningLabel->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_warningLabel->setStyleSheet("QLabel { " + panel + " font-size: 22px; }");
    m_warningLabel->hide();
    grid->addWidget(m_warningLabel, 0, 0, Qt::AlignTop | Qt::AlignRight);
    m_hintLabel = new QLabel;
    m_hintLabel->setObjectName("TrainHint");
    m_hintLabel->setWordWrap(true);
    m_hintLabel->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_hintLabel->setMaximumWidth(900);
    m_hintLabel->hide();
    scaleHud();
    grid->addWidget(m_hintLabel, 0, 0, Qt::AlignBottom | Qt::AlignHCenter);
    grid->setContentsMargins(0, 0, 0, 0);
    // (over the view's native window they are drawn in its frames: Viewport::addOverlay)
    for (QWidget* w : {static_cast<QWidget*>(m_hudPanel), static_cast<QWidget*>(m_warningLabel),
                       static_cast<QWidget*>(m_hintLabel)}) {
        w->setContentsMargins(0, 0, 0, 0);
        m_view->addOverlay(w);
    }
    // the hydraulics beside the view (never over the target), for a model with pumps
    auto* row = new QHBoxLayout;
    row->setContentsMargins(0, 0, 0, 0);
    row->setSpacing(0);
    row->addWidget(viewBox, 1);
    buildSideScreens(row, viewBox);
    m_hydraulics = new HydraulicPanel;
    m_hydraulics->setObjectName("AttemptHydraulics");
    m_hydraulics->setHeadingVisible(true);
    m_hydraulics->setStyleSheet("QWidget { font-size: 11pt; }");  // (a side panel: smaller than the HUD)
    m_hydraulics->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Preferred);
    m_hydraulics->hide();
    row->addWidget(m_hydraulics);
    layout->addLayout(row, 1);
    // how to drive, below the view (never over the target): the profile's keys and levers
    m_controls = new QLabel;
    m_controls->setObjectName("AttemptControls");
    m_controls->setWordWrap(true);
    m_controls->setTextFormat(Qt::RichText);
    m_controls->setContentsMargins(12, 4, 12, 0);
    m_controls->setStyleSheet("font-size: 11pt;");
    layout->addWidget(m_controls);

    auto* bar = new QHBoxLayout;
    bar->setContentsMargins(12, 6, 12, 6);
    auto* keys = new QLabel;
    bar->addWidget(keys);
    bar->addSpacing(12);
    m_centre = new QLabel;
    m_centre->setObjectName("CentreLink");
    m_centre->hide();
    bar->addWidget(m_centre);
    bar->addStretch();
    m_expertBox = new QCheckBox;
    m_expertBox->setObjectName("ShowExpert");
    m_expertBox->setChecked(QSettings().value("trainer/showExpert", false).toBool());
    connect(m_expertBox, &QCheckBox::toggled, this, [this](bool on) {
        // the studio's own choice; Trainer Mode's is the trainer's (setKiosk)
        if (!m_kiosk) QSettings().setValue("trainer/showExpert", on);
        TutorialRunner* runner = m_training->runner();
        if (m_on && runner->isActive() && !(runner->latest() && runner->latest()->ended))
            runner->setGhost(on ? m_training->demoLog() : nullptr, m_training->demoProfile());
        if (!on) m_view->clearGhost();
        m_view->setFocus();
    });
    bar->addWidget(m_expertBox);
    bar->addSpacing(12);
    m_hydraulicsBox = new QCheckBox;
    m_hydraulicsBox->setObjectName("ShowHydraulics");
    m_hydraulicsBox->setChecked(QSettings().value("trainer/showHydraulics", true).toBool());
    m_hydraulicsBox->hide();
    connect(m_hydraulicsBox, &QCheckBox::toggled, this, [this](bool on) {
        QSettings().setValue("trainer/showHydraulics", on);
        m_hydraulics->setVisible(on && m_hydraulics->hasFluidPower());
        m_view->setFocus();
    });
    connect(m_hydraulics, &HydraulicPanel::modelChanged, this, [this](bool fluid) {
        m_hydraulicsBox->setVisible(fluid);
        m_hydraulics->setVisible(fluid && m_hydraulicsBox->isChecked());
    });
    bar->addWidget(m_hydraulicsBox);
    bar->addSpacing(12);
    auto* viewLabel = new QLabel;
    bar->addWidget(viewLabel);
    m_cameraBox = new QComboBox;
    m_cameraBox->setObjectName("AttemptCamera");
    for (const QString& name : Viewport::cameraNames()) m_cameraBox->addItem(QString(), name);
    m_cameraBox->addItem(QString(), QStringLiteral("ThreeScreens"));  // (attempt_screens.cpp)
    bar->addWidget(m_cameraBox);
    connect(m_cameraBox, &QComboBox::activated, this, [this](int i) {
        setThreeScreens(m_cameraBox->itemData(i).toString() == QLatin1String("ThreeScreens"));
        if (m_three) return m_view->setFocus();
        m_view->setCamera(m_cameraBox->itemData(i).toString());
        if (m_cameraBox->itemData(i).toString() != QLatin1String("Operator seat"))
            trainui::frameModelAndTargets(m_view);
        m_view->setFocus();
    });
    auto* stop = new QPushButton;
    stop->setObjectName("StopButton");
    bar->addWidget(stop);
    m_texts.add([this, keys, viewLabel, stop] {
        keys->setText(tr("Esc or Stop ends the attempt."));
        m_expertBox->setText(tr("Show the expert"));
        m_expertBox->setToolTip(m_kiosk ? tr("Your trainer chooses whether the expert is shown.")
                                        : tr("The demonstration runs beside the attempt, drawn translucent."));
        m_hydraulicsBox->setText(tr("Hydraulics"));
        m_hydraulicsBox->setToolTip(tr("The pump, the spools and the chamber pressures beside the view."));
        viewLabel->setText(tr("View:"));
        for (int i = 0; i < m_cameraBox->count() - 1; ++i)
            m_cameraBox->setItemText(i, Viewport::cameraLabel(m_cameraBox->itemData(i).toString()));
        m_cameraBox->setItemText(m_cameraBox->count() - 1, tr("Three screens (−60°, 0°, +60°)"));
        stop->setText(tr("Stop"));
    });
    layout->addLayout(bar);
    connect(stop, &QPushButton::clicked, this, &AttemptScreen::stopRequested);
    auto* esc = new QShortcut(QKeySequence(Qt::Key_Escape), this);
    esc->setContext(Qt::WidgetWithChildrenShortcut);
    connect(esc, &QShortcut::activated, this, &AttemptScreen::stopRequested);
}

void AttemptScreen::setKiosk(bool kiosk)
{
    m_kiosk = kiosk;
    // (toggled: an attempt under way gets or loses its ghost at once)
    m_expertBox->setChecked(
        QSettings().value(kiosk ? "trainer/kioskShowExpert" : "trainer/showExpert", false).toBool());
    m_expertBox->setEnabled(!kiosk && m_on && m_training->demoLog() != nullptr);
    m_texts.apply();
}

void AttemptScreen::prepare()
{
    m_on = true;
    TutorialRunner* runner = m_training->runner();
    const auto demo = m_training->demoLog();
    if (m_kiosk) {
        // the trainer's choice, read anew for each attempt (set in the records, after the PIN)
        const QSignalBlocker block(m_expertBox);
        m_expertBox->setChecked(QSettings().value("trainer/kioskShowExpert", false).toBool());
    }
    m_expertBox->setEnabled(demo != nullptr && !m_kiosk);
    if (demo && m_expertBox->isChecked()) runner->setGhost(demo, m_training->demoProfile());
    m_view->clearGhost();
    m_shownStep = -1;
    m_hudText.clear();
    showControls();
    // the hydraulics (a model with pumps) beside the view before the view is framed
    if (const auto f = runner->latest()) m_hydraulics->setSnapshot(f->snapshot);
}

void AttemptScreen::aim()
{
    const auto t = m_training->tutorial();
    if (!t) return;
    // inside a scene (or on three screens) the operator's seat; in the open, from where the target shows
    const bool seat = !t->sceneFile.empty() || m_three;
    const QString camera = seat ? QStringLiteral("Operator seat") : QStringLiteral("Iso");
    m_view->resetOperatorSeat();
    m_view->setCamera(camera);
    if (!t->sceneFile.empty()) aimSeatAtFirstGoal(*t);
    if (!seat) QTimer::singleShot(0, m_view, [v = m_view] { trainui::frameModelAndTargets(v); });
    m_cameraBox->setCurrentIndex(std::max(0, m_cameraBox->findData(m_three ? QStringLiteral("ThreeScreens") : camera)));
    setThreeScreens(m_three);
    m_view->setFocus();
}

void AttemptScreen::leave()
{
    m_on = false;
    m_view->clearGhost();
    syncSideScreens();
}

void AttemptScreen::showControls()
{
    const auto t = m_training->tutorial();
    if (!t) return;
    // one line: the drives side by side
    QStringList drives;
    for (const DriveControls& c : driveControls(*t, m_training->profile())) drives << c.text().toHtmlEscaped();
    m_controls->setText("<b>" + tr("Controls:") + "</b> " + drives.join(QStringLiteral(" &nbsp;|&nbsp; ")));
}

void AttemptScreen::retranslate()
{
    m_texts.apply();
    showControls();
    // the HUD, the hints and the warnings at the next frame
    m_shownStep = -1;
    m_hudText.clear();
    m_hintText.clear();
    m_warningText.clear();
}

bool AttemptScreen::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_view && event->type() == QEvent::Resize) scaleHud();
    if (watched == m_view && event->type() == QEvent::KeyPress &&
        static_cast<QKeyEvent*>(event)->key() == Qt::Key_Escape) {
        emit stopRequested();
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

void AttemptScreen::showFrame(const TrainFrame& f)
{
    if (f.snapshot->step != m_shownStep) {
        m_shownStep = f.snapshot->step;
        m_view->setSnapshot(f.snapshot);
        m_hydraulics->setSnapshot(f.snapshot);
        if (f.ghost && m_expertBox->isChecked()) m_view->setGhost(f.ghost);
        else m_view->clearGhost();
        syncSideScreens();
    }
    updateHud(f);
    placeHud(f);
}

void AttemptScreen::scaleHud()
{
    // 22 px from a 900-pixel-high view up, down to 16 px
    const int px = std::clamp(m_view->height() / 40, 16, 22);
    if (!m_hud || !m_hintLabel || px == m_hudFontPx) return;
    m_hudFontPx = px;
    m_hud->setStyleSheet(QStringLiteral("color: white; font-size: %1px;").arg(px));
    m_hintLabel->setStyleSheet(QStringLiteral("QLabel { background: rgba(30, 60, 110, 210); color: white; "
                                              "border-radius: 8px; padding: 8px 14px; font-size: %1px; }")
                                   .arg(px));
}

void AttemptScreen::placeHud(const TrainFrame& f)
{
    const auto t = m_training->tutorial();
    if (!t || !f.snapshot) return;
    const auto& goals = t->spec.goals;
    const int g = f.progress.goal;
    if (g < 0 || g >= int(goals.size())) return;
    // the goal's point: its target, or the load to grasp where it is now
    const trainer::Goal& goal = goals[std::size_t(g)];
    Eigen::Vector3d point;
    if (goal.kind == trainer::Goal::Kind::Reach || goal.kind == trainer::Goal::Kind::Place) {
        point = goal.target;
    } else if (goal.kind == trainer::Goal::Kind::Grasp) {
        const int i = t->model->bodyIndex(t->spec.grip.loadBodyId);
        if (i < 0 || std::size_t(i) >= f.snapshot->bodyPoses.size()) return;
        point = f.snapshot->bodyPoses[std::size_t(i)] * t->spec.grip.loadPoint;
    } else {
        return;
    }
    Eigen::Vector2d pixel;
    if (!m_view->cameraState().pixelOf(point, m_view->width(), m_view->height(), pixel)) return;
    const QPoint at(int(pixel.x()), int(pixel.y()));
    // the corner the HUD is in, with a margin for the target's sphere and arrow
    constexpr int kMargin = 60;
    const QSize size = m_hudPanel->sizeHint();
    const QRect top(QPoint(0, 0), size), low(QPoint(0, m_view->height() - size.height()), size);
    bool lowNow = m_hudLow;
    if (!m_hudLow && top.adjusted(-kMargin, -kMargin, kMargin, kMargin).contains(at)) lowNow = true;
    else if (m_hudLow && low.adjusted(-kMargin, -kMargin, kMargin, kMargin).contains(at) &&
             !top.adjusted(-kMargin, -kMargin, kMargin, kMargin).contains(at))
        lowNow = false;
    if (lowNow == m_hudLow) return;
    m_hudLow = lowNow;
    auto* grid = static_cast<QGridLayout*>(m_hudPanel->parentWidget()->layout());
    grid->setAlignment(m_hudPanel, (m_hudLow ? Qt::AlignBottom : Qt::AlignTop) | Qt::AlignLeft);
    grid->setAlignment(m_hintLabel, (m_hudLow ? Qt::AlignTop : Qt::AlignBottom) | Qt::AlignHCenter);
}

void AttemptScreen::updateHud(const TrainFrame& f)
{
    const auto t = m_training->tutorial();
    if (!t) return;
    const std::string lang = TrainingController::language().toStdString();
    const trainer::SessionProgress& p = f.progress;
    const auto& goals = t->spec.goals;
    QStringList lines;
    if (p.goal < int(goals.size())) {
        const trainer::Goal& g = goals[std::size_t(p.goal)];
        lines << "<span style='font-size:26px; font-weight:bold'>" +
                     QString::fromStdString(g.name.in(lang)).toHtmlEscaped() + "</span>";
        if (goals.size() > 1) lines << tr("Goal %1 of %2").arg(p.goal + 1).arg(goals.size());
        lines << goalLines(g, p);
        m_dwellBar->setVisible(g.dwell > 0);
        m_dwellBar->setValue(g.dwell > 0 ? int(std::clamp(p.dwell / g.dwell, 0.0, 1.0) * 1000) : 0);
    } else {
        lines << "<span style='font-size:26px; font-weight:bold'>" + tr("All goals done") + "</span>";
        m_dwellBar->hide();
    }
    lines << tr("Time: %1 / %2 s").arg(num(p.t, 1), num(t->scoring().timeLimit, 0));
    if (p.penalties > 0)
        lines << "<span style='color:#ff8a80'>" + tr("Penalties: %1").arg(num(p.penalties, 0)) + "</span>";
    if (p.grasped) lines << tr("Load in the claws");
    // the station: bank and its warnings
    const bool live = m_training->attemptLive();
    QStringList warnings;
    if (trainer::Station* station = m_training->station()) {
        if (const auto st = station->latest()) {
            if (const QString bank = hudBankLine(*st); !bank.isEmpty()) lines << bank;
            if (live)
                for (const QString& w : hudWarnings(*st)) warnings << w.toHtmlEscaped();
        }
    }
    if (f.paused && live && !f.ended) warnings << tr("Paused by the instructor");
    if (p.overload) warnings << tr("Overload: a relief valve is open");
    if (p.nearWorker) warnings << tr("Too close to a worker (%1 m)").arg(num(p.workerDistance, 2));
    if (p.clearance >= 0 && p.clearance < t->scoring().nearDistance)
        warnings << tr("Clearance %1 m").arg(num(p.clearance, 2));
    const QString text = lines.join("<br>");
    if (text != m_hudText) {
        m_hudText = text;
        m_hud->setText(text);
    }
    QString w;
    for (const QString& s : warnings)
        w += (w.isEmpty() ? "" : "<br>") + QStringLiteral("<span style='color:#ffc04d'>⚠ %1</span>").arg(s);
    if (w != m_warningText) {
        m_warningText = w;
        m_warningLabel->setText(w);
        m_warningLabel->setVisible(!w.isEmpty());
    }
    QStringList hints;
    for (int h : p.hints)
        if (h >= 0 && h < int(t->spec.hints.size()))
            hints << QString::fromStdString(t->spec.hints[std::size_t(h)].text.in(lang));
    const QString hint = hints.join("\n");
    if (hint != m_hintText) {
        m_hintText = hint;
        m_hintLabel->setText(hint);
        m_hintLabel->setVisible(!hint.isEmpty());
    }
}

QStringList AttemptScreen::goalLines(const trainer::Goal& g, const trainer::SessionProgress& p)
{
    const QString ok = QStringLiteral(" <span style='color:#4cd964'>✔</span>");
    const auto degrees = [](double rad) { return num(rad * 180.0 / M_PI, 0); };
    QStringList lines;
    if (p.distance >= 0) lines << tr("Distance: %1 m").arg(num(p.distance, 2)) + (p.positioned ? ok : QString());
    // a goal with ALIGN (the head pointing like the arrow): how far it is turned from it
    const bool aligned = p.angleError < 0 || p.angleError <= p.angleTolerance;
    if (p.angleError >= 0)
        lines << tr("Angle: %1° off (within %2°)").arg(degrees(p.angleError), degrees(p.angleTolerance)) +
                     (aligned ? ok : QString());
    if (g.dwell <= 0) return lines;
    // the hold: how much longer, or what it waits for
    if (p.withinTolerance) {
        lines << tr("Hold: %1 s more").arg(num(std::max(0.0, g.dwell - p.dwell), 1));
        return lines;
    }
    QStringList waiting;
    if (p.distance >= 0 && !p.positioned) waiting << tr("come within %1 m").arg(num(g.tolerance, 2));
    if (!aligned)
        waiting << (g.kind == trainer::Goal::Kind::Place ? tr("align the load: %1° off") : tr("align the head: %1° off"))
                       .arg(degrees(p.angleError));
    if (g.kind == trainer::Goal::Kind::Place && !p.grasped) waiting << tr("hold the load in the claws");
    lines << (waiting.isEmpty() ? tr("Hold %1 s").arg(num(g.dwell, 1))
                                : tr("Hold %1 s once you %2").arg(num(g.dwell, 1), waiting.join(tr(" and "))));
    return lines;
}

void AttemptScreen::aimSeatAtFirstGoal(const trainer::Tutorial& t)
{
    // where the first goal is: its target, or the load to grasp (where it is now)
    if (t.spec.goals.empty()) return;
    const trainer::Goal& g = t.spec.goals.front();
    const auto f = m_training->runner()->latest();
    Eigen::Vector3d p;
    if (g.kind == trainer::Goal::Kind::Reach || g.kind == trainer::Goal::Kind::Place) {
        p = g.target;
    } else if (g.kind == trainer::Goal::Kind::Grasp) {
        const int i = t.model->bodyIndex(t.spec.grip.loadBodyId);
        if (!f || !f->snapshot || i < 0 || std::size_t(i) >= f->snapshot->bodyPoses.size()) return;
        p = f->snapshot->bodyPoses[std::size_t(i)] * t.spec.grip.loadPoint;
    } else {
        return;
    }
    // and the tool that goes there: the seat looks between the two
    const auto worldPoint = [&](int bodyId, const Eigen::Vector3d& local, Eigen::Vector3d& out) {
        const int i = t.model->bodyIndex(bodyId);
        if (!f || !f->snapshot || i < 0 || std::size_t(i) >= f->snapshot->bodyPoses.size()) return false;
        out = f->snapshot->bodyPoses[std::size_t(i)] * local;
        return true;
    };
    Eigen::Vector3d tool;
    const bool hasTool = g.kind == trainer::Goal::Kind::Reach
                             ? worldPoint(g.bodyId, g.point, tool)
                             : worldPoint(t.spec.grip.toolBodyId, t.spec.grip.toolPoint, tool);
    // when the goal is outside the middle of the view, the seat turns (the operator turns
    // their head) to see the goal and the tool, or at least the goal; its place and
    // pitch stay
    const Camera& c = m_view->cameraState();
    const auto headingTo = [&](const Eigen::Vector3d& q) {
        const Eigen::Vector3d d = q - c.seatEye;
        return std::atan2(d.x(), d.y());  // 0 = +y, positive to the right (+x)
    };
    if ((p - c.seatEye).head<2>().norm() < 0.5) return;
    const double half = 0.5 * c.seatFieldOfView;
    const double toGoal = std::remainder(headingTo(p) - c.seatHeading, 2 * M_PI);
    if (std::abs(toGoal) < 0.7 * half) return;
    double turn = toGoal;
    if (hasTool) {
        const double toTool = std::remainder(headingTo(tool) - c.seatHeading, 2 * M_PI);
        turn = 0.5 * (toGoal + toTool);
        // the goal at most 0.8 of the half-field from the middle
        turn = std::clamp(turn, toGoal - 0.8 * half, toGoal + 0.8 * half);
    }
    m_view->setOperatorSeat(c.seatEye, c.seatHeading + turn, c.seatPitch);
}

}  // namespace studio
