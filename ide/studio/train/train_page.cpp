#include "ide/studio/train/train_page.h"

#include "ide/i18n/language.h"
#include "ide/paths/paths.h"
#include "ide/studio/sim/hydraulic_panel.h"
#include "ide/studio/train/records_view.h"
#include "ide/studio/train/tutorial_runner.h"
#include "ide/studio/view/viewport.h"
#include "trainer/io/user_folders.h"
#include "trainer/station/station.h"
#include "trainer/training/attempt_log.h"

#include <QChart>
#include <QChartView>
#include <QApplication>
#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QInputDialog>
#include <QMessageBox>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QEvent>
#include <QFile>
#include <QFileInfo>
#include <QFrame>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QWheelEvent>
#include <QLabel>
#include <QLegend>
#include <QLineEdit>
#include <QLineSeries>
#include <QListWidget>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QShortcut>
#include <QSlider>
#include <QSplitter>
#include <QStackedWidget>
#include <QTableWidget>
#include <QThread>
#include <QTimer>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace studio {

namespace {

constexpr double kSpeeds[] = {0.25, 0.5, 1.0, 2.0, 4.0};

QString stars(int n)
{
    QString s;
    for (int i = 0; i < 3; ++i) s += i < n ? QChar(0x2605) : QChar(0x2606);
    return s;
}

QString num(double v, int decimals) { return QLocale().toString(v, 'f', decimals); }

constexpr qint64 kLogEveryMs = 500;  // events to the records this often during an attempt

QString guestCode() { return QStringLiteral("guest"); }

constexpr int kKeptRecordings = 20;  // older recordings are deleted

/// The station profile saved beside an input log.
QString profileBeside(const QString& log) { return log + QStringLiteral(".profile.json"); }

QString settingsKey(const QString& op, const QString& id, const char* what)
{
    return QStringLiteral("trainer/progress/%1/%2/%3").arg(op.isEmpty() ? QStringLiteral("-") : op, id,
                                                          QLatin1String(what));
}

/// Fit All, then one notch of the wheel out: Fit All frames the model only, and the
/// targets (scene graphics) often lie just outside it.
void frameModelAndTargets(Viewport* v)
{
    v->fitAll();
    const QPointF centre(v->width() / 2.0, v->height() / 2.0);
    QWheelEvent out(centre, v->mapToGlobal(centre), QPoint(), QPoint(0, -120), Qt::NoButton, Qt::NoModifier,
                    Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(v, &out);
}

QLabel* wrapped(const QString& text = {})
{
    auto* l = new QLabel(text);
    l->setWordWrap(true);
    return l;
}

}  // namespace

// ---------------------------------------------------------------- progress

CourseProgress CourseProgress::load(const QString& op, const QString& id)
{
    QSettings s;
    CourseProgress p;
    p.stars = s.value(settingsKey(op, id, "stars"), 0).toInt();
    p.score = s.value(settingsKey(op, id, "score"), 0.0).toDouble();
    p.passed = s.value(settingsKey(op, id, "passed"), false).toBool();
    p.attempts = s.value(settingsKey(op, id, "attempts"), 0).toInt();
    return p;
}

void CourseProgress::record(const QString& op, const QString& id, const trainer::TutorialResult& r)
{
    const CourseProgress old = load(op, id);
    QSettings s;
    s.setValue(settingsKey(op, id, "stars"), std::max(old.stars, r.stars));
    s.setValue(settingsKey(op, id, "score"), std::max(old.score, r.score));
    s.setValue(settingsKey(op, id, "passed"), old.passed || r.passed);
    s.setValue(settingsKey(op, id, "attempts"), old.attempts + 1);
}

// ---------------------------------------------------------------- page

TrainPage::TrainPage(TutorialRunner* runner, trainer::Station* station, QWidget* parent)
    : QWidget(parent), m_runner(runner), m_station(station)
{
    setObjectName("TrainPage");
    // big enough to read from the operator's seat (the HUD's own labels are bigger)
    setStyleSheet("QWidget { font-size: 14pt; }"
                  "QPushButton { padding: 8px 18px; }"
                  "QHeaderView::section { padding: 4px 8px; }"
                  "QLabel#TrainTitle { font-size: 26pt; font-weight: bold; }");
    m_operator = QSettings().value("trainer/operator").toString();
    openRecords();
    m_stack = new QStackedWidget;
    m_stack->addWidget(buildCourse());
    m_stack->addWidget(buildStart());
    m_stack->addWidget(buildAttempt());
    m_stack->addWidget(buildResult());
    m_stack->addWidget(buildDebrief());
    m_recordsView = new RecordsView;
    m_stack->addWidget(m_recordsView);
    connect(m_recordsView, &RecordsView::backRequested, this, &TrainPage::showCourse);
    connect(m_recordsView, &RecordsView::operatorsChanged, this, [this] { setOperator(m_operator); });
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_stack);

    connect(m_runner, &TutorialRunner::finished, this, &TrainPage::onFinished);
    m_timer = new QTimer(this);
    m_timer->setInterval(16);
    connect(m_timer, &QTimer::timeout, this, &TrainPage::poll);
    m_timer->start();
    setTutorialsDir(paths::tutorialsDir());
    setOperator(m_operator);
}

void TrainPage::openRecords(const QString& path)
{
    m_imported = 0;
    m_recordsProblem.clear();
    auto db = std::make_unique<trainer::records::RecordsDb>();
    QString error;
    if (!db->openSqlite(path, false, &error)) {
        m_recordsProblem = error;  // progress goes to QSettings, attempts to pending files
        qWarning("Train: the trainee records cannot be opened: %s", qPrintable(error));
        return;
    }
    m_db = std::move(db);
    QString importError;
    m_imported = trainer::AttemptLog::importPending(*m_db, trainer::userFolders::pendingAttempts(), &importError);
    if (!importError.isEmpty()) m_recordsProblem = importError;
}

bool TrainPage::openRecordsAt(const QString& path)
{
    if (m_attemptLog) return false;  // not during an attempt
    m_db.reset();
    openRecords(path);
    setOperator(m_operator);
    if (m_screen == Screen::Records) showRecords();
    return m_db != nullptr;
}

void TrainPage::setKiosk(bool kiosk)
{
    m_kiosk = kiosk;
    // in kiosk mode only a trainer with the PIN sees the records; without a PIN, nobody
    m_recordsButton->setVisible(!kiosk || !QSettings().value("trainer/pin").toString().isEmpty());
    if (kiosk && m_screen == Screen::Records) showCourse();
}

void TrainPage::setAllUnlocked(bool unlocked)
{
    m_allUnlocked = unlocked;
    refreshCourse();
}

