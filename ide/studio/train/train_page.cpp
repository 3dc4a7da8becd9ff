#include "ide/studio/train/train_page.h"

#include "ide/paths/paths.h"
#include "ide/studio/train/attempt_screen.h"
#include "ide/studio/train/course_screen.h"
#include "ide/studio/train/debrief_screen.h"
#include "ide/studio/train/pin_dialog.h"
#include "ide/studio/train/records_view.h"
#include "ide/studio/train/result_screen.h"
#include "ide/studio/train/start_screen.h"
#include "ide/studio/train/tutorial_runner.h"
#include "ide/studio/view/viewport.h"

#include <QCheckBox>
#include <QEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QStackedWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace studio {

TrainPage::TrainPage(TutorialRunner* runner, trainer::Station* station, QWidget* parent)
    : QWidget(parent), m_training(std::make_unique<TrainingController>(runner, station))
{
    setObjectName("TrainPage");
    // big enough to read from the operator's seat (the HUD's own labels are bigger)
    setStyleSheet("QWidget { font-size: 14pt; }"
                  "QPushButton { padding: 8px 18px; }"
                  "QHeaderView::section { padding: 4px 8px; }"
                  "QLabel#TrainTitle { font-size: 26pt; font-weight: bold; }");
    TrainingController* training = m_training.get();
    m_course = new CourseScreen(training);
    m_start = new StartScreen(training);
    m_attempt = new AttemptScreen(training);
    m_result = new ResultScreen(training);
    m_debrief = new DebriefScreen(training);
    m_recordsView = new RecordsView;
    m_stack = new QStackedWidget;
    // in the order of Screen
    for (QWidget* w : std::initializer_list<QWidget*>{m_course, m_start, m_attempt, m_result, m_debrief, m_recordsView})
        m_stack->addWidget(w);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_stack);

    connect(m_course, &CourseScreen::openRequested, this, &TrainPage::openTutorial);
    connect(m_course, &CourseScreen::operatorChosen, this, &TrainPage::setOperator);
    connect(m_course, &CourseScreen::recordsRequested, this, &TrainPage::askRecordsPin);
    connect(m_start, &StartScreen::startRequested, this, [this] { startAttempt(); });
    connect(m_start, &StartScreen::backRequested, this, &TrainPage::showCourse);
    connect(m_attempt, &AttemptScreen::stopRequested, this, &TrainPage::stopAttempt);
    connect(m_result, &ResultScreen::courseRequested, this, &TrainPage::showCourse);
    connect(m_result, &ResultScreen::retryRequested, this, &TrainPage::retry);
    connect(m_result, &ResultScreen::debriefRequested, this, &TrainPage::showDebrief);
    connect(m_result, &ResultScreen::nextRequested, this, &TrainPage::nextStage);
    connect(m_debrief, &DebriefScreen::backRequested, this, [this] { setScreen(Screen::Result); });
    connect(m_recordsView, &RecordsView::backRequested, this, &TrainPage::showCourse);
    connect(m_recordsView, &RecordsView::operatorsChanged, this, [this] { setOperator(operatorId()); });

    connect(runner, &TutorialRunner::finished, this, &TrainPage::onFinished);
    m_timer = new QTimer(this);
    m_timer->setInterval(16);
    connect(m_timer, &QTimer::timeout, this, &TrainPage::poll);
    m_timer->start();
    setTutorialsDir(paths::tutorialsDir());
    setOperator(operatorId());
}

TrainPage::~TrainPage()
{
    m_timer->stop();
    m_training->leaveAttempt();  // the runner closed, the recording stopped, the attempt's record closed …
    delete m_stack;              // … then the screens, while the controller they show still exists
}

// ---------------------------------------------------------------- parts

QListWidget* TrainPage::courseList() const { return m_course->courseList(); }
Viewport* TrainPage::attemptViewport() const { return m_attempt->view(); }
Viewport* TrainPage::demoViewport() const { return m_start->view(); }
QLabel* TrainPage::hud() const { return m_attempt->hud(); }
QLabel* TrainPage::resultHeading() const { return m_result->heading(); }
QLabel* TrainPage::resultNote() const { return m_result->note(); }
QTableWidget* TrainPage::breakdownTable() const { return m_result->breakdown(); }
QChartView* TrainPage::forceChart() const { return m_debrief->forceChart(); }
QTableWidget* TrainPage::comparisonTable() const { return m_debrief->comparison(); }
QListWidget* TrainPage::timeline() const { return m_debrief->timeline(); }
QSlider* TrainPage::replaySlider() const { return m_debrief->slider(); }
QSlider* TrainPage::demoSlider() const { return m_start->slider(); }
QCheckBox* TrainPage::expertBox() const { return m_attempt->expertBox(); }
HydraulicPanel* TrainPage::hydraulicPanel() const { return m_attempt->hydraulicPanel(); }
QCheckBox* TrainPage::hydraulicsBox() const { return m_attempt->hydraulicsBox(); }
QPushButton* TrainPage::recordsButton() const { return m_course->recordsButton(); }
QPushButton* TrainPage::languageButton(const QString& code) const { return m_course->languageButton(code); }
QLabel* TrainPage::courseTitle() const { return m_course->title(); }
QLabel* TrainPage::startTitle() const { return m_start->title(); }
QLabel* TrainPage::resultScore() const { return m_result->score(); }

