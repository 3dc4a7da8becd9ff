#include "trainer/training/attempt_log.h"

#include "trainer/io/read_file.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
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

AttemptLog::AttemptLog(records::AttemptRecorder* db, QString pendingFolder, qint64 operatorId, const Tutorial& tutorial,
                       const QString& language)
    : m_db(db), m_tutorial(&tutorial), m_folder(std::move(pendingFolder))
{
    m_start.operatorId = operatorId;
    m_start.tutorialId = QString::fromStdString(tutorial.spec.id);
    m_start.tutorialTitle = QString::fromStdString(tutorial.title(language.toStdString()));
    m_start.language = language;
    m_start.started = QDateTime::currentDateTimeUtc();
    m_start.uid = QUuid::createUuid().toString(QUuid::WithoutBraces);
    ensureBegun();
}

bool AttemptLog::ensureBegun()
{
    if (m_attempt > 0) return true;
    if (!m_db || !m_db->isOpen()) {
        if (m_problem.isEmpty()) m_problem = Tr::tr("the records database is not open: this attempt is kept aside and recorded later");
        return false;
    }
    QString error;
    m_attempt = m_db->beginAttempt(m_start, &error);
    if (m_attempt <= 0) {
        m_attempt = 0;
        m_problem = error;
        return false;
    }
    return true;
}

void AttemptLog::update(const std::vector<TutorialEvent>& events)
{
    if (m_written >= events.size() || !ensureBegun()) return;
    QString error;
    if (m_db->appendEvents(m_attempt, toRecordEvents(events, m_written, m_tutorial, m_start.language.toStdString()), &error)) {
        m_written = events.size();
        m_problem.clear();
    } else {
        m_problem = error;
    }
}

bool AttemptLog::finish(const std::vector<TutorialEvent>& events, const TutorialResult& result, bool aborted)
{
    update(events);
    QString error;
    if (m_attempt > 0 && m_written == events.size() &&
        m_db->finishAttempt(m_attempt, toRecordResult(result, aborted), &error)) {
        return true;
    }
    if (!error.isEmpty()) m_problem = error;
    // the database refused: the whole record goes to a pending file (what was already
    // written stays in the database as an interrupted attempt only if it was begun; the
    // pending file is complete on its own)
    QJsonObject o;
    o["format"] = QString::fromLatin1(kPendingFormat);
    o["version"] = 1;
    o["operator"] = m_start.operatorId;
    o["tutorial"] = m_start.tutorialId;
    o["title"] = m_start.tutorialTitle;
    o["language"] = m_start.language;
    o["started"] = m_start.started.toString(Qt::ISODateWithMs);
    o["replaces"] = m_attempt;  // the attempt begun in the database, if any
    o["uid"] = m_start.uid;     // completes that attempt (or begins one with this uid)
    const records::AttemptResult r = toRecordResult(result, aborted);
    o["aborted"] = aborted;
    o["duration"] = r.durationS;
    o["score"] = r.score;
    o["stars"] = r.stars;
    o["passed"] = r.passed;
    QJsonArray breakdown, list;
    for (const records::ScoreItem& i : r.breakdown) {
        breakdown.append(QJsonObject{{"key", i.key}, {"label", i.label}, {"value", i.value}, {"points", i.points}, {"max", i.maxPoints}});
    }
    for (const records::AttemptEvent& e : toRecordEvents(events, 0, m_tutorial, m_start.language.toStdString())) {
        list.append(QJsonObject{{"t", e.t}, {"kind", e.kind}, {"text", e.text}, {"value", std::isfinite(e.value) ? QJsonValue(e.value) : QJsonValue()},
                                {"penalty", e.penalty}, {"detail", e.detail}});
    }
    o["breakdown"] = breakdown;
    o["events"] = list;
    QDir().mkpath(m_folder);
    const QString path = QDir(m_folder).filePath(QStringLiteral("attempt-%1-%2.json")
                                                     .arg(m_start.started.toString("yyyyMMdd-HHmmss-zzz"))
                                                     .arg(m_start.operatorId));
    QSaveFile f(path);
    if (f.open(QIODevice::WriteOnly) && f.write(QJsonDocument(o).toJson()) >= 0 && f.commit()) {
        m_pendingFile = path;
        m_problem = Tr::tr("%1 — this attempt was saved in %2 and will be recorded when the database can be written")
                        .arg(m_problem, QDir::toNativeSeparators(path));
    } else {
        m_problem = Tr::tr("%1 — and the attempt could not be saved aside either: %2").arg(m_problem, f.errorString());
    }
    return false;
}

int AttemptLog::importPending(records::AttemptRecorder& db, const QString& folder, QString* error)
{
    int imported = 0;
    const QDir dir(folder);
    for (const QString& name : dir.entryList({"attempt-*.json"}, QDir::Files, QDir::Name)) {
        QJsonParseError pe;
        const std::optional<QByteArray> text =
            readLimitedFile(dir.filePath(name), kMaxPendingBytes, solver::trText("Tutorials", "a pending attempt"), ".json",
                            solver::trText("Tutorials", "a pending attempt is a JSON file that padrob writes; check that this is one"), nullptr);
        const QJsonDocument doc = text ? QJsonDocument::fromJson(*text, &pe) : QJsonDocument();
        const QJsonObject o = doc.object();
        if (o["format"].toString() != QLatin1String(kPendingFormat)) {
            if (error) *error = Tr::tr("%1 is not a pending attempt: left where it is").arg(dir.filePath(name));
            continue;
        }
        records::AttemptStart start;
        start.operatorId = o["operator"].toInteger();
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
        records::AttemptResult r;
        r.status = o["aborted"].toBool() ? records::AttemptStatus::Aborted : records::AttemptStatus::Finished;
        r.durationS = o["duration"].toDouble();
        r.score = o["score"].toDouble();
        r.stars = o["stars"].toInt();
        r.passed = o["passed"].toBool();
        for (const QJsonValue& v : o["breakdown"].toArray()) {
            const QJsonObject i = v.toObject();
            r.breakdown.append({i["key"].toString(), i["label"].toString(), i["value"].toDouble(), i["points"].toDouble(), i["max"].toDouble()});
        }
        QString e;
        // begun in the database before it refused: complete that attempt with the events
        // it lacks (by their index), never a second copy
        records::Attempt begun;
        qint64 id = 0;
        if (db.findAttempt(start.uid, begun, &e)) {
            id = begun.id;
            events = events.mid(std::min(events.size(), begun.events.size()));
            for (qsizetype i = 0; i < events.size(); ++i) events[i].seq = int(begun.events.size() + i);
        } else if (e.isEmpty()) {
            id = db.beginAttempt(start, &e);
        }
        if (id <= 0 || !db.appendEvents(id, events, &e) || !db.finishAttempt(id, r, &e)) {
            if (error) *error = e;
            return imported;  // the database refuses again: try later
        }
        QFile::remove(dir.filePath(name));
        ++imported;
    }
    return imported;
}

}  // namespace trainer