void TrainPage::askRecordsPin()
{
    const QString pin = QSettings().value("trainer/pin").toString();
    if (!m_kiosk) return showRecords();
    if (pin.isEmpty() || findChild<QInputDialog*>("RecordsPinDialog")) return;
    auto* dialog = new QInputDialog(this);
    dialog->setObjectName("RecordsPinDialog");
    dialog->setWindowTitle(tr("Trainee records"));
    dialog->setLabelText(tr("The trainer's PIN:"));
    dialog->setTextEchoMode(QLineEdit::Password);
    dialog->setOkButtonText(tr("OK"));
    dialog->setCancelButtonText(tr("Cancel"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QInputDialog::textValueSelected, this, [this, pin](const QString& typed) {
        if (typed == pin) showRecords();
    });
    dialog->open();
}

void TrainPage::showRecords()
{
    leaveRun();
    m_current = -1;
    giveRecordsTheTutorials();
    m_recordsView->setRecords(m_db.get(), m_recordsProblem);
    m_recordsView->selectOperator(m_operator.isEmpty() ? guestCode() : m_operator);
    setScreen(Screen::Records);
}

void TrainPage::giveRecordsTheTutorials()
{
    QHash<QString, QString> titles;
    QHash<QString, double> passMarks;
    QHash<QString, std::shared_ptr<const trainer::Tutorial>> tutorials;
    for (const Entry& e : m_entries) {
        titles.insert(e.id, e.title);
        if (!e.tutorial) continue;
        passMarks.insert(e.id, e.tutorial->scoring().pass);
        tutorials.insert(e.id, e.tutorial);
    }
    m_recordsView->setTutorials(titles, passMarks, tutorials);
}

QStringList TrainPage::knownOperators() const
{
    if (!m_db) return QSettings().value("trainer/operators").toStringList();
    QList<trainer::records::OperatorProgress> all;
    QStringList codes;
    if (m_db->progress(all))
        for (const auto& p : all)
            if (p.op.code != guestCode()) codes << p.op.code;
    return codes;
}

void TrainPage::loadProgress()
{
    m_progress.clear();
    if (!m_db || m_operatorDbId == 0) return;
    QList<trainer::records::OperatorProgress> all;
    QString error;
    if (!m_db->progress(all, &error)) {
        m_recordsProblem = error;
        return;
    }
    for (const auto& op : all) {
        if (op.op.id != m_operatorDbId) continue;
        for (const trainer::records::TutorialProgress& t : op.tutorials)
            m_progress.insert(t.tutorialId, CourseProgress{t.bestStars, t.bestScore, t.passed, t.attempts});
    }
}

CourseProgress TrainPage::progressOf(const QString& tutorialId) const
{
    return m_db ? m_progress.value(tutorialId) : CourseProgress::load(m_operator, tutorialId);
}

TrainPage::~TrainPage()
{
    m_timer->stop();
    stopRecording();
    if (m_runner->isActive()) m_runner->close();
    m_attemptLog.reset();  // before the records close
}

QString TrainPage::language()
{
    return i18n::current();
}

void TrainPage::setTutorialsDir(const QString& dir)
{
    m_dir = dir;
    m_entries.clear();
    // the open tutorial's index and model belong to the old list
    m_current = -1;
    m_bundle.reset();
    for (const QFileInfo& f : QDir(dir).entryInfoList({"*.tut"}, QDir::Files, QDir::Name)) {
        Entry e;
        e.path = f.absoluteFilePath();
        solver::Diagnostics diags(e.path.toStdString());
        e.tutorial = trainer::loadTutorial(e.path.toStdString(), diags);
        if (e.tutorial) {
            e.id = QString::fromStdString(e.tutorial->spec.id);
            e.level = e.tutorial->spec.level;
            e.titleText = e.tutorial->spec.title;
        } else {
            // what it says about itself, for the list
            QFile file(e.path);
            solver::Diagnostics ignored(e.path.toStdString());
            if (file.open(QIODevice::ReadOnly)) {
                const trainer::TutorialSpec spec =
                    trainer::parseTutorial(file.readAll().toStdString(), e.path.toStdString(), ignored);
                e.id = QString::fromStdString(spec.id);
                e.level = spec.level;
                e.titleText = spec.title;
            }
            for (const solver::Diagnostic& d : diags) {
                if (d.severity == solver::Severity::Error) {
                    e.problem = QString::fromStdString(d.format());
                    break;
                }
            }
        }
        if (e.id.isEmpty()) e.id = f.completeBaseName();
        m_entries.push_back(std::move(e));
    }
    std::stable_sort(m_entries.begin(), m_entries.end(),
                     [](const Entry& a, const Entry& b) { return a.level < b.level; });
    retitle();
    refreshCourse();
}

void TrainPage::retitle()
{
    const std::string lang = language().toStdString();
    for (Entry& e : m_entries) {
        e.title = QString::fromStdString(e.titleText.in(lang));
        if (e.title.isEmpty()) e.title = QFileInfo(e.path).completeBaseName();
    }
}

void TrainPage::setOperator(const QString& id)
{
    m_operator = id.trimmed();
    QSettings s;
    s.setValue("trainer/operator", m_operator);
    if (m_db) {
        // the records know operators by code; a new code is a new operator
        const QString code = m_operator.isEmpty() ? guestCode() : m_operator;
        QString error;
        m_operatorDbId = m_db->operatorFor(code, m_operator.isEmpty() ? tr("Guest") : code, &error);
        if (m_operatorDbId == 0) m_recordsProblem = error;
    } else {
        QStringList known = s.value("trainer/operators").toStringList();
        if (!m_operator.isEmpty() && !known.contains(m_operator)) {
            known.append(m_operator);
            s.setValue("trainer/operators", known);
        }
    }
    if (m_operatorBox) {
        const QStringList known = knownOperators();
        const QSignalBlocker block(m_operatorBox);
        m_operatorBox->clear();
        m_operatorBox->addItems(known);
        m_operatorBox->setCurrentText(m_operator);
    }
    refreshCourse();
}

std::shared_ptr<const trainer::Tutorial> TrainPage::tutorial() const
{
    return m_current >= 0 ? m_entries[std::size_t(m_current)].tutorial : nullptr;
}

int TrainPage::entryOf(const QString& id) const
{
    for (std::size_t i = 0; i < m_entries.size(); ++i)
        if (m_entries[i].id == id) return int(i);
    return -1;
}

bool TrainPage::isLocked(int entry) const
{
    if (m_allUnlocked) return false;
    // every stage of the level just below must be passed
    const int level = m_entries[std::size_t(entry)].level;
    int below = -1;
    for (const Entry& e : m_entries)
        if (e.level < level) below = std::max(below, e.level);
    if (below < 0) return false;
    for (const Entry& e : m_entries) {
        if (e.level == below && !progressOf(e.id).passed) return true;
    }
    return false;
}

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
    // (the children that are screens of their own, the records view, follow by themselves)
    m_texts.apply();
    for (QPushButton* b : m_languageButtons) b->setChecked(b->objectName() == "LanguageButton_" + language());
    retitle();
    refreshCourse();
    fillStart();
    // the HUD, the hints and the demonstration's clock at the next poll, even paused
    m_shownStep = -1;
    m_hudText.clear();
    m_hintText.clear();
    m_warningText.clear();
    if (m_screen == Screen::Attempt || m_screen == Screen::Start) poll();
    if (m_lastRun) {
        fillResult();
        fillTimeline();
        fillCharts();
        fillComparison();
        showReplaySample(m_replaySlider->value());
    }
    giveRecordsTheTutorials();  // the titles in the new language, before the view shows them again
}

// ---------------------------------------------------------------- course

QWidget* TrainPage::buildCourse()
{
    auto* page = new QWidget;
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(24, 24, 24, 24);
    auto* top = new QHBoxLayout;
    m_courseTitle = new QLabel;
    m_courseTitle->setObjectName("TrainTitle");
    m_texts.add([this] { m_courseTitle->setText(tr("Training course")); });
    top->addWidget(m_courseTitle, 1);
    // the languages, each in its own name, big enough for a finger on the kiosk's screen
    auto* languages = new QButtonGroup(page);
    languages->setExclusive(true);
    for (const QString& code : i18n::languages()) {
        auto* b = new QPushButton(i18n::nativeName(code));
        b->setObjectName("LanguageButton_" + code);
        b->setCheckable(true);
        b->setChecked(code == language());
        b->setMinimumSize(190, 64);
        b->setFocusPolicy(Qt::NoFocus);
        b->setStyleSheet("QPushButton { font-size: 18pt; padding: 10px 26px; border: 2px solid #8a949e; "
                         "border-radius: 8px; background: #f4f6f8; color: #1d2329; }"
                         "QPushButton:checked { background: #1f6fc5; border-color: #1f6fc5; color: white; "
                         "font-weight: bold; }");
        languages->addButton(b);
        connect(b, &QPushButton::clicked, this, [code] { i18n::switchTo(code); });
        top->addWidget(b, 0, Qt::AlignVCenter);
        m_languageButtons << b;
    }
    layout->addLayout(top);
    auto* opRow = new QHBoxLayout;
    auto* opLabel = new QLabel;
    m_texts.add([opLabel] { opLabel->setText(tr("Operator:")); });
    opRow->addWidget(opLabel);
    m_operatorBox = new QComboBox;
    m_operatorBox->setObjectName("OperatorBox");
    m_operatorBox->setEditable(true);
    m_operatorBox->setMinimumWidth(240);
    m_operatorBox->addItems(knownOperators());
    m_operatorBox->setCurrentText(m_operator);
    m_texts.add([this] { m_operatorBox->lineEdit()->setPlaceholderText(tr("name or number")); });
    connect(m_operatorBox->lineEdit(), &QLineEdit::editingFinished, this,
            [this] { setOperator(m_operatorBox->currentText()); });
    connect(m_operatorBox, &QComboBox::textActivated, this, [this](const QString& t) { setOperator(t); });
    opRow->addWidget(m_operatorBox);
    opRow->addStretch();
    layout->addLayout(opRow);
    m_courseList = new QListWidget;
    m_courseList->setObjectName("CourseList");
    m_courseList->setStyleSheet("QListWidget { font-size: 16pt; } QListWidget::item { padding: 10px; }");
    layout->addWidget(m_courseList, 1);
    auto* buttons = new QHBoxLayout;
    m_recordsButton = new QPushButton;
    m_recordsButton->setObjectName("RecordsButton");
    m_texts.add([this] {
        m_recordsButton->setText(tr("Records"));
        m_recordsButton->setToolTip(tr("The trainee records: operators, attempts, progress (for the trainer)."));
    });
    connect(m_recordsButton, &QPushButton::clicked, this, &TrainPage::askRecordsPin);
    buttons->addWidget(m_recordsButton);
    buttons->addSpacing(12);
    auto* courseCentre = new QLabel;
    courseCentre->setObjectName("CentreLinkCourse");
    courseCentre->hide();
    m_centreLabels << courseCentre;
    buttons->addWidget(courseCentre);
    buttons->addStretch();
    m_openButton = new QPushButton;
    m_texts.add([this] { m_openButton->setText(tr("Open")); });
    m_openButton->setEnabled(false);
    buttons->addWidget(m_openButton);
    layout->addLayout(buttons);
    const auto open = [this] {
        QListWidgetItem* it = m_courseList->currentItem();
        if (it && (it->flags() & Qt::ItemIsEnabled)) openTutorial(it->data(Qt::UserRole).toString());
    };
    connect(m_openButton, &QPushButton::clicked, this, open);
    connect(m_courseList, &QListWidget::itemActivated, this, open);
    connect(m_courseList, &QListWidget::currentItemChanged, this, [this](QListWidgetItem* it) {
        m_openButton->setEnabled(it && (it->flags() & Qt::ItemIsEnabled));
    });
    return page;
}

