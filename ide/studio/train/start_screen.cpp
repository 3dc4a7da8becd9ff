#include "ide/studio/train/start_screen.h"

#include "ide/studio/train/drive_controls.h"
#include "ide/studio/train/lever_bars.h"
#include "ide/studio/train/train_ui.h"
#include "ide/studio/train/training_controller.h"
#include "ide/studio/train/tutorial_runner.h"
#include "ide/studio/view/viewport.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSlider>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>

namespace studio {

namespace {
constexpr double kSpeeds[] = {0.25, 0.5, 1.0, 2.0, 4.0};
}

StartScreen::StartScreen(TrainingController* training, QWidget* parent) : QWidget(parent), m_training(training)
{
    TutorialRunner* runner = m_training->runner();
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(24, 24, 24, 24);
    auto* left = new QVBoxLayout;
    m_title = new QLabel;
    m_title->setObjectName("TrainTitle");
    m_title->setWordWrap(true);
    m_intro = trainui::wrapped();
    m_intro->setTextFormat(Qt::RichText);
    m_intro->setStyleSheet("font-size: 15pt;");
    m_intro->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    // how to drive: the keys and levers of the profile for this stage's drives
    m_controls = trainui::wrapped();
    m_controls->setObjectName("StartControls");
    m_controls->setTextFormat(Qt::RichText);
    m_controls->setStyleSheet("font-size: 12pt;");
    left->addWidget(m_title);
    left->addWidget(m_intro, 1);
    left->addWidget(m_controls);
    m_watchButton = new QPushButton;
    m_startButton = new QPushButton;
    m_startButton->setObjectName("StartButton");
    m_startButton->setStyleSheet("font-size: 18pt; font-weight: bold; padding: 10px 30px;");
    auto* back = new QPushButton;
    m_texts.add([this, back] {
        m_watchButton->setText(tr("Watch the demonstration"));
        m_startButton->setText(tr("Start"));
        back->setText(tr("Back to the course"));
    });
    left->addWidget(m_watchButton);
    left->addWidget(m_startButton);
    left->addWidget(back);
    auto* leftBox = new QWidget;
    leftBox->setLayout(left);
    leftBox->setMinimumWidth(380);
    leftBox->setMaximumWidth(560);
    layout->addWidget(leftBox);

    auto* right = new QVBoxLayout;
    m_view = new Viewport;
    m_view->setMinimumSize(480, 360);
    // the expert's levers over the replay (drawn into the view's frames)
    auto* viewBox = new QWidget;
    auto* grid = new QGridLayout(viewBox);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(m_view, 0, 0);
    m_bars = new LeverBars;
    grid->addWidget(m_bars, 0, 0, Qt::AlignTop | Qt::AlignRight);
    m_view->addOverlay(m_bars);
    right->addWidget(viewBox, 1);
    auto* controls = new QHBoxLayout;
    m_play = new QPushButton;
    m_play->setEnabled(false);
    m_texts.add([this, runner] { m_play->setText(m_demoRunning && !runner->isPaused() ? tr("Pause") : tr("Play")); });
    m_speed = new QComboBox;
    for (double s : kSpeeds) m_speed->addItem(QString(), s);
    m_speed->setCurrentIndex(2);
    m_texts.add([this] {  // ×0.25 or ×0,25
        for (int i = 0; i < m_speed->count(); ++i)
            m_speed->setItemText(i, QStringLiteral("×%1").arg(QLocale().toString(m_speed->itemData(i).toDouble())));
    });
    m_slider = new QSlider(Qt::Horizontal);
    m_slider->setObjectName("DemoSlider");
    m_time = new QLabel;
    m_time->setMinimumWidth(150);
    m_note = trainui::wrapped();
    m_note->setObjectName("DemoNote");
    m_note->setStyleSheet("color: #b35c00;");
    m_note->hide();
    left->insertWidget(2, m_note);
    // the scrub slider and the clock on a row of their own (the slider keeps its room on
    // a narrow screen), the buttons below
    auto* scrub = new QHBoxLayout;
    scrub->addWidget(m_slider, 1);
    scrub->addWidget(m_time);
    right->addLayout(scrub);
    controls->addWidget(m_play);
    auto* speedLabel = new QLabel;
    controls->addWidget(speedLabel);
    controls->addWidget(m_speed);
    controls->addStretch(1);
    m_follow = new QCheckBox;
    m_follow->setObjectName("DemoFollowCamera");
    m_texts.add([this, speedLabel] {
        speedLabel->setText(tr("Speed:"));
        m_follow->setText(tr("Expert's camera"));
        m_follow->setToolTip(tr("Look where the expert looked while recording (untick to move the view yourself)."));
    });
    m_follow->setChecked(true);
    m_follow->setEnabled(false);
    controls->addWidget(m_follow);
    right->addLayout(controls);
    layout->addLayout(right, 1);

    connect(m_watchButton, &QPushButton::clicked, this, &StartScreen::watchDemonstration);
    connect(m_startButton, &QPushButton::clicked, this, &StartScreen::startRequested);
    connect(back, &QPushButton::clicked, this, &StartScreen::backRequested);
    connect(m_play, &QPushButton::clicked, this, [this, runner] {
        if (!m_demoRunning) return watchDemonstration();
        runner->setPaused(!runner->isPaused());
        m_play->setText(runner->isPaused() ? tr("Play") : tr("Pause"));
    });
    connect(m_speed, &QComboBox::currentIndexChanged, this,
            [this, runner](int) { runner->setSpeed(m_speed->currentData().toDouble()); });
    // scrub: seek while dragging is cheap forward; a release seeks exactly
    connect(m_slider, &QSlider::sliderReleased, this, &StartScreen::seekSlider);
    connect(m_slider, &QSlider::actionTriggered, this, [this](int action) {
        if (action == QSlider::SliderMove) return;  // dragging: on release
        QTimer::singleShot(0, this, &StartScreen::seekSlider);
    });
}

void StartScreen::seekSlider()
{
    if (!m_demoRunning) watchDemonstration();
    m_training->runner()->seek(m_slider->value() / 10.0);
}

void StartScreen::open()
{
    fill();
    const auto demo = m_training->demoLog();
    m_watchButton->setEnabled(demo != nullptr);
    m_slider->setRange(0, demo ? int(std::ceil((demo->duration() + TutorialRunner::kGrace) * 10)) : 0);
    m_slider->setValue(0);
    m_time->clear();
    // the machine at the start, before any demonstration
    TutorialRunner* runner = m_training->runner();
    if (runner->start(m_training->tutorial(), m_training->bundle(), nullptr, m_training->profile(), true)) {
        if (auto f = runner->latest()) m_view->setSnapshot(f->snapshot);
        runner->close();
    }
    QTimer::singleShot(0, m_view, [v = m_view] { trainui::frameModelAndTargets(v); });
}

void StartScreen::fill()
{
    const auto t = m_training->tutorial();
    if (!t) return;
    const std::string lang = TrainingController::language().toStdString();
    m_title->setText(QString::fromStdString(t->title(lang)));
    QString intro;
    for (const trainer::LocalText& p : t->spec.intro)
        intro += "<p>" + QString::fromStdString(p.in(lang)).toHtmlEscaped() + "</p>";
    intro += "<p>" +
             tr("Time limit: %1 s. Pass mark: %2 of 100.")
                 .arg(trainui::num(t->scoring().timeLimit, 0), trainui::num(t->scoring().pass, 0)) +
             "</p>";
    m_intro->setText(intro);
    m_controls->setText("<b>" + tr("How to drive (%1):").arg(m_training->profile().localized(m_training->profile().name).toHtmlEscaped()) + "</b><br>" +
                        driveControlsHtml(driveControls(*t, m_training->profile())));
    const QString warning = m_training->demoWarning();
    m_note->setText(warning);
    m_note->setVisible(!warning.isEmpty());
    m_watchButton->setToolTip(m_training->demoLog() ? QString() : tr("This tutorial has no demonstration."));
    m_follow->setEnabled(!m_training->demoCamera().empty());
}

void StartScreen::watchDemonstration()
{
    const auto t = m_training->tutorial();
    if (!t || !m_training->demoLog()) return;
    TutorialRunner* runner = m_training->runner();
    runner->setSpeed(m_speed->currentData().toDouble());
    QString error;
    if (!runner->start(t, m_training->bundle(), m_training->demoLog(), m_training->demoProfile(), false, &error)) {
        m_time->setText(error);
        return;
    }
    m_demoRunning = true;
    m_shownStep = -1;
    showLevers();
    m_play->setEnabled(true);
    m_play->setText(tr("Pause"));
}

void StartScreen::showFrame(const TrainFrame& f)
{
    if (!m_demoRunning || f.snapshot->step == m_shownStep) return;
    m_shownStep = f.snapshot->step;
    m_view->setSnapshot(f.snapshot);
    m_bars->setCommands(f.snapshot->u);
    const trainer::CameraPath& path = m_training->demoCamera();
    if (!path.empty() && m_follow->isChecked()) {
        const trainer::CameraKey k = path.at(f.snapshot->t);
        Camera c = m_view->cameraState();
        c.mode = Camera::Mode::Orbit;
        c.target = k.target;
        c.distance = k.distance;
        c.yaw = k.yaw;
        c.pitch = k.pitch;
        m_view->setCameraState(c);
    }
    if (!m_slider->isSliderDown()) {
        const QSignalBlocker block(m_slider);
        m_slider->setValue(int(std::lround(f.snapshot->t * 10)));
    }
    QString text = tr("%1 s of %2 s").arg(trainui::num(f.snapshot->t, 1), trainui::num(f.duration, 0));
    if (f.ended && f.output)
        text = f.output->result.passed ? tr("Done: passed, %1 of 100").arg(trainui::num(f.output->result.score, 0))
                                       : tr("Done");
    m_time->setText(text);
}

void StartScreen::demoFinished()
{
    m_play->setText(tr("Play"));
}

void StartScreen::showLevers()
{
    const auto t = m_training->tutorial();
    const auto log = m_training->demoLog();
    if (!t || !log) return;
    // the controls of the devices the expert's input was recorded from, through the
    // profile it is replayed with
    QStringList devices;
    for (const trainer::DeviceInfo& d : log->devices) devices << d.id << trainer::kindKey(d.kind);
    m_bars->setDrives(driveControls(*t, m_training->demoProfile(), &devices));
    m_bars->show();
}

void StartScreen::leave()
{
    m_demoRunning = false;
    m_bars->hide();
    m_play->setText(tr("Play"));
    m_play->setEnabled(m_training->demoLog() != nullptr);
}

void StartScreen::retranslate()
{
    m_texts.apply();
    fill();
    if (m_demoRunning) showLevers();
    m_shownStep = -1;  // the clock at the next frame, even paused
}

}  // namespace studio
