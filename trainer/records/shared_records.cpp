#include "trainer/records/shared_records.h"

#include <QCoreApplication>
#include <QSysInfo>

#include <algorithm>

namespace trainer::records {

namespace {

/// The translation context of this file's messages (lupdate reads Tr::tr).
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(trainer::records::SharedRecords)
};

}  // namespace

SharedRecords::SharedRecords() = default;

SharedRecords::~SharedRecords()
{
    close();
}

bool SharedRecords::open(const SharedLocation& where, QString* error)
{
    close();
    m_where = where;
    m_where.eventsPerStep = std::max(1, where.eventsPerStep);
    m_where.retryAfterS = std::max(0.0, where.retryAfterS);
    if (m_where.station.trimmed().isEmpty()) m_where.station = QSysInfo::machineHostName();
    if (m_where.station.trimmed().isEmpty()) m_where.station = QStringLiteral("station");
    m_where.station = m_where.station.trimmed();
    RecordsLocation local;
    local.sqlitePath = where.journalPath;
    local.busyTimeoutMs = where.busyTimeoutMs;
    if (!m_local.open(local, error)) return false;
    // attempts recorded before schema 3 get their uid here, so they reach the server too
    if (!m_local.giveUids(error)) {
        m_local.close();
        return false;
    }
    return true;
}

void SharedRecords::close()
{
    m_local.close();
    dropServer();
    m_online = false;
    m_lastError.clear();
    m_sinceFailure.invalidate();
    m_where.server.password.clear();
}

bool SharedRecords::isOpen() const
{
    return m_local.isOpen();
}

QString SharedRecords::station() const
{
    return m_where.station;
}

RecordsDb& SharedRecords::journal()
{
    return m_local;
}

int SharedRecords::interruptedAtOpen() const
{
    return m_local.interruptedAtOpen();
}

// recording ------------------------------------------------------------------------------

qint64 SharedRecords::addOperator(const QString& code, const QString& name, QString* error)
{
    return m_local.addOperator(code, name, error);
}

bool SharedRecords::findOperator(const QString& code, Operator& out, QString* error)
{
    if (m_local.findOperator(code, out, error)) return true;
    if (error && !error->isEmpty()) return false;  // the journal failed
    if (!m_remote.isOpen() || !m_online) return false;
    // registered at another station: the server's, copied into the journal
    Operator there;
    QString e;
    if (!m_remote.findOperator(code, there, &e)) {
        if (!e.isEmpty()) {  // the server is gone: offline until the next sync
            m_online = false;
            m_lastError = e;
            m_sinceFailure.start();
            dropServer();
        }
        return false;
    }
    const qint64 id = m_local.addOperator(there.code, there.name, error);
    if (id <= 0) return false;
    m_local.noteOperatorSynced(id, nullptr);  // if it fails, the next sync finds the server's row
    m_remoteOperator.insert(id, there.id);
    return m_local.findOperator(there.code, out, error);
}

qint64 SharedRecords::beginAttempt(const AttemptStart& start, QString* error)
{
    AttemptStart s = start;
    if (s.station.isEmpty()) s.station = m_where.station;
    return m_local.beginAttempt(s, error);
}

bool SharedRecords::appendEvents(qint64 attemptId, const QList<AttemptEvent>& events, QString* error)
{
    return m_local.appendEvents(attemptId, events, error);
}

bool SharedRecords::finishAttempt(qint64 attemptId, const AttemptResult& result, QString* error)
{
    return m_local.finishAttempt(attemptId, result, error);
}

bool SharedRecords::findAttempt(const QString& uid, Attempt& out, QString* error) const
{
    return m_local.findAttempt(uid, out, error);
}

// the server -----------------------------------------------------------------------------

bool SharedRecords::hasServer() const
{
    return m_where.server.isSet();
}

bool SharedRecords::online() const
{
    return m_online;
}

void SharedRecords::setAfterServerStep(std::function<void(int)> hook)
{
    m_afterStep = std::move(hook);
}

void SharedRecords::dropServer()
{
    m_remote.close();
    m_remoteOperator.clear();
}

bool SharedRecords::connectServer(QString* error)
{
    m_remoteOperator.clear();
    RecordsLocation server;
    server.postgres = m_where.server;
    server.busyTimeoutMs = m_where.busyTimeoutMs;
    return m_remote.open(server, error);
}

