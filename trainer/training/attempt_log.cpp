#include "trainer/training/attempt_log.h"

#include "trainer/io/read_file.h"

#include "solver/core/output_file.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QFileInfo>
#include <QUuid>

#include <cmath>

namespace trainer {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(AttemptLog)
};

constexpr const char* kPendingFormat = "padrob-pending-attempt";

}  // namespace

QList<records::AttemptEvent> toRecordEvents(const std::vector<TutorialEvent>& events, std::size_t from,
                                           const Tutorial* tutorial, const std::string& language)
{
    QList<records::AttemptEvent> out;
    for (std::size_t i = from; i < events.size(); ++i) {
        const TutorialEvent& e = events[i];
        out.append({e.t, QString::fromLatin1(TutorialEvent::key(e.kind)), e.text(tutorial, language), e.value, e.penalty,
                    QString::fromStdString(e.detail)});
    }
    return out;
}

records::AttemptResult toRecordResult(const TutorialResult& r, bool aborted)
{
    records::AttemptResult out;
    out.status = aborted ? records::AttemptStatus::Aborted : records::AttemptStatus::Finished;
    out.durationS = r.time;
    out.score = std::clamp(r.score, 0.0, 100.0);
    out.stars = r.stars;
    out.passed = r.passed;
    for (const ScoreItem& i : r.breakdown) {
        out.breakdown.append({QString::fromStdString(i.key), i.label(), i.value, i.points, i.max});
    }
    return out;
}

AttemptLog::AttemptLog(records::AttemptRecorder* db, QString pendingFolder, const QString& operatorCode,
                       const QString& operatorName, const Tutorial& tutorial, const QString& language)
    : m_db(db), m_tutorial(&tutorial), m_folder(std::move(pendingFolder)), m_operatorCode(operatorCode.trimmed()),
      m_operatorName(operatorName)
{
    m_start.tutorialId = QString::fromStdString(tutorial.spec.id);
    m_start.tutorialTitle = QString::fromStdString(tutorial.title(language.toStdString()));
    m_start.language = language;
    m_start.started = QDateTime::currentDateTimeUtc();
    m_start.uid = QUuid::createUuid().toString(QUuid::WithoutBraces);
    m_pendingFile = QDir(m_folder).filePath(
        QStringLiteral("attempt-%1-%2.json").arg(m_start.started.toString("yyyyMMdd-HHmmss-zzz"), m_start.uid));
    // on the disk before the database is asked: a database that hangs or refuses, then
    // a kill, loses nothing
    writePending({}, nullptr, false);
    if (ensureBegun()) dropPending();
}

bool AttemptLog::ensureBegun()
{
    if (m_attempt > 0) return true;
    if (!m_db || !m_db->isOpen()) {
        if (m_problem.isEmpty()) m_problem = Tr::tr("the records database is not open: this attempt is kept aside and recorded later");
        return false;
    }
    QString error;
    if (m_start.operatorId <= 0) m_start.operatorId = m_db->operatorFor(m_operatorCode, m_operatorName, &error);
    if (m_start.operatorId > 0) m_attempt = m_db->beginAttempt(m_start, &error);
    if (m_attempt <= 0) {
        m_start.operatorId = std::max<qint64>(m_start.operatorId, 0);
        m_attempt = 0;
        m_problem = error;
        return false;
    }
    return true;
}

void AttemptLog::update(const std::vector<TutorialEvent>& events)
{
    if (m_written < events.size() && ensureBegun()) {
        QString error;
        if (m_db->appendEvents(m_attempt, toRecordEvents(events, m_written, m_tutorial, m_start.language.toStdString()), &error)) {
            m_written = events.size();
            m_problem.clear();
        } else {
            m_problem = error;
        }
    }
    if (m_attempt > 0 && m_written == events.size()) {
        dropPending();
    } else if (!m_pendingOnDisk || m_pendingEvents != events.size()) {
        writePending(events, nullptr, false);  // what the database refuses, kept aside
    }
}