QPushButton* TrainPage::languageButton(const QString& code) const
{
    for (QPushButton* b : m_languageButtons)
        if (b->objectName() == "LanguageButton_" + code) return b;
    return nullptr;
}

void TrainPage::refreshCourse()
{
    if (!m_courseList) return;
    loadProgress();
    const QString selected = m_courseList->currentItem() ? m_courseList->currentItem()->data(Qt::UserRole).toString()
                                                         : QString();
    m_courseList->clear();
    for (std::size_t i = 0; i < m_entries.size(); ++i) {
        const Entry& e = m_entries[i];
        const CourseProgress p = progressOf(e.id);
        QString text = tr("Level %1 — %2").arg(e.level).arg(e.title);
        auto* it = new QListWidgetItem;
        it->setData(Qt::UserRole, e.id);
        if (!e.tutorial || !e.problem.isEmpty()) {
            text += "   " + tr("(cannot be used)");
            it->setFlags(it->flags() & ~Qt::ItemIsEnabled);
            it->setToolTip(e.problem.isEmpty() ? tr("This tutorial cannot be loaded.") : e.problem);
        } else if (isLocked(int(i))) {
            text += "   " + tr("(locked: pass the level before)");
            it->setFlags(it->flags() & ~Qt::ItemIsEnabled);
            it->setToolTip(tr("Pass every stage of the level before to unlock this one."));
        } else {
            text += "   " + stars(p.stars);
            if (p.attempts > 0) text += "   " + tr("best %1 of 100").arg(num(p.score, 0));
        }
        it->setText(text);
        m_courseList->addItem(it);
        if (!selected.isEmpty() && e.id == selected) m_courseList->setCurrentItem(it);
    }
}

void TrainPage::showCourse()
{
    leaveRun();
    m_current = -1;
    refreshCourse();
    setScreen(Screen::Course);
}

bool TrainPage::openTutorial(const QString& id)
{
    const int i = entryOf(id);
    if (i < 0 || !m_entries[std::size_t(i)].tutorial || isLocked(i)) return false;
    leaveRun();
    const Entry& e = m_entries[std::size_t(i)];
    const trainer::Tutorial& t = *e.tutorial;
    if (m_current != i || !m_bundle) {
        QString error;
        m_bundle = makeTutorialBundle(t, &error);
        if (!m_bundle) {
            m_entries[std::size_t(i)].problem = error;
            refreshCourse();
            return false;
        }
        m_scene = makeTutorialScene(t);
        for (Viewport* v : {m_demoView, m_attemptView, m_replayView}) {
            v->setBundle(m_bundle);
            v->setScene(m_scene);
        }
        m_expert.reset();
        m_expertFor.clear();
    }
    m_current = i;
    QString error;
    if (!trainer::tutorialProfile(t, {}, m_profile, &error)) m_profile = trainer::StationProfile{};
    loadDemonstration(t);
    fillStart();
    m_watchButton->setEnabled(m_demoLog != nullptr);
    m_demoSlider->setRange(0, m_demoLog ? int(std::ceil((m_demoLog->duration() + TutorialRunner::kGrace) * 10)) : 0);
    m_demoSlider->setValue(0);
    m_demoTime->clear();
    // the machine at the start, before any demonstration
    if (m_runner->start(e.tutorial, m_bundle, nullptr, m_profile, true)) {
        if (auto f = m_runner->latest()) m_demoView->setSnapshot(f->snapshot);
        m_runner->close();
    }
    QTimer::singleShot(0, m_demoView, [v = m_demoView] { frameModelAndTargets(v); });
    setScreen(Screen::Start);
    return true;
}

QString TrainPage::unreadableDemoText() const
{
    if (m_demoUnreadable.isEmpty()) return {};
    return tr("The demonstration chosen for this stage (%1) cannot be read: %2. The shipped demonstration is used.")
        .arg(m_demoUnreadable.value(0), m_demoUnreadable.value(1));
}

void TrainPage::fillStart()
{
    const auto t = tutorial();
    if (!t) return;
    const std::string lang = language().toStdString();
    m_startTitle->setText(QString::fromStdString(t->title(lang)));
    QString intro;
    for (const trainer::LocalText& p : t->spec.intro) intro += "<p>" + QString::fromStdString(p.in(lang)).toHtmlEscaped() + "</p>";
    intro += "<p>" + tr("Time limit: %1 s. Pass mark: %2 of 100.")
                         .arg(num(t->scoring().timeLimit, 0), num(t->scoring().pass, 0)) + "</p>";
    m_startIntro->setText(intro);
    m_demoWarning = unreadableDemoText();
    m_demoNote->setText(m_demoWarning);
    m_demoNote->setVisible(!m_demoWarning.isEmpty());
    m_watchButton->setToolTip(m_demoLog ? QString() : tr("This tutorial has no demonstration."));
}

// ---------------------------------------------------------------- start and demonstration

QString TrainPage::userDemonstrationPath(const QString& tutorialId)
{
    return trainer::userFolders::demonstrations() + QLatin1Char('/') + tutorialId + QStringLiteral(".demo.log");
}

void TrainPage::loadDemonstration(const trainer::Tutorial& t)
{
    const QString id = QString::fromStdString(t.spec.id);
    const QString before = m_demoFile;
    m_demoLog.reset();
    m_demoFile.clear();
    m_demoWarning.clear();
    m_demoUnreadable.clear();
    m_demoProfile = m_profile;
    // the stage's own demonstration, chosen by a trainer; else the shipped one
    const QString chosen = QSettings().value("trainer/demo/" + id).toString();
    if (!chosen.isEmpty()) {
        auto log = std::make_shared<trainer::InputLog>();
        QString error;
        if (trainer::InputLog::load(chosen, *log, &error)) {
            m_demoLog = log;
            m_demoFile = chosen;
            // the profile it was recorded through, when it was kept beside it
            QFile json(profileBeside(chosen));
            trainer::StationProfile p;
            QList<trainer::ProfileIssue> issues;
            if (json.open(QIODevice::ReadOnly) && trainer::StationProfile::fromJson(json.readAll(), p, issues))
                m_demoProfile = p;
        } else {
            m_demoUnreadable = {chosen, error};
            m_demoWarning = unreadableDemoText();
            qWarning("Train: %s", qPrintable(m_demoWarning));
        }
    }
    // the shipped demonstration's camera (a trainer's own recording has none)
    m_demoCamera = trainer::CameraPath();
    if (m_demoFile.isEmpty() && !t.cameraFile.empty()) {
        QString cameraError;
        if (!trainer::CameraPath::load(QString::fromStdString(t.cameraFile), m_demoCamera, &cameraError))
            qWarning("Train: %s", qPrintable(cameraError));
    }
    if (m_demoFollow) m_demoFollow->setEnabled(!m_demoCamera.empty());
    if (!m_demoLog && !t.demoFile.empty()) {
        auto log = std::make_shared<trainer::InputLog>();
        const QString shipped = QString::fromStdString(t.demoFile);
        if (trainer::InputLog::load(shipped, *log, nullptr)) {
            m_demoLog = log;
            m_demoFile = shipped;
        }
    }
    if (m_demoFile != before) {  // the expert's run was of another log
        m_expert.reset();
        m_expertFor.clear();
    }
}