bool SharedRecords::sync(QString* error)
{
    if (!isOpen()) {
        if (error) *error = Tr::tr("cannot send the records to the centre's server: the station's records are not open");
        return false;
    }
    if (!hasServer()) return true;
    if (!m_lastError.isEmpty() && m_sinceFailure.isValid() &&
        m_sinceFailure.elapsed() < qint64(m_where.retryAfterS * 1000)) {
        if (error) *error = m_lastError;  // too soon to try again
        return false;
    }
    QString e;
    const bool fresh = !m_remote.isOpen();
    bool ok = syncNow(&e);
    if (!ok && !fresh) {
        // the connection may have died since the last sync (the server restarted):
        // one more try on a new one
        dropServer();
        e.clear();
        ok = syncNow(&e);
    }
    if (!ok) {
        dropServer();
        m_online = false;
        m_lastError = e;
        m_sinceFailure.start();
        if (error) *error = e;
        return false;
    }
    m_online = true;
    m_lastError.clear();
    m_sinceFailure.invalidate();
    return true;
}

bool SharedRecords::syncNow(QString* error)
{
    if (!m_remote.isOpen() && !connectServer(error)) return false;

    QList<RecordsDb::Unsynced> attempts;
    QList<Operator> operators;
    if (!m_local.unsynced(attempts, operators, error)) return false;
    if (attempts.isEmpty() && operators.isEmpty()) return m_remote.check(error);  // still there?

    int steps = 0;
    auto stepDone = [&] {
        ++steps;
        if (m_afterStep) m_afterStep(steps);
    };
    auto remoteOperator = [&](const Operator& op) -> qint64 {
        const auto it = m_remoteOperator.constFind(op.id);
        if (it != m_remoteOperator.constEnd()) return *it;
        const qint64 id = m_remote.ensureOperator(op, error);
        if (id > 0) m_remoteOperator.insert(op.id, id);
        return id;
    };

    // operators by code: the server keeps one row per code
    for (const Operator& op : operators) {
        if (remoteOperator(op) <= 0) return false;
        stepDone();
        if (!m_local.noteOperatorSynced(op.id, error)) return false;
    }

    // attempts by uid, events by (uid, seq): each step one server transaction, then
    // noted in the journal; a step repeated (the note lost in a crash) changes nothing
    for (const RecordsDb::Unsynced& u : attempts) {
        const qint64 op = remoteOperator(u.op);
        if (op <= 0) return false;
        Attempt head;
        if (!m_local.attemptHead(u.attemptId, head, error)) return false;
        if (head.station.isEmpty()) head.station = m_where.station;  // written to the journal directly
        int from = u.syncedEvents;
        for (;;) {
            QList<AttemptEvent> chunk;
            if (!m_local.eventsOf(u.attemptId, from, m_where.eventsPerStep, chunk, error)) return false;
            const bool last = chunk.size() < m_where.eventsPerStep;
            // the result only with the last events: a finished attempt on the server has them all
            Attempt copy = head;
            if (!last) copy.status = AttemptStatus::Running;
            if (!m_remote.mergeAttempt(copy, op, chunk, error)) return false;
            stepDone();
            if (!chunk.isEmpty()) from = chunk.last().seq + 1;
            if (!m_local.noteSynced(u.attemptId, from, copy.status, error)) return false;
            if (last) break;
        }
    }
    return true;
}

SyncBacklog SharedRecords::pending(QString* error) const
{
    SyncBacklog b;
    QList<RecordsDb::Unsynced> attempts;
    QList<Operator> operators;
    if (!m_local.unsynced(attempts, operators, error)) return b;
    b.operators = int(operators.size());
    b.attempts = int(attempts.size());
    for (const RecordsDb::Unsynced& u : attempts) b.events += std::max(0, u.events - u.syncedEvents);
    return b;
}

QString SharedRecords::offlineMessage() const
{
    if (!isOpen() || !hasServer() || m_online) return {};
    if (m_lastError.isEmpty())
        return Tr::tr("not connected yet to the centre's records server %1: this station records on its own "
                      "until it is")
            .arg(m_where.server.describe());
    return Tr::tr("this station records on its own, and sends its records to the centre's server %1 when it "
                  "is back (%2)")
        .arg(m_where.server.describe(), m_lastError);
}

}  // namespace trainer::records