bool AttemptLog::finish(const std::vector<TutorialEvent>& events, const TutorialResult& result, bool aborted)
{
    update(events);
    QString error;
    if (m_attempt > 0 && m_written == events.size() &&
        m_db->finishAttempt(m_attempt, toRecordResult(result, aborted), &error)) {
        dropPending();
        return true;
    }
    if (!error.isEmpty()) m_problem = error;
    // the database refused: the whole record goes to the pending file (complete on its
    // own; importPending() completes the attempt the database had begun, if it had)
    const QString why = m_problem;
    if (writePending(events, &result, aborted)) {
        m_problem = Tr::tr("%1 — this attempt was saved in %2 and will be recorded when the database can be written")
                        .arg(why, QDir::toNativeSeparators(m_pendingFile));
    }
    return false;
}

bool AttemptLog::writePending(const std::vector<TutorialEvent>& events, const TutorialResult* result, bool aborted)
{
    QJsonObject o;
    o["format"] = QString::fromLatin1(kPendingFormat);
    o["version"] = 2;
    o["code"] = m_operatorCode;  // the operator, by code: ids are a database's own
    o["name"] = m_operatorName;
    o["tutorial"] = m_start.tutorialId;
    o["title"] = m_start.tutorialTitle;
    o["language"] = m_start.language;
    o["started"] = m_start.started.toString(Qt::ISODateWithMs);
    o["uid"] = m_start.uid;  // completes the attempt the database began (or begins one with it)
    if (result) {
        const records::AttemptResult r = toRecordResult(*result, aborted);
        QJsonArray breakdown;
        for (const records::ScoreItem& i : r.breakdown) {
            breakdown.append(QJsonObject{{"key", i.key}, {"label", i.label}, {"value", i.value}, {"points", i.points}, {"max", i.maxPoints}});
        }
        o["result"] = QJsonObject{{"aborted", aborted}, {"duration", r.durationS}, {"score", r.score},
                                  {"stars", r.stars},   {"passed", r.passed},     {"breakdown", breakdown}};
    }
    QJsonArray list;
    for (const records::AttemptEvent& e : toRecordEvents(events, 0, m_tutorial, m_start.language.toStdString())) {
        list.append(QJsonObject{{"t", e.t}, {"kind", e.kind}, {"text", e.text}, {"value", std::isfinite(e.value) ? QJsonValue(e.value) : QJsonValue()},
                                {"penalty", e.penalty}, {"detail", e.detail}});
    }
    o["events"] = list;
    const QByteArray bytes = QJsonDocument(o).toJson();
    // written whole into a temporary file, fsynced, renamed over the last one, and its
    // size checked: a full disk is an error here, never an empty file taken for a record
    solver::Text error;
    const bool ok = QDir().mkpath(m_folder) &&
                    solver::writeWholeFile(QFile::encodeName(m_pendingFile).toStdString(),
                                           std::string_view(bytes.constData(), std::size_t(bytes.size())), {}, error) &&
                    QFileInfo(m_pendingFile).size() == bytes.size();
    if (ok) {
        m_pendingOnDisk = true;
        m_pendingEvents = events.size();
        return true;
    }
    const QString why = error.empty() ? Tr::tr("cannot write %1").arg(QDir::toNativeSeparators(m_pendingFile)) : translated(error);
    m_problem = m_problem.isEmpty() ? Tr::tr("this attempt cannot be kept aside: %1").arg(why)
                                    : Tr::tr("%1 — and the attempt could not be saved aside either: %2").arg(m_problem, why);
    return false;
}

void AttemptLog::dropPending()
{
    if (m_pendingOnDisk && QFile::remove(m_pendingFile)) m_pendingOnDisk = false;
}

namespace {

/// Moves a file that is not a pending attempt out of the queue (into folder/quarantine).
QString quarantine(const QDir& dir, const QString& name, const QString& why)
{
    const QString shown = QDir::toNativeSeparators(dir.filePath(name));
    if (!dir.mkpath(QStringLiteral("quarantine")) || !QFile::rename(dir.filePath(name), dir.filePath("quarantine/" + name)))
        return Tr::tr("%1 is not a pending attempt (%2), and it cannot be moved aside").arg(shown, why);
    return Tr::tr("%1 is not a pending attempt (%2): moved to %3")
        .arg(shown, why, QDir::toNativeSeparators(dir.filePath(QStringLiteral("quarantine"))));
}

}  // namespace