bool TrainPage::saveDemonstration(const QString& path, QString* error)
{
    if (m_recordedInput.isEmpty() || !QFileInfo::exists(m_recordedInput)) {
        if (error) *error = tr("There is no recorded input: only an attempt with the operator's controls is recorded.");
        return false;
    }
    QDir().mkpath(QFileInfo(path).absolutePath());
    if (QFileInfo(path).absoluteFilePath() != QFileInfo(m_recordedInput).absoluteFilePath()) {
        for (const QString& f : {path, profileBeside(path)}) QFile::remove(f);
        if (!QFile::copy(m_recordedInput, path)) {
            if (error) *error = tr("Cannot write %1.").arg(path);
            return false;
        }
        QFile::copy(profileBeside(m_recordedInput), profileBeside(path));
    }
    return true;
}

bool TrainPage::useAsDemonstration(const QString& pathIn, QString* error)
{
    const auto t = tutorial();
    if (!t) return false;
    const QString id = QString::fromStdString(t->spec.id);
    QString path = pathIn;
    if (path.isEmpty()) {
        path = userDemonstrationPath(id);
        if (!saveDemonstration(path, error)) return false;
    }
    auto log = std::make_shared<trainer::InputLog>();
    if (!trainer::InputLog::load(path, *log, error)) return false;
    QSettings().setValue("trainer/demo/" + id, QFileInfo(path).absoluteFilePath());
    loadDemonstration(*t);
    return true;
}

void TrainPage::useShippedDemonstration()
{
    const auto t = tutorial();
    if (!t) return;
    QSettings().remove("trainer/demo/" + QString::fromStdString(t->spec.id));
    loadDemonstration(*t);
}

bool TrainPage::startRecording(const trainer::Tutorial& t)
{
    if (!m_station || m_recorder) return false;
    QDir dir(trainer::userFolders::attemptInput());
    dir.mkpath(".");
    // keep the newest few
    const QFileInfoList old = dir.entryInfoList({"*.log"}, QDir::Files, QDir::Time);
    for (int i = kKeptRecordings - 1; i < old.size(); ++i) {
        QFile::remove(old[i].absoluteFilePath());
        QFile::remove(profileBeside(old[i].absoluteFilePath()));
    }
    const QString file = dir.filePath(QStringLiteral("%1-%2.log")
                                          .arg(QString::fromStdString(t.spec.id),
                                               QDateTime::currentDateTime().toString("yyyyMMdd-HHmmss-zzz")));
    auto recorder = std::make_unique<trainer::InputRecorder>();
    QString error;
    trainer::StationProfile profile;
    if (!m_station->startRecording(*recorder, file, &error, &profile)) {
        qWarning("Train: the attempt's input is not recorded: %s", qPrintable(error));
        return false;
    }
    m_recorder = std::move(recorder);
    m_recordingFile = file;
    m_recordingProfile = profile;
    return true;
}

void TrainPage::stopRecording()
{
    if (!m_recorder) return;
    QString error;
    const bool ok = m_station ? m_station->stopRecording(*m_recorder, &error) : m_recorder->stop(&error);
    m_recorder.reset();
    if (!ok) {
        qWarning("Train: the attempt's input log %s may be incomplete: %s", qPrintable(m_recordingFile), qPrintable(error));
        return;
    }
    QFile json(profileBeside(m_recordingFile));
    if (json.open(QIODevice::WriteOnly)) json.write(m_recordingProfile.toJson());
    m_recordedInput = m_recordingFile;
}

void TrainPage::setShowExpert(bool show)
{
    m_expertBox->setChecked(show);
}

bool TrainPage::showExpert() const { return m_expertBox->isChecked(); }

QWidget* TrainPage::buildStart()
{
    auto* page = new QWidget;
    auto* layout = new QHBoxLayout(page);
    layout->setContentsMargins(24, 24, 24, 24);
    auto* left = new QVBoxLayout;
    m_startTitle = new QLabel;
    m_startTitle->setObjectName("TrainTitle");
    m_startTitle->setWordWrap(true);
    m_startIntro = wrapped();
    m_startIntro->setTextFormat(Qt::RichText);
    m_startIntro->setStyleSheet("font-size: 15pt;");
    m_startIntro->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    left->addWidget(m_startTitle);
    left->addWidget(m_startIntro, 1);
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
    m_demoView = new Viewport;
    m_demoView->setMinimumSize(480, 360);
    right->addWidget(m_demoView, 1);
    auto* controls = new QHBoxLayout;
    m_demoPlay = new QPushButton;
    m_demoPlay->setEnabled(false);
    m_texts.add([this] {
        m_demoPlay->setText(m_demoRunning && !m_runner->isPaused() ? tr("Pause") : tr("Play"));
    });
    m_demoSpeed = new QComboBox;
    for (double s : kSpeeds) m_demoSpeed->addItem(QString(), s);
    m_demoSpeed->setCurrentIndex(2);
    m_texts.add([this] {  // ×0.25 or ×0,25
        for (int i = 0; i < m_demoSpeed->count(); ++i)
            m_demoSpeed->setItemText(i, QStringLiteral("×%1").arg(QLocale().toString(m_demoSpeed->itemData(i).toDouble())));
    });
    m_demoSlider = new QSlider(Qt::Horizontal);
    m_demoSlider->setObjectName("DemoSlider");
    m_demoTime = new QLabel;
    m_demoTime->setMinimumWidth(150);
    m_demoNote = wrapped();
    m_demoNote->setObjectName("DemoNote");
    m_demoNote->setStyleSheet("color: #b35c00;");
    m_demoNote->hide();
    left->insertWidget(2, m_demoNote);
    controls->addWidget(m_demoPlay);
    auto* speedLabel = new QLabel;
    controls->addWidget(speedLabel);
    controls->addWidget(m_demoSpeed);
    controls->addWidget(m_demoSlider, 1);
    controls->addWidget(m_demoTime);
    m_demoFollow = new QCheckBox;
    m_demoFollow->setObjectName("DemoFollowCamera");
    m_texts.add([this, speedLabel] {
        speedLabel->setText(tr("Speed:"));
        m_demoFollow->setText(tr("Expert's camera"));
        m_demoFollow->setToolTip(tr("Look where the expert looked while recording (untick to move the view yourself)."));
    });
    m_demoFollow->setChecked(true);
    m_demoFollow->setEnabled(false);
    controls->addWidget(m_demoFollow);
    right->addLayout(controls);
    layout->addLayout(right, 1);

    connect(m_watchButton, &QPushButton::clicked, this, &TrainPage::watchDemonstration);
    connect(m_startButton, &QPushButton::clicked, this, [this] { startAttempt(); });
    connect(back, &QPushButton::clicked, this, &TrainPage::showCourse);
    connect(m_demoPlay, &QPushButton::clicked, this, [this] {
        if (!m_demoRunning) return watchDemonstration();
        m_runner->setPaused(!m_runner->isPaused());
        m_demoPlay->setText(m_runner->isPaused() ? tr("Play") : tr("Pause"));
    });
    connect(m_demoSpeed, &QComboBox::currentIndexChanged, this,
            [this](int) { m_runner->setSpeed(m_demoSpeed->currentData().toDouble()); });
    // scrub: seek while dragging is cheap forward; a release seeks exactly
    connect(m_demoSlider, &QSlider::sliderReleased, this, [this] {
        if (!m_demoRunning) watchDemonstration();
        m_runner->seek(m_demoSlider->value() / 10.0);
    });
    connect(m_demoSlider, &QSlider::actionTriggered, this, [this](int action) {
        if (action == QSlider::SliderMove) return;  // dragging: on release
        QTimer::singleShot(0, this, [this] {
            if (!m_demoRunning) watchDemonstration();
            m_runner->seek(m_demoSlider->value() / 10.0);
        });
    });
    return page;
}

void TrainPage::watchDemonstration()
{
    const auto t = tutorial();
    if (!t || !m_demoLog) return;
    m_runner->setSpeed(m_demoSpeed->currentData().toDouble());
    QString error;
    if (!m_runner->start(t, m_bundle, m_demoLog, m_demoProfile, false, &error)) {
        m_demoTime->setText(error);
        return;
    }
    m_demoRunning = true;
    m_shownStep = -1;
    m_demoPlay->setEnabled(true);
    m_demoPlay->setText(tr("Pause"));
}

// ---------------------------------------------------------------- attempt

