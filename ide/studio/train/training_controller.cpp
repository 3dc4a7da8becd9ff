#include "ide/studio/train/training_controller.h"

#include "ide/i18n/language.h"
#include "ide/studio/train/tutorial_runner.h"
#include "trainer/io/user_folders.h"
#include "trainer/station/station.h"
#include "trainer/training/attempt_log.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QPointer>
#include <QSettings>
#include <QThread>

#include <algorithm>

namespace studio {

namespace {

constexpr qint64 kLogEveryMs = 500;  // events to the records this often during an attempt

constexpr int kKeptRecordings = 20;  // older recordings are deleted

/// The station profile saved beside an input log.
QString profileBeside(const QString& log)
{
    return log + QStringLiteral(".profile.json");
}

QString settingsKey(const QString& op, const QString& id, const char* what)
{
    return QStringLiteral("trainer/progress/%1/%2/%3")
        .arg(op.isEmpty() ? QStringLiteral("-") : op, id, QLatin1String(what));
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

// ---------------------------------------------------------------- controller

TrainingController::TrainingController(TutorialRunner* runner, trainer::Station* station, QObject* parent)
    : QObject(parent), m_runner(runner), m_station(station)
{
    m_operator = QSettings().value("trainer/operator").toString();
    openRecords();
}

TrainingController::~TrainingController()
{
    stopRecording();
    if (m_runner->isActive()) m_runner->close();
    m_attemptLog.reset();  // before the records close
}

QString TrainingController::language()
{
    return i18n::current();
}

QString TrainingController::operatorCode(const QString& id)
{
    return id.isEmpty() ? QStringLiteral("guest") : id;
}

// ---------------------------------------------------------------- the course

void TrainingController::setTutorialsDir(const QString& dir)
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
                const trainer::TutorialSpec spec = trainer::parseTutorial(file.readAll().toStdString(),
                                                                          e.path.toStdString(), ignored);
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
}

void TrainingController::retitle()
{
    const std::string lang = language().toStdString();
    for (Entry& e : m_entries) {
        e.title = QString::fromStdString(e.titleText.in(lang));
        if (e.title.isEmpty()) e.title = QFileInfo(e.path).completeBaseName();
    }
}

int TrainingController::entryOf(const QString& id) const
{
    for (std::size_t i = 0; i < m_entries.size(); ++i)
        if (m_entries[i].id == id) return int(i);
    return -1;
}

bool TrainingController::isLocked(int entry) const
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

std::vector<std::shared_ptr<const trainer::Tutorial>> TrainingController::tutorials() const
{
    std::vector<std::shared_ptr<const trainer::Tutorial>> out;
    for (const Entry& e : m_entries)
        if (e.tutorial) out.push_back(e.tutorial);
    return out;
}

// ---------------------------------------------------------------- the operator and the records

void TrainingController::openRecords(const QString& path)
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

bool TrainingController::openRecordsAt(const QString& path)
{
    if (m_attemptLog) return false;  // not during an attempt
    m_db.reset();
    openRecords(path);
    setOperator(m_operator);
    return m_db != nullptr;
}

void TrainingController::setOperator(const QString& id)
{
    m_operator = id.trimmed();
    QSettings s;
    s.setValue("trainer/operator", m_operator);
    if (m_db) {
        // the records know operators by code; a new code is a new operator
        const QString code = operatorCode(m_operator);
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
    loadProgress();
}

QStringList TrainingController::knownOperators() const
{
    if (!m_db) return QSettings().value("trainer/operators").toStringList();
    QList<trainer::records::OperatorProgress> all;
    QStringList codes;
    if (m_db->progress(all))
        for (const auto& p : all)
            if (p.op.code != operatorCode({})) codes << p.op.code;
    return codes;
}

void TrainingController::loadProgress()
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

CourseProgress TrainingController::progressOf(const QString& tutorialId) const
{
    return m_db ? m_progress.value(tutorialId) : CourseProgress::load(m_operator, tutorialId);
}

// ---------------------------------------------------------------- the open tutorial

std::shared_ptr<const trainer::Tutorial> TrainingController::tutorial() const
{
    return m_current >= 0 ? m_entries[std::size_t(m_current)].tutorial : nullptr;
}

bool TrainingController::open(int i, bool* newModel)
{
    if (newModel) *newModel = false;
    if (i < 0 || i >= int(m_entries.size()) || !m_entries[std::size_t(i)].tutorial) return false;
    const trainer::Tutorial& t = *m_entries[std::size_t(i)].tutorial;
    if (m_current != i || !m_bundle) {
        QString error;
        m_bundle = makeTutorialBundle(t, &error);
        if (!m_bundle) {
            m_entries[std::size_t(i)].problem = error;
            return false;
        }
        m_scene = makeTutorialScene(t);
        forgetExpert();
        if (newModel) *newModel = true;
    }
    m_current = i;
    QString error;
    if (!trainer::tutorialProfile(t, {}, m_profile, &error)) m_profile = trainer::StationProfile{};
    loadDemonstration(t);
    return true;
}

// ---------------------------------------------------------------- demonstrations

QString TrainingController::userDemonstrationPath(const QString& tutorialId)
{
    return trainer::userFolders::demonstrations() + QLatin1Char('/') + tutorialId + QStringLiteral(".demo.log");
}

QString TrainingController::demoWarning() const
{
    if (m_demoUnreadable.isEmpty()) return {};
    return tr("The demonstration chosen for this stage (%1) cannot be read: %2. The shipped demonstration is used.")
        .arg(m_demoUnreadable.value(0), m_demoUnreadable.value(1));
}

void TrainingController::loadDemonstration(const trainer::Tutorial& t)
{
    const QString id = QString::fromStdString(t.spec.id);
    const QString before = m_demoFile;
    m_demoLog.reset();
    m_demoFile.clear();
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
            qWarning("Train: %s", qPrintable(demoWarning()));
        }
    }
    // the shipped demonstration's camera (a trainer's own recording has none)
    m_demoCamera = trainer::CameraPath();
    if (m_demoFile.isEmpty() && !t.cameraFile.empty()) {
        QString cameraError;
        if (!trainer::CameraPath::load(QString::fromStdString(t.cameraFile), m_demoCamera, &cameraError))
            qWarning("Train: %s", qPrintable(cameraError));
    }
    if (!m_demoLog && !t.demoFile.empty()) {
        auto log = std::make_shared<trainer::InputLog>();
        const QString shipped = QString::fromStdString(t.demoFile);
        if (trainer::InputLog::load(shipped, *log, nullptr)) {
            m_demoLog = log;
            m_demoFile = shipped;
        }
    }
    if (m_demoFile != before) forgetExpert();  // the expert's run was of another log
}

bool TrainingController::saveDemonstration(const QString& path, QString* error)
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

bool TrainingController::useAsDemonstration(const QString& pathIn, QString* error)
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

void TrainingController::useShippedDemonstration()
{
    const auto t = tutorial();
    if (!t) return;
    QSettings().remove("trainer/demo/" + QString::fromStdString(t->spec.id));
    loadDemonstration(*t);
}

// ---------------------------------------------------------------- the attempt

bool TrainingController::startRecording(const trainer::Tutorial& t)
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
    const QString file = dir.filePath(
        QStringLiteral("%1-%2.log")
            .arg(QString::fromStdString(t.spec.id), QDateTime::currentDateTime().toString("yyyyMMdd-HHmmss-zzz")));
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

void TrainingController::stopRecording()
{
    if (!m_recorder) return;
    QString error;
    const bool ok = m_station ? m_station->stopRecording(*m_recorder, &error) : m_recorder->stop(&error);
    m_recorder.reset();
    if (!ok) {
        qWarning("Train: the attempt's input log %s may be incomplete: %s", qPrintable(m_recordingFile),
                 qPrintable(error));
        return;
    }
    QFile json(profileBeside(m_recordingFile));
    if (json.open(QIODevice::WriteOnly)) json.write(m_recordingProfile.toJson());
    m_recordedInput = m_recordingFile;
}

bool TrainingController::beginAttempt(std::shared_ptr<const trainer::InputLog> drive)
{
    const auto t = tutorial();
    if (!t) return false;
    m_runner->setSpeed(1.0);
    QString error;
    m_recordedInput.clear();
    // the operator's input, recorded from the session's start (a demonstration from any run)
    const bool recording = !drive && startRecording(*t);
    if (!m_runner->start(t, m_bundle, drive, drive ? m_demoProfile : m_profile, false, &error)) {
        if (recording) stopRecording();
        return false;
    }
    m_attemptLive = !drive;
    m_lastRun.reset();
    // the trainee records: the attempt now, its events as it goes, the result at the end
    m_attemptLog.reset();
    m_attemptTutorial = t;
    const QString code = operatorCode(m_operator);
    m_attemptLog = std::make_unique<trainer::AttemptLog>(m_db.get(), trainer::userFolders::pendingAttempts(), code,
                                                         m_operator.isEmpty() ? tr("Guest") : code, *t, language());
    m_lastLogUpdate = QDateTime::currentMSecsSinceEpoch();
    return true;
}

void TrainingController::logProgress(const TrainFrame& f)
{
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    if (m_attemptLog && !f.ended && now - m_lastLogUpdate >= kLogEveryMs) {
        m_lastLogUpdate = now;
        m_attemptLog->update(f.events);
    }
}

bool TrainingController::finishAttempt(std::shared_ptr<const trainer::RunOutput> output)
{
    stopRecording();
    m_lastRun = std::move(output);
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
    return live;
}

bool TrainingController::leaveAttempt()
{
    const bool live = m_attemptLive;
    m_attemptLive = false;
    if (m_runner->isActive()) m_runner->close();
    stopRecording();
    m_attemptLog.reset();  // an attempt left unfinished stays "running" until the records mark it interrupted
    return live;
}

// ---------------------------------------------------------------- the expert

void TrainingController::forgetExpert()
{
    m_expert.reset();
    m_expertFor.clear();
}

void TrainingController::computeExpert()
{
    const auto t = tutorial();
    if (!t || !m_demoLog || m_expertBusy) return;
    const QString id = QString::fromStdString(t->spec.id);
    if (m_expert && m_expertFor == id) {
        emit expertReady();
        return;
    }
    m_expertBusy = true;
    auto log = m_demoLog;
    auto profile = m_demoProfile;
    QPointer<TrainingController> self(this);
    QThread* worker = QThread::create([self, t, log, profile, id] {
        auto out = std::make_shared<trainer::RunOutput>();
        QString error;
        const bool ok = trainer::runTutorialWithLog(t, log, profile, *out, &error, TutorialRunner::kGrace);
        // back in the GUI thread, where the controller may have gone meanwhile
        QMetaObject::invokeMethod(
            qApp,
            [self, out, ok, id] {
                if (!self) return;
                self->m_expertBusy = false;
                if (!ok) return;
                self->m_expert = out;
                self->m_expertFor = id;
                emit self->expertReady();
            },
            Qt::QueuedConnection);
    });
    connect(worker, &QThread::finished, worker, &QObject::deleteLater);
    worker->start(QThread::LowPriority);
}

}  // namespace studio