int AttemptLog::importPending(records::AttemptRecorder& db, const QString& folder, QString* error)
{
    int imported = 0;
    QStringList problems;
    const auto done = [&] {
        if (error) *error = problems.join(QLatin1Char('\n'));
        return imported;
    };
    const QDir dir(folder);
    for (const QString& name : dir.entryList({"attempt-*.json"}, QDir::Files, QDir::Name)) {
        QJsonParseError pe{};
        QString readError;
        const std::optional<QByteArray> text =
            readLimitedFile(dir.filePath(name), kMaxPendingBytes, solver::trText("Tutorials", "a pending attempt"), ".json",
                            solver::trText("Tutorials", "a pending attempt is a JSON file that padrob writes; check that this is one"),
                            &readError);
        if (!text) {
            problems << quarantine(dir, name, readError);
            continue;
        }
        const QJsonObject o = QJsonDocument::fromJson(*text, &pe).object();
        const int version = o["version"].toInt();
        if (pe.error != QJsonParseError::NoError || o["format"].toString() != QLatin1String(kPendingFormat) ||
            version < 1 || version > 2) {
            problems << quarantine(dir, name, pe.error != QJsonParseError::NoError ? pe.errorString() : Tr::tr("not its format"));
            continue;
        }
        records::AttemptStart start;
        start.tutorialId = o["tutorial"].toString();
        start.tutorialTitle = o["title"].toString();
        start.language = o["language"].toString();
        start.started = QDateTime::fromString(o["started"].toString(), Qt::ISODateWithMs);
        start.uid = o["uid"].toString();  // "" in files of older Padrobs: a new one
        QList<records::AttemptEvent> events;
        for (const QJsonValue& v : o["events"].toArray()) {
            const QJsonObject e = v.toObject();
            events.append({e["t"].toDouble(), e["kind"].toString(), e["text"].toString(),
                           e["value"].isNull() ? std::numeric_limits<double>::quiet_NaN() : e["value"].toDouble(),
                           e["penalty"].toDouble(), e["detail"].toString()});
        }
        // version 1 kept the result at the top and the operator as an id of the database
        const QJsonObject res = version >= 2 ? o["result"].toObject() : o;
        records::AttemptResult r;
        if (version >= 2 && !o.contains("result")) {
            r.status = records::AttemptStatus::Interrupted;  // its process died during it
        } else {
            r.status = res["aborted"].toBool() ? records::AttemptStatus::Aborted : records::AttemptStatus::Finished;
            r.durationS = res["duration"].toDouble();
            r.score = res["score"].toDouble();
            r.stars = res["stars"].toInt();
            r.passed = res["passed"].toBool();
            for (const QJsonValue& v : res["breakdown"].toArray()) {
                const QJsonObject i = v.toObject();
                r.breakdown.append({i["key"].toString(), i["label"].toString(), i["value"].toDouble(), i["points"].toDouble(), i["max"].toDouble()});
            }
        }
        QString e;
        if (version >= 2) {
            const QString code = o["code"].toString().trimmed();
            if (code.isEmpty()) {
                problems << quarantine(dir, name, Tr::tr("it names no operator"));
                continue;
            }
            start.operatorId = db.operatorFor(code, o["name"].toString(), &e);
        } else {
            start.operatorId = o["operator"].toInteger();
            if (start.operatorId <= 0) {
                problems << quarantine(dir, name, Tr::tr("it names no operator"));
                continue;
            }
        }
        // begun in the database before it refused: complete that attempt with the events
        // it lacks (by their index), never a second copy
        records::Attempt begun;
        qint64 id = 0;
        if (start.operatorId <= 0) {
            // the database refuses: try later
        } else if (db.findAttempt(start.uid, begun, &e)) {
            if (begun.status == records::AttemptStatus::Finished || begun.status == records::AttemptStatus::Aborted) {
                QFile::remove(dir.filePath(name));  // recorded whole already: a result is never undone
                continue;
            }
            id = begun.id;
            events = events.mid(std::min(events.size(), begun.events.size()));
            for (qsizetype i = 0; i < events.size(); ++i) events[i].seq = int(begun.events.size() + i);
        } else if (e.isEmpty()) {
            id = db.beginAttempt(start, &e);
        }
        if (id <= 0 || !db.appendEvents(id, events, &e) || !db.finishAttempt(id, r, &e)) {
            problems << e;
            return done();  // the database refuses again: the rest wait for the next time
        }
        QFile::remove(dir.filePath(name));
        ++imported;
    }
    return done();
}

}  // namespace trainer