// ---------------------------------------------------------------- the course and the records

void TrainPage::setTutorialsDir(const QString& dir)
{
    m_training->setTutorialsDir(dir);
    refreshCourse();
}

void TrainPage::setOperator(const QString& id)
{
    m_training->setOperator(id);
    m_course->showOperators();
    refreshCourse();
}

void TrainPage::refreshCourse() { m_course->refresh(); }

bool TrainPage::openRecordsAt(const QString& path)
{
    if (m_training->attemptRecorded()) return false;  // not during an attempt
    const bool open = m_training->openRecordsAt(path);
    m_course->showOperators();
    refreshCourse();
    if (m_screen == Screen::Records) showRecords();
    return open;
}

void TrainPage::setKiosk(bool kiosk)
{
    m_kiosk = kiosk;
    m_attempt->setKiosk(kiosk);
    // in kiosk mode only a trainer with the PIN sees the records; without a PIN, nobody
    m_course->recordsButton()->setVisible(!kiosk || !PinDialog::trainerPin().isEmpty());
    if (kiosk && m_screen == Screen::Records) showCourse();
}

void TrainPage::setAllUnlocked(bool unlocked)
{
    m_training->setAllUnlocked(unlocked);
    refreshCourse();
}

void TrainPage::askRecordsPin()
{
    if (!m_kiosk) return showRecords();
    if (PinDialog::trainerPin().isEmpty() || findChild<PinDialog*>("RecordsPinDialog")) return;
    auto* dialog = new PinDialog(tr("Trainee records"), tr("The trainer's PIN:"), this);
    dialog->setObjectName("RecordsPinDialog");
    connect(dialog, &PinDialog::unlocked, this, &TrainPage::showRecords);
    dialog->open();
}

void TrainPage::showRecords()
{
    leaveRun();
    m_training->close();
    giveRecordsTheTutorials();
    m_recordsView->setRecords(m_training->records(), m_training->recordsProblem());
    m_recordsView->selectOperator(TrainingController::operatorCode(operatorId()));
    setScreen(Screen::Records);
}

void TrainPage::giveRecordsTheTutorials()
{
    QHash<QString, QString> titles;
    QHash<QString, double> passMarks;
    QHash<QString, std::shared_ptr<const trainer::Tutorial>> tutorials;
    for (const TrainingController::Entry& e : m_training->entries()) {
        titles.insert(e.id, e.title);
        if (!e.tutorial) continue;
        passMarks.insert(e.id, e.tutorial->scoring().pass);
        tutorials.insert(e.id, e.tutorial);
    }
    m_recordsView->setTutorials(titles, passMarks, tutorials);
}

void TrainPage::showCourse()
{
    leaveRun();
    m_training->close();
    refreshCourse();
    setScreen(Screen::Course);
}

// ---------------------------------------------------------------- screens and language

void TrainPage::setScreen(Screen s)
{
    m_screen = s;
    m_stack->setCurrentIndex(int(s));
    emit screenChanged(s);
}

void TrainPage::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void TrainPage::retranslate()
{
    // (the records view, a screen of its own, follows by itself)
    m_training->retitle();
    m_course->retranslate();
    m_start->retranslate();
    m_attempt->retranslate();
    showCentreLink();
    // the HUD and the demonstration's clock now, even paused
    if (m_screen == Screen::Attempt || m_screen == Screen::Start) poll();
    // (their fixed texts too when no attempt has ended yet: they show after one)
    m_result->retranslate(m_kiosk);
    m_debrief->retranslate();
    giveRecordsTheTutorials();  // the titles in the new language, before the view shows them again
}

// ---------------------------------------------------------------- a stage

bool TrainPage::openTutorial(const QString& id)
{
    const int i = m_training->entryOf(id);
    if (i < 0 || !m_training->entries()[std::size_t(i)].tutorial || m_training->isLocked(i)) return false;
    leaveRun();
    bool newModel = false;
    if (!m_training->open(i, &newModel)) {
        refreshCourse();  // with why it cannot be used
        return false;
    }
    if (newModel) {
        for (Viewport* v : {m_start->view(), m_attempt->view(), m_debrief->view()}) {
            v->setBundle(m_training->bundle());
            v->setScene(m_training->scene());
        }
    }
    m_start->open();
    setScreen(Screen::Start);
    return true;
}

void TrainPage::watchDemonstration() { m_start->watchDemonstration(); }