QWidget* TrainPage::buildAttempt()
{
    auto* page = new QWidget;
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* viewBox = new QWidget;
    auto* grid = new QGridLayout(viewBox);
    grid->setContentsMargins(0, 0, 0, 0);
    m_attemptView = new Viewport;
    m_attemptView->setObjectName("AttemptViewport");
    m_attemptView->setFocusPolicy(Qt::StrongFocus);
    m_attemptView->installEventFilter(this);
    grid->addWidget(m_attemptView, 0, 0);

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
        m_attemptView->addOverlay(w);
    }
    // the hydraulics beside the view (never over the target), for a model with pumps
    auto* row = new QHBoxLayout;
    row->setContentsMargins(0, 0, 0, 0);
    row->setSpacing(0);
    row->addWidget(viewBox, 1);
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
    auto* attemptCentre = new QLabel;
    attemptCentre->setObjectName("CentreLink");
    attemptCentre->hide();
    m_centreLabels << attemptCentre;
    bar->addWidget(attemptCentre);
    bar->addStretch();
    m_expertBox = new QCheckBox;
    m_expertBox->setObjectName("ShowExpert");
    m_expertBox->setChecked(QSettings().value("trainer/showExpert", false).toBool());
    connect(m_expertBox, &QCheckBox::toggled, this, [this](bool on) {
        QSettings().setValue("trainer/showExpert", on);
        if (m_screen == Screen::Attempt && m_runner->isActive() && !(m_runner->latest() && m_runner->latest()->ended))
            m_runner->setGhost(on ? m_demoLog : nullptr, m_demoProfile);
        if (!on) m_attemptView->clearGhost();
        m_attemptView->setFocus();
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
        m_attemptView->setFocus();
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
    bar->addWidget(m_cameraBox);
    connect(m_cameraBox, &QComboBox::activated, this, [this](int i) {
        m_attemptView->setCamera(m_cameraBox->itemData(i).toString());
        if (m_cameraBox->itemData(i).toString() != QLatin1String("Operator seat")) frameModelAndTargets(m_attemptView);
        m_attemptView->setFocus();
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
        for (int i = 0; i < m_cameraBox->count(); ++i)
            m_cameraBox->setItemText(i, Viewport::cameraLabel(m_cameraBox->itemData(i).toString()));
        stop->setText(tr("Stop"));
        showCentreLink();
    });
    layout->addLayout(bar);
    connect(stop, &QPushButton::clicked, this, &TrainPage::stopAttempt);
    auto* esc = new QShortcut(QKeySequence(Qt::Key_Escape), page);
    esc->setContext(Qt::WidgetWithChildrenShortcut);
    connect(esc, &QShortcut::activated, this, &TrainPage::stopAttempt);
    return page;
}

void TrainPage::startAttempt(std::shared_ptr<const trainer::InputLog> drive)
{
    const auto t = tutorial();
    if (!t) return;
    leaveRun();
    m_runner->setSpeed(1.0);
    QString error;
    m_recordedInput.clear();
    // the operator's input, recorded from the session's start (a demonstration from any run)
    const bool recording = !drive && startRecording(*t);
    if (!m_runner->start(t, m_bundle, drive, drive ? m_demoProfile : m_profile, false, &error)) {
        if (recording) stopRecording();
        return;
    }
    m_expertBox->setEnabled(m_demoLog != nullptr);
    if (m_demoLog && m_expertBox->isChecked()) m_runner->setGhost(m_demoLog, m_demoProfile);
    m_attemptView->clearGhost();
    m_attemptLive = !drive;
    m_lastRun.reset();
    // the trainee records: the attempt now, its events as it goes, the result at the end
    m_attemptLog.reset();
    m_attemptTutorial = t;
    const QString code = m_operator.isEmpty() ? guestCode() : m_operator;
    m_attemptLog = std::make_unique<trainer::AttemptLog>(m_db.get(), trainer::userFolders::pendingAttempts(), code,
                                                         m_operator.isEmpty() ? tr("Guest") : code, *t, language());
    m_lastLogUpdate = QDateTime::currentMSecsSinceEpoch();
    m_shownStep = -1;
    m_hudText.clear();
    // the hydraulics (a model with pumps) beside the view before the view is framed
    if (const auto f = m_runner->latest()) m_hydraulics->setSnapshot(f->snapshot);
    setScreen(Screen::Attempt);
    // inside a scene the operator's seat; in the open, from where the target shows
    const QString camera = t->sceneFile.empty() ? QStringLiteral("Iso") : QStringLiteral("Operator seat");
    m_attemptView->resetOperatorSeat();
    m_attemptView->setCamera(camera);
    if (!t->sceneFile.empty()) aimSeatAtFirstGoal(*t);
    if (t->sceneFile.empty()) QTimer::singleShot(0, m_attemptView, [v = m_attemptView] { frameModelAndTargets(v); });
    m_cameraBox->setCurrentIndex(std::max(0, m_cameraBox->findData(camera)));
    m_attemptView->setFocus();
    if (m_attemptLive) emit attemptStarted(t);
    poll();
}

std::vector<std::shared_ptr<const trainer::Tutorial>> TrainPage::tutorials() const
{
    std::vector<std::shared_ptr<const trainer::Tutorial>> out;
    for (const Entry& e : m_entries)
        if (e.tutorial) out.push_back(e.tutorial);
    return out;
}

bool TrainPage::startAttemptFor(const QString& id, const QString& operatorCode)
{
    const int i = entryOf(id);
    if (i < 0 || !m_entries[std::size_t(i)].tutorial) return false;
    if (m_screen == Screen::Records) showCourse();
    if (operatorCode.trimmed() != m_operator) setOperator(operatorCode);
    // the instructor decides: a stage still locked for the operator opens too
    const bool unlocked = m_allUnlocked;
    m_allUnlocked = true;
    const bool open = openTutorial(id);
    m_allUnlocked = unlocked;
    if (!open) return false;
    startAttempt();
    return m_screen == Screen::Attempt && m_attemptLive;
}

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
    for (QLabel* l : m_centreLabels) {
        l->setText((warn ? QStringLiteral("⚠ ") : QStringLiteral("● ")) + text);
        l->setToolTip(text);
        l->setStyleSheet(warn ? "QLabel { color: #b26a00; font-weight: bold; }" : "QLabel { color: #1b7f3b; }");
        l->setVisible(!text.isEmpty());
    }
}

void TrainPage::aimSeatAtFirstGoal(const trainer::Tutorial& t)
{
    // where the first goal is: its target, or the load to grasp (where it is now)
    if (t.spec.goals.empty()) return;
    const trainer::Goal& g = t.spec.goals.front();
    Eigen::Vector3d p;
    if (g.kind == trainer::Goal::Kind::Reach || g.kind == trainer::Goal::Kind::Place) {
        p = g.target;
    } else if (g.kind == trainer::Goal::Kind::Grasp) {
        const auto f = m_runner->latest();
        const int i = t.model->bodyIndex(t.spec.grip.loadBodyId);
        if (!f || !f->snapshot || i < 0 || std::size_t(i) >= f->snapshot->bodyPoses.size()) return;
        p = f->snapshot->bodyPoses[std::size_t(i)] * t.spec.grip.loadPoint;
    } else {
        return;
    }
    // and the tool that goes there: the seat looks between the two
    const auto f = m_runner->latest();
    const auto worldPoint = [&](int bodyId, const Eigen::Vector3d& local, Eigen::Vector3d& out) {
        const int i = t.model->bodyIndex(bodyId);
        if (!f || !f->snapshot || i < 0 || std::size_t(i) >= f->snapshot->bodyPoses.size()) return false;
        out = f->snapshot->bodyPoses[std::size_t(i)] * local;
        return true;
    };
    Eigen::Vector3d tool;
    const bool hasTool = g.kind == trainer::Goal::Kind::Reach ? worldPoint(g.bodyId, g.point, tool)
                                                              : worldPoint(t.spec.grip.toolBodyId, t.spec.grip.toolPoint, tool);
    // when the goal is outside the middle of the view, the seat turns (the operator turns
    // their head) to see the goal and the tool, or at least the goal; its place and
    // pitch stay
    const Camera& c = m_attemptView->cameraState();
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
    m_attemptView->setOperatorSeat(c.seatEye, c.seatHeading + turn, c.seatPitch);
}

