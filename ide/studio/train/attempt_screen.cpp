#include "ide/studio/train/attempt_screen.h"

#include "ide/studio/sim/hydraulic_panel.h"
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
    m_hud->setStyleSheet("color: white; font-size: 22px;");
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
    m_hintLabel->setStyleSheet("QLabel { background: rgba(30, 60, 110, 210); color: white; border-radius: 8px; "
                               "padding: 10px 16px; font-size: 22px; }");
    m_hintLabel->setMaximumWidth(900);
    m_hintLabel->hide();
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
        QSettings().setValue("trainer/showExpert", on);
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
        m_expertBox->setToolTip(tr("The demonstration runs beside the attempt, drawn translucent."));
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

void AttemptScreen::prepare()
{
    m_on = true;
    TutorialRunner* runner = m_training->runner();
    const auto demo = m_training->demoLog();
    m_expertBox->setEnabled(demo != nullptr);
    if (demo && m_expertBox->isChecked()) runner->setGhost(demo, m_training->demoProfile());
    m_view->clearGhost();
    m_shownStep = -1;
    m_hudText.clear();
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

void AttemptScreen::retranslate()
{
    m_texts.apply();
    // the HUD, the hints and the warnings at the next frame
    m_shownStep = -1;
    m_hudText.clear();
    m_hintText.clear();
    m_warningText.clear();
}

bool AttemptScreen::eventFilter(QObject* watched, QEvent* event)
{
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
        if (p.distance >= 0)
            lines << tr("Distance: %1 m").arg(num(p.distance, 2)) +
                         (p.withinTolerance ? " <span style='color:#4cd964'>✔</span>" : QString());
        m_dwellBar->setVisible(g.dwell > 0);
        m_dwellBar->setValue(g.dwell > 0 ? int(std::clamp(p.dwell / g.dwell, 0.0, 1.0) * 1000) : 0);
        if (g.dwell > 0) lines << tr("Hold: %1 of %2 s").arg(num(p.dwell, 1), num(g.dwell, 1));
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
            if (st->bankNames.size() > 1)
                lines << tr("Bank: <b>%1</b> (%2 of %3)")
                             .arg(st->bankNames.value(st->activeBank).toHtmlEscaped())
                             .arg(st->activeBank + 1)
                             .arg(st->bankNames.size());
            if (live)
                for (const QString& w : st->warnings) warnings << w.toHtmlEscaped();
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