void TrainPage::useShippedDemonstration() { m_training->useShippedDemonstration(); }

bool TrainPage::useAsDemonstration(const QString& path, QString* error)
{
    return m_training->useAsDemonstration(path, error);
}

void TrainPage::setShowExpert(bool show) { m_attempt->expertBox()->setChecked(show); }

bool TrainPage::showExpert() const { return m_attempt->expertBox()->isChecked(); }

void TrainPage::startAttempt(std::shared_ptr<const trainer::InputLog> drive)
{
    const auto t = tutorial();
    if (!t) return;
    leaveRun();
    if (!m_training->beginAttempt(drive)) return;
    m_attempt->prepare();
    setScreen(Screen::Attempt);
    m_attempt->aim();
    if (m_training->attemptLive()) emit attemptStarted(t);
    poll();
}

bool TrainPage::startAttemptFor(const QString& id, const QString& operatorCode)
{
    const int i = m_training->entryOf(id);
    if (i < 0 || !m_training->entries()[std::size_t(i)].tutorial) return false;
    if (m_screen == Screen::Records) showCourse();
    if (operatorCode.trimmed() != operatorId()) setOperator(operatorCode);
    // the instructor decides: a stage still locked for the operator opens too
    const bool unlocked = m_training->allUnlocked();
    m_training->setAllUnlocked(true);
    const bool open = openTutorial(id);
    m_training->setAllUnlocked(unlocked);
    if (!open) return false;
    startAttempt();
    return m_screen == Screen::Attempt && attemptLive();
}

void TrainPage::stopAttempt()
{
    TutorialRunner* runner = m_training->runner();
    if (m_screen == Screen::Attempt && runner->isActive()) runner->stop();
}

void TrainPage::leaveRun()
{
    m_start->leave();
    m_debrief->leave();
    m_attempt->leave();
    if (m_training->leaveAttempt()) emit attemptEnded();
}

void TrainPage::poll()
{
    if (m_screen == Screen::Debrief && m_debrief->advance(m_timer->interval() / 1000.0)) return;
    const std::shared_ptr<const TrainFrame> f = m_training->runner()->latest();
    if (!f || !f->snapshot) return;
    if (m_screen == Screen::Start) {
        m_start->showFrame(*f);
    } else if (m_screen == Screen::Attempt) {
        m_attempt->showFrame(*f);
        m_training->logProgress(*f);
    }
}

void TrainPage::onFinished()
{
    const auto f = m_training->runner()->latest();
    if (!f || !f->output) return;
    if (m_screen == Screen::Start && m_start->demoRunning()) {
        m_start->demoFinished();
        poll();
        return;
    }
    if (m_screen != Screen::Attempt) return;
    poll();  // the last frame on the HUD
    if (m_training->finishAttempt(f->output)) emit attemptEnded();
    showResult();
}

// ---------------------------------------------------------------- after the attempt

void TrainPage::showResult()
{
    if (!m_training->lastRun()) return;
    m_result->fill(m_kiosk);
    setScreen(Screen::Result);
}

void TrainPage::retry()
{
    if (tutorial()) startAttempt();
}

void TrainPage::nextStage()
{
    const int next = m_training->current() + 1;
    if (next < int(m_training->entries().size())) openTutorial(m_training->entries()[std::size_t(next)].id);
}

void TrainPage::showDebrief()
{
    if (!m_training->lastRun()) return;
    m_debrief->fill();
    setScreen(Screen::Debrief);
    m_training->computeExpert();
}

// ---------------------------------------------------------------- the training centre

void TrainPage::setCentreLink(CentreLink link, const QString& name, const QString& detail)
{
    m_centreLink = link;
    m_centreName = name;
    m_centreDetail = detail;
    showCentreLink();
}

QString TrainPage::centreLinkText() const
{
    switch (m_centreLink) {
    case CentreLink::Off: return {};
    case CentreLink::Online: return tr("On the centre's network as %1").arg(m_centreName);
    case CentreLink::NoKey:
        return tr("On the centre's network as %1, but without the centre's key: the instructor's commands are "
                  "refused (%2)")
            .arg(m_centreName, m_centreDetail);
    case CentreLink::Failed: return tr("Not on the centre's network: %1").arg(m_centreDetail);
    }
    return {};
}

void TrainPage::showCentreLink()
{
    const QString text = centreLinkText();
    const bool warn = m_centreLink == CentreLink::NoKey || m_centreLink == CentreLink::Failed;
    for (QLabel* l : {m_course->centreLabel(), m_attempt->centreLabel()}) {
        l->setText((warn ? QStringLiteral("⚠ ") : QStringLiteral("● ")) + text);
        l->setToolTip(text);
        l->setStyleSheet(warn ? "QLabel { color: #b26a00; font-weight: bold; }" : "QLabel { color: #1b7f3b; }");
        l->setVisible(!text.isEmpty());
    }
}

}  // namespace studio