bool TrainPage::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_attemptView && event->type() == QEvent::KeyPress &&
        static_cast<QKeyEvent*>(event)->key() == Qt::Key_Escape) {
        stopAttempt();
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

void TrainPage::stopAttempt()
{
    if (m_screen == Screen::Attempt && m_runner->isActive()) m_runner->stop();
}

void TrainPage::leaveRun()
{
    const bool live = m_attemptLive;
    m_attemptLive = false;
    m_demoRunning = false;
    m_replayPlaying = false;
    if (m_demoPlay) {
        m_demoPlay->setText(tr("Play"));
        m_demoPlay->setEnabled(m_demoLog != nullptr);
    }
    if (m_runner->isActive()) m_runner->close();
    stopRecording();
    m_attemptView->clearGhost();
    m_attemptLog.reset();  // an attempt left unfinished stays "running" until the records mark it interrupted
    if (live) emit attemptEnded();
}

void TrainPage::poll()
{
    if (m_screen == Screen::Debrief && m_replayPlaying && m_lastRun && !m_lastRun->samples.empty()) {
        m_replayClock += m_timer->interval() / 1000.0;
        const auto& samples = m_lastRun->samples;
        int i = m_replaySlider->value();
        while (i + 1 < int(samples.size()) && samples[std::size_t(i + 1)].t <= m_replayClock) ++i;
        if (i + 1 >= int(samples.size())) {
            m_replayPlaying = false;
            m_replayPlay->setText(tr("Play"));
        }
        m_replaySlider->setValue(i);
        return;
    }
    const std::shared_ptr<const TrainFrame> f = m_runner->latest();
    if (!f || !f->snapshot) return;
    if (m_screen == Screen::Start && m_demoRunning) {
        if (f->snapshot->step == m_shownStep) return;
        m_shownStep = f->snapshot->step;
        m_demoView->setSnapshot(f->snapshot);
        if (!m_demoCamera.empty() && m_demoFollow->isChecked()) {
            const trainer::CameraKey k = m_demoCamera.at(f->snapshot->t);
            Camera c = m_demoView->cameraState();
            c.mode = Camera::Mode::Orbit;
            c.target = k.target;
            c.distance = k.distance;
            c.yaw = k.yaw;
            c.pitch = k.pitch;
            m_demoView->setCameraState(c);
        }
        if (!m_demoSlider->isSliderDown()) {
            const QSignalBlocker block(m_demoSlider);
            m_demoSlider->setValue(int(std::lround(f->snapshot->t * 10)));
        }
        QString text = tr("%1 s of %2 s").arg(num(f->snapshot->t, 1), num(f->duration, 0));
        if (f->ended && f->output)
            text = f->output->result.passed ? tr("Done: passed, %1 of 100").arg(num(f->output->result.score, 0))
                                            : tr("Done");
        m_demoTime->setText(text);
    } else if (m_screen == Screen::Attempt) {
        if (f->snapshot->step != m_shownStep) {
            m_shownStep = f->snapshot->step;
            m_attemptView->setSnapshot(f->snapshot);
            m_hydraulics->setSnapshot(f->snapshot);
            if (f->ghost && m_expertBox->isChecked()) m_attemptView->setGhost(f->ghost);
            else m_attemptView->clearGhost();
        }
        updateHud(*f);
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        if (m_attemptLog && !f->ended && now - m_lastLogUpdate >= kLogEveryMs) {
            m_lastLogUpdate = now;
            m_attemptLog->update(f->events);
        }
    }
}

void TrainPage::updateHud(const TrainFrame& f)
{
    const auto t = tutorial();
    if (!t) return;
    const std::string lang = language().toStdString();
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
    if (p.penalties > 0) lines << "<span style='color:#ff8a80'>" + tr("Penalties: %1").arg(num(p.penalties, 0)) + "</span>";
    if (p.grasped) lines << tr("Load in the claws");
    // the station: bank and its warnings
    QStringList warnings;
    if (m_station) {
        if (const auto st = m_station->latest()) {
            if (st->bankNames.size() > 1)
                lines << tr("Bank: <b>%1</b> (%2 of %3)")
                             .arg(st->bankNames.value(st->activeBank).toHtmlEscaped())
                             .arg(st->activeBank + 1)
                             .arg(st->bankNames.size());
            if (m_attemptLive)
                for (const QString& w : st->warnings) warnings << w.toHtmlEscaped();
        }
    }
    if (f.paused && m_attemptLive && !f.ended) warnings << tr("Paused by the instructor");
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
    for (const QString& s : warnings) w += (w.isEmpty() ? "" : "<br>") + QStringLiteral("<span style='color:#ffc04d'>⚠ %1</span>").arg(s);
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

void TrainPage::onFinished()
{
    const auto f = m_runner->latest();
    if (!f || !f->output) return;
    if (m_screen == Screen::Start && m_demoRunning) {
        m_demoPlay->setText(tr("Play"));
        poll();
        return;
    }
    if (m_screen != Screen::Attempt) return;
    poll();  // the last frame on the HUD
    stopRecording();
    m_lastRun = f->output;
    const bool live = m_attemptLive;
    m_attemptLive = false;
    const trainer::TutorialResult& r = m_lastRun->result;
    m_unwritten.clear();
    m_notRecorded = false;
    m_madeDemonstration = false;
    if (m_attemptLog) {
        m_notRecorded = !m_attemptLog->finish(r.events, r, r.endReason == "aborted");
        if (m_notRecorded) m_unwritten = m_attemptLog->problem();
        m_attemptLog.reset();
    }
    if (!m_db) {
        if (const auto t = tutorial()) CourseProgress::record(m_operator, QString::fromStdString(t->spec.id), r);
    }
    if (live) emit attemptEnded();
    showResult();
}

// ---------------------------------------------------------------- result

QWidget* TrainPage::buildResult()
{
    auto* page = new QWidget;
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(32, 24, 32, 24);
    m_resultHeading = new QLabel;
    m_resultHeading->setObjectName("ResultHeading");
    m_resultHeading->setAlignment(Qt::AlignCenter);
    m_resultStars = new QLabel;
    m_resultStars->setAlignment(Qt::AlignCenter);
    m_resultStars->setStyleSheet("font-size: 44px; color: #e6a700;");
    m_resultScore = new QLabel;
    m_resultScore->setObjectName("ResultScore");
    m_resultScore->setAlignment(Qt::AlignCenter);
    m_resultScore->setWordWrap(true);
    m_resultScore->setStyleSheet("font-size: 20pt;");
    layout->addWidget(m_resultHeading);
    layout->addWidget(m_resultStars);
    layout->addWidget(m_resultScore);
    m_resultNote = wrapped();
    m_resultNote->setObjectName("ResultNote");
    m_resultNote->setAlignment(Qt::AlignCenter);
    m_resultNote->setStyleSheet("color: #b35c00;");
    layout->addWidget(m_resultNote);
    auto* middle = new QHBoxLayout;
    m_breakdown = new QTableWidget(0, 4);
    m_breakdown->setObjectName("Breakdown");
    m_breakdown->verticalHeader()->hide();
    m_breakdown->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_breakdown->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_breakdown->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    m_breakdown->horizontalHeader()->setSectionResizeMode(3, QHeaderView::ResizeToContents);
    m_breakdown->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_breakdown->setSelectionMode(QAbstractItemView::NoSelection);
    auto* left = new QVBoxLayout;
    auto* scoreTitle = new QLabel;
    left->addWidget(scoreTitle);
    left->addWidget(m_breakdown);
    middle->addLayout(left, 1);
    auto* right = new QVBoxLayout;
    auto* improveTitle = new QLabel;
    right->addWidget(improveTitle);
    m_improvements = new QListWidget;
    m_improvements->setObjectName("Improvements");
    m_improvements->setWordWrap(true);
    m_improvements->setStyleSheet("QListWidget::item { padding: 6px 2px; }");
    right->addWidget(m_improvements);
    middle->addLayout(right, 1);
    layout->addLayout(middle, 1);
    auto* buttons = new QHBoxLayout;
    auto* course = new QPushButton;
    auto* retryButton = new QPushButton;
    retryButton->setObjectName("RetryButton");
    auto* debrief = new QPushButton;
    debrief->setObjectName("DebriefButton");
    m_nextButton = new QPushButton;
    m_nextButton->setObjectName("NextButton");
    buttons->addWidget(course);
    m_saveDemoButton = new QPushButton;
    m_saveDemoButton->setObjectName("SaveDemoButton");
    m_useDemoButton = new QPushButton;
    m_useDemoButton->setObjectName("UseDemoButton");
    m_texts.add([=, this] {
        m_breakdown->setHorizontalHeaderLabels({tr("Measure"), tr("Measured"), tr("Points"), tr("Of")});
        scoreTitle->setText("<b>" + tr("Score") + "</b>");
        improveTitle->setText("<b>" + tr("What to improve") + "</b>");
        course->setText(tr("Course"));
        retryButton->setText(tr("Retry"));
        debrief->setText(tr("Debrief"));
        m_nextButton->setText(tr("Next stage"));
        m_saveDemoButton->setText(tr("Save as demonstration…"));
        m_saveDemoButton->setToolTip(tr("Saves the operator's input of this attempt as an input log."));
        m_useDemoButton->setText(tr("Use as this stage's demonstration"));
        m_useDemoButton->setToolTip(tr("From now on the demonstration, the expert and the comparison of this stage "
                                       "replay this attempt's input instead of the shipped one."));
    });
    buttons->addWidget(m_saveDemoButton);
    buttons->addWidget(m_useDemoButton);
    connect(m_saveDemoButton, &QPushButton::clicked, this, [this] {
        const auto t = tutorial();
        if (!t) return;
        const QString path = QFileDialog::getSaveFileName(
            this, tr("Save as demonstration"), userDemonstrationPath(QString::fromStdString(t->spec.id)),
            tr("Padrob input logs (*.log);;All files (*)"));
        QString error;
        if (!path.isEmpty() && !saveDemonstration(path, &error))
            QMessageBox::warning(this, tr("Save as demonstration"), error);
    });
    connect(m_useDemoButton, &QPushButton::clicked, this, [this] {
        QString error;
        if (useAsDemonstration({}, &error)) {
            m_madeDemonstration = true;
            fillResult();
        } else {
            QMessageBox::warning(this, tr("Use as this stage's demonstration"), error);
        }
    });
    buttons->addStretch();
    buttons->addWidget(retryButton);
    buttons->addWidget(debrief);
    buttons->addWidget(m_nextButton);
    layout->addLayout(buttons);
    connect(course, &QPushButton::clicked, this, &TrainPage::showCourse);
    connect(retryButton, &QPushButton::clicked, this, &TrainPage::retry);
    connect(debrief, &QPushButton::clicked, this, &TrainPage::showDebrief);
    connect(m_nextButton, &QPushButton::clicked, this, &TrainPage::nextStage);
    return page;
}

void TrainPage::showResult()
{
    if (!m_lastRun) return;
    fillResult();
    setScreen(Screen::Result);
}

void TrainPage::fillResult()
{
    if (!m_lastRun) return;
    const trainer::TutorialResult& r = m_lastRun->result;
    m_resultHeading->setText(r.passed ? tr("PASSED") : tr("NOT PASSED"));
    m_resultHeading->setStyleSheet(QStringLiteral("font-size: 40px; font-weight: bold; color: %1;")
                                       .arg(r.passed ? "#2e9d4a" : "#c0392b"));
    m_resultStars->setText(stars(r.stars));
    QString why;
    if (r.endReason == "time-up") why = tr("The time ran out.");
    else if (r.endReason == "hard-hit") why = tr("The machine hit the scene too hard.");
    else if (r.endReason == "worker-hit") why = tr("The machine touched a worker.");
    else if (r.endReason == "aborted") why = tr("The attempt was stopped.");
    else if (r.endReason == "input-ended") why = tr("The input ended before the goals were done.");
    else if (r.endReason == "solver-error") why = tr("The simulation failed.");
    const QString score = tr("Score %1 of 100 in %2 s").arg(num(r.score, 0), num(r.time, 1));
    m_resultScore->setText(why.isEmpty() ? score : score + QLatin1Char('\n') + why);
    QString note;
    if (m_notRecorded)
        note = tr("The trainee records could not be written (%1); the attempt is kept and will be added the next "
                  "time they can.").arg(m_unwritten);
    else if (m_madeDemonstration)
        note = tr("This attempt is now the stage's demonstration.");
    m_resultNote->setText(note);
    m_breakdown->setRowCount(int(r.breakdown.size()));
    for (int i = 0; i < int(r.breakdown.size()); ++i) {
        const trainer::ScoreItem& s = r.breakdown[std::size_t(i)];
        QString measured;
        if (s.key == "time") measured = tr("%1 s").arg(num(s.value, 1));
        else if (s.key == "path") measured = tr("%1 %").arg(num(s.value, 0));
        else if (s.key == "smooth") measured = tr("%1 m/s³").arg(num(s.value, 2));
        else if (s.key == "safety") measured = tr("%1 penalty points").arg(num(s.value, 0));
        else measured = num(s.value, 2);
        m_breakdown->setItem(i, 0, new QTableWidgetItem(s.label()));
        m_breakdown->setItem(i, 1, new QTableWidgetItem(measured));
        m_breakdown->setItem(i, 2, new QTableWidgetItem(num(s.points, 1)));
        m_breakdown->setItem(i, 3, new QTableWidgetItem(num(s.max, 0)));
        for (int c = 1; c < 4; ++c) m_breakdown->item(i, c)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    }
    m_improvements->clear();
    const QStringList advice = r.improvements();
    m_improvements->addItems(advice.isEmpty() ? QStringList{tr("Nothing: a clean run.")} : advice);
    const int next = m_current + 1;
    loadProgress();  // the attempt just recorded may unlock the next stage
    m_nextButton->setEnabled(next < int(m_entries.size()) && m_entries[std::size_t(next)].tutorial && !isLocked(next));
    const bool recorded = !m_recordedInput.isEmpty();
    m_saveDemoButton->setVisible(recorded && !m_kiosk);  // for trainers
    m_useDemoButton->setVisible(recorded && !m_kiosk);
}

void TrainPage::retry()
{
    if (tutorial()) startAttempt();
}

void TrainPage::nextStage()
{
    const int next = m_current + 1;
    if (next < int(m_entries.size())) openTutorial(m_entries[std::size_t(next)].id);
}

// ---------------------------------------------------------------- debrief

QWidget* TrainPage::buildDebrief()
{
    auto* page = new QWidget;
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(12, 12, 12, 12);
    auto* split = new QSplitter(Qt::Horizontal);
    // the replay and its controls
    auto* replayBox = new QWidget;
    auto* replay = new QVBoxLayout(replayBox);
    replay->setContentsMargins(0, 0, 0, 0);
    m_replayView = new Viewport;
    m_replayView->setMinimumSize(400, 300);
    replay->addWidget(m_replayView, 1);
    auto* controls = new QHBoxLayout;
    m_replayPlay = new QPushButton;
    m_replaySlider = new QSlider(Qt::Horizontal);
    m_replaySlider->setObjectName("ReplaySlider");
    m_replayTime = new QLabel;
    m_replayTime->setMinimumWidth(90);
    controls->addWidget(m_replayPlay);
    controls->addWidget(m_replaySlider, 1);
    controls->addWidget(m_replayTime);
    replay->addLayout(controls);
    m_forceChart = new QChartView;
    m_forceChart->setObjectName("ForceChart");
    m_forceChart->setMinimumHeight(200);
    m_forceChart->setRenderHint(QPainter::Antialiasing);
    m_reliefChart = new QChartView;
    m_reliefChart->setObjectName("ReliefChart");
    m_reliefChart->setMinimumHeight(150);
    replay->addWidget(m_forceChart);
    replay->addWidget(m_reliefChart);
    split->addWidget(replayBox);
    // the events and the expert
    auto* side = new QWidget;
    auto* sideLayout = new QVBoxLayout(side);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    auto* eventsTitle = new QLabel;
    sideLayout->addWidget(eventsTitle);
    m_timeline = new QListWidget;
    m_timeline->setObjectName("Timeline");
    m_timeline->setWordWrap(true);
    sideLayout->addWidget(m_timeline, 1);
    auto* expertTitle = new QLabel;
    sideLayout->addWidget(expertTitle);
    m_comparison = new QTableWidget(5, 3);
    m_comparison->setObjectName("Comparison");
    m_comparison->verticalHeader()->hide();
    m_comparison->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_comparison->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_comparison->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    m_comparison->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_comparison->setSelectionMode(QAbstractItemView::NoSelection);
    m_comparison->setMinimumHeight(200);
    sideLayout->addWidget(m_comparison);
    auto* back = new QPushButton;
    sideLayout->addWidget(back);
    m_texts.add([=, this] {
        m_replayPlay->setText(m_replayPlaying ? tr("Pause") : tr("Play"));
        eventsTitle->setText("<b>" + tr("Events") + "</b>");
        expertTitle->setText("<b>" + tr("You and the expert") + "</b>");
        m_comparison->setHorizontalHeaderLabels({tr("Measure"), tr("You"), tr("Expert")});
        back->setText(tr("Back to the result"));
    });
    split->addWidget(side);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    layout->addWidget(split);

    connect(back, &QPushButton::clicked, this, [this] {
        m_replayPlaying = false;
        setScreen(Screen::Result);
    });
    connect(m_replaySlider, &QSlider::valueChanged, this, &TrainPage::showReplaySample);
    connect(m_replayPlay, &QPushButton::clicked, this, [this] {
        if (!m_lastRun || m_lastRun->samples.empty()) return;
        m_replayPlaying = !m_replayPlaying;
        if (m_replayPlaying) {
            if (m_replaySlider->value() >= m_replaySlider->maximum()) m_replaySlider->setValue(0);
            m_replayClock = m_lastRun->samples[std::size_t(m_replaySlider->value())].t;
        }
        m_replayPlay->setText(m_replayPlaying ? tr("Pause") : tr("Play"));
    });
    connect(m_timeline, &QListWidget::itemClicked, this, [this](QListWidgetItem* it) {
        if (!m_lastRun) return;
        const double t = it->data(Qt::UserRole).toDouble();
        const auto& s = m_lastRun->samples;
        const auto at = std::lower_bound(s.begin(), s.end(), t,
                                         [](const trainer::SessionSample& a, double v) { return a.t < v; });
        m_replaySlider->setValue(int(std::min<std::ptrdiff_t>(at - s.begin(), std::ptrdiff_t(s.size()) - 1)));
    });
    return page;
}

void TrainPage::showDebrief()
{
    if (!m_lastRun) return;
    fillDebrief();
    setScreen(Screen::Debrief);
    computeExpert();
}

void TrainPage::showReplaySample(int index)
{
    if (!m_lastRun || index < 0 || index >= int(m_lastRun->samples.size())) return;
    const trainer::SessionSample& s = m_lastRun->samples[std::size_t(index)];
    m_replayView->setSnapshot(snapshotFromSample(s, m_bundle));
    m_replayTime->setText(tr("%1 s").arg(num(s.t, 2)));
    if (!m_replayPlaying) m_replayClock = s.t;
}

namespace {

/// Labels with as many decimals as the ticks need ("%.1f": QtCharts' localized labels
/// take only 'f' formats, not "%g").
void decimalsForTicks(QValueAxis* axis)
{
    const double step = axis->tickCount() > 1 ? (axis->max() - axis->min()) / (axis->tickCount() - 1) : 1.0;
    int decimals = 0;
    while (decimals < 3 && std::abs(step * std::pow(10.0, decimals) - std::round(step * std::pow(10.0, decimals))) > 1e-6)
        ++decimals;
    axis->setLabelFormat(QStringLiteral("%.%1f").arg(decimals));
}

/// A chart of one series against the time, its numbers in the locale's format.
QChart* makeChart(const QString& title, QLineSeries* series, const QString& yTitle, double yMin, double yMax, double tMax)
{
    auto* chart = new QChart;
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->setLocalizeNumbers(true);
    chart->setLocale(QLocale());
    chart->setTitle(title);
    chart->legend()->hide();
    chart->addSeries(series);
    auto* x = new QValueAxis;
    x->setTitleText(QCoreApplication::translate("studio::TrainPage", "t [s]"));
    x->setRange(0, std::max(1.0, tMax));
    auto* y = new QValueAxis;
    y->setTitleText(yTitle);
    y->setRange(yMin, yMax);
    x->applyNiceNumbers();
    y->applyNiceNumbers();
    decimalsForTicks(x);
    decimalsForTicks(y);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    series->attachAxis(x);
    series->attachAxis(y);
    chart->setMargins(QMargins(4, 4, 4, 4));
    return chart;
}

}  // namespace

void TrainPage::fillDebrief()
{
    const auto& samples = m_lastRun->samples;
    m_replayPlaying = false;
    m_replayPlay->setText(tr("Play"));
    m_replaySlider->setRange(0, std::max(0, int(samples.size()) - 1));
    m_replaySlider->setValue(0);
    showReplaySample(0);
    QTimer::singleShot(0, m_replayView, [v = m_replayView] { frameModelAndTargets(v); });
    fillTimeline();
    fillCharts();
    fillComparison();
}

void TrainPage::fillTimeline()
{
    if (!m_lastRun) return;
    const auto t = tutorial();
    const std::string lang = language().toStdString();
    const int row = m_timeline->currentRow();
    m_timeline->clear();
    for (const trainer::TutorialEvent& e : m_lastRun->result.events) {
        auto* it = new QListWidgetItem(tr("%1 s — %2").arg(num(e.t, 1), e.text(t.get(), lang)));
        it->setData(Qt::UserRole, e.t);
        m_timeline->addItem(it);
    }
    if (m_lastRun->result.events.empty()) m_timeline->addItem(tr("No events."));
    if (row >= 0 && row < m_timeline->count()) {
        const QSignalBlocker block(m_timeline);
        m_timeline->setCurrentRow(row);
    }
}

void TrainPage::fillCharts()
{
    // the most loaded drive's force, and the relief valves open, against time
    if (!m_lastRun || !m_bundle) return;
    const auto& samples = m_lastRun->samples;
    const solver::Model& m = *m_bundle->model;
    int joint = -1;
    double most = 0.0;
    for (const trainer::SessionSample& s : samples)
        for (std::size_t j = 0; j < s.driveForce.size(); ++j)
            if (std::abs(s.driveForce[j]) > most) {
                most = std::abs(s.driveForce[j]);
                joint = int(j);
            }
    const double tMax = samples.empty() ? 1.0 : samples.back().t;
    auto* force = new QLineSeries;
    double lo = 0.0, hi = 0.0;
    const bool linear = joint >= 0 && m.jointType[std::size_t(joint)] != solver::JointType::Revolute;
    const double scale = 1e-3;  // kN or kN·m
    if (joint >= 0) {
        for (const trainer::SessionSample& s : samples) {
            const double v = s.driveForce[std::size_t(joint)] * scale;
            force->append(s.t, v);
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    const double pad = std::max(0.1, 0.08 * (hi - lo));
    QString name;
    if (joint >= 0) {
        name = QStringLiteral("C %1").arg(m.jointId[std::size_t(joint)]);
        if (!m.jointName[std::size_t(joint)].empty()) name += ' ' + QString::fromStdString(m.jointName[std::size_t(joint)]);
    }
    QChart* old = m_forceChart->chart();
    m_forceChart->setChart(makeChart(joint >= 0 ? tr("Force of %1").arg(name) : tr("No drive force"), force,
                                     linear ? tr("kN") : tr("kN·m"), lo - pad, hi + pad, tMax));
    delete old;
    auto* relief = new QLineSeries;
    int reliefMax = 1;
    for (const trainer::SessionSample& s : samples) {
        const int open = int(std::count(s.relief.begin(), s.relief.end(), std::uint8_t(1)));
        reliefMax = std::max(reliefMax, open);
        relief->append(s.t, open);
    }
    old = m_reliefChart->chart();
    m_reliefChart->setChart(makeChart(tr("Relief valves open"), relief, tr("valves"), 0, reliefMax + 0.2, tMax));
    delete old;
}

void TrainPage::computeExpert()
{
    const auto t = tutorial();
    if (!t || !m_demoLog || m_expertBusy) return;
    const QString id = QString::fromStdString(t->spec.id);
    if (m_expert && m_expertFor == id) return fillComparison();
    m_expertBusy = true;
    auto log = m_demoLog;
    auto profile = m_demoProfile;
    QPointer<TrainPage> self(this);
    QThread* worker = QThread::create([self, t, log, profile, id] {
        auto out = std::make_shared<trainer::RunOutput>();
        QString error;
        const bool ok = trainer::runTutorialWithLog(t, log, profile, *out, &error, TutorialRunner::kGrace);
        // back in the GUI thread, where the page may have gone meanwhile
        QMetaObject::invokeMethod(qApp, [self, out, ok, id] {
            if (!self) return;
            self->m_expertBusy = false;
            if (!ok) return;
            self->m_expert = out;
            self->m_expertFor = id;
            self->fillComparison();
        }, Qt::QueuedConnection);
    });
    connect(worker, &QThread::finished, worker, &QObject::deleteLater);
    worker->start(QThread::LowPriority);
}

void TrainPage::fillComparison()
{
    if (!m_lastRun) return;
    const trainer::TutorialResult& you = m_lastRun->result;
    const trainer::TutorialResult* expert = m_expert ? &m_expert->result : nullptr;
    const struct {
        QString label;
        double a, b;
        int decimals;
    } rows[] = {
        {tr("Time [s]"), you.time, expert ? expert->time : 0.0, 1},
        {tr("Path length [m]"), you.pathLength, expert ? expert->pathLength : 0.0, 2},
        {tr("Overshoot [m]"), you.overshoot, expert ? expert->overshoot : 0.0, 3},
        {tr("RMS jerk [m/s³]"), you.rmsJerk, expert ? expert->rmsJerk : 0.0, 2},
        {tr("Score"), you.score, expert ? expert->score : 0.0, 0},
    };
    m_comparison->setRowCount(5);
    for (int i = 0; i < 5; ++i) {
        m_comparison->setItem(i, 0, new QTableWidgetItem(rows[i].label));
        m_comparison->setItem(i, 1, new QTableWidgetItem(num(rows[i].a, rows[i].decimals)));
        m_comparison->setItem(i, 2, new QTableWidgetItem(expert ? num(rows[i].b, rows[i].decimals)
                                                                : (m_demoLog ? tr("…") : tr("none"))));
    }
}

}  // namespace studio
