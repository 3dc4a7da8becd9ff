#include "trainer/centre/station_node.h"

#include "trainer/input/input_log.h"
#include "trainer/centre/station_records.h"
#include "trainer/station/station_engine.h"
#include "trainer/training/faults.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QSysInfo>

#include <chrono>
#include <cmath>
#include <thread>

namespace trainer::centre {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(StationNode)
};

std::int64_t wallMs() { return QDateTime::currentMSecsSinceEpoch(); }

QString fileHash(const std::string& path)
{
    QFile f(QString::fromStdString(path));
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromLatin1(QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256).toHex());
}

}  // namespace

StationNode::StationNode(Bus& bus, StationNodeOptions options)
    : m_bus(bus), m_o(std::move(options)), m_guard(m_o.key)
{
    if (m_o.tutorials.empty()) {
        m_error = Tr::tr("A station needs at least one tutorial to run.");
        return;
    }
    if (m_o.name.empty()) {
        m_error = Tr::tr("A station needs a name, unique in the centre.");
        return;
    }
    for (const auto& t : m_o.tutorials) {
        if (t->modelFile != m_o.tutorials.front()->modelFile) {
            m_error = Tr::tr("The tutorials of one station must all use the same model: %1 uses %2, %3 uses %4.")
                          .arg(QString::fromStdString(m_o.tutorials.front()->spec.id),
                               QString::fromStdString(m_o.tutorials.front()->modelFile),
                               QString::fromStdString(t->spec.id), QString::fromStdString(t->modelFile));
            return;
        }
    }
    m_tutorial = m_o.tutorials.front();
    m_session = std::make_unique<TutorialSession>(m_tutorial);
    m_announce.node = m_o.name;
    m_announce.role = "station";
    m_announce.host = QSysInfo::machineHostName().toStdString();
    m_announce.pid = static_cast<int>(QCoreApplication::applicationPid());
    m_announce.model = QFileInfo(QString::fromStdString(m_tutorial->modelFile)).completeBaseName().toStdString();
    m_announce.modelHash = fileHash(m_tutorial->modelFile).toStdString();
    for (const auto& t : m_o.tutorials) m_announce.tutorials.push_back(t->spec.id);
    m_announce.language = m_o.language.toStdString();
    m_announce.startedMs = static_cast<std::uint64_t>(wallMs());
    if (m_o.record) {
        if (m_o.records.station.isEmpty()) m_o.records.station = QString::fromStdString(m_o.name);
        m_records = std::make_unique<StationRecords>(m_o.records, m_o.pendingFolder, m_o.language);
        if (!m_records->ok()) m_error = m_records->error();
    }
}

StationNode::~StationNode()
{
    if (m_recording) finishRecord(true);
}

std::shared_ptr<const Tutorial> StationNode::tutorial(const std::string& id) const
{
    for (const auto& t : m_o.tutorials) {
        if (t->spec.id == id) return t;
    }
    return nullptr;
}

void StationNode::run(const std::atomic<bool>& stop)
{
    if (!ok()) return;
    m_bus.announce(m_announce);
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    auto next = t0;
    while (!stop.load(std::memory_order_relaxed)) {
        tick(std::chrono::duration<double>(clock::now() - t0).count());
        next += std::chrono::milliseconds(1);
        const auto now = clock::now();
        if (next < now - std::chrono::milliseconds(50)) next = now;  // far behind: do not race to catch up
        std::this_thread::sleep_until(next);
    }
    if (m_recording && !m_session->ended()) {
        m_session->stop(TutorialEvent::Kind::Aborted);
        publishEvents();
        finishRecord(true);
    }
    m_bus.withdraw(m_o.name);
}

void StationNode::tick(double nowS)
{
    if (!ok()) return;
    m_lastTick = nowS;
    for (const Command& c : m_bus.takeCommands()) {
        if (c.target == m_o.name) handle(c);
    }
    if (m_status == "running") {
        // real time: the simulation keeps wall time minus the pauses
        const double target = nowS - m_simOffset;
        int steps = 0;
        while (m_session->time() + 0.5e-3 < target && steps < 50 && !m_session->ended()) {
            if (m_engine) {
                m_engine->update(m_session->time());
                m_session->setCommands(m_engine->commands());
            } else if (m_o.input) {
                m_input = m_o.input();
                m_session->setCommands(m_input);
            }
            m_session->step();
            ++steps;
        }
        if (m_session->time() + 0.5e-3 < target) m_simOffset = nowS - m_session->time();  // fell behind: slip
        if (m_session->ended()) {
            m_status = "ended";
            publishEvents();
            finishRecord(m_session->result().endReason == "aborted");
        }
    }
    if (nowS >= m_nextState) {
        noticeRecords();
        publishEvents();
        publishState(nowS);
        m_nextState = std::max(m_nextState + 1.0 / m_o.stateRate, nowS - 0.5 / m_o.stateRate);
    }
    if (m_recording && nowS >= m_nextRecord) {
        m_records->update(m_session->events());
        m_nextRecord = nowS + 1.0;
    }
}

void StationNode::noticeRecords()
{
    if (!m_records) return;
    const QString problem = m_records->problem();
    const int imported = m_records->imported();
    if (problem != m_recordsProblem && m_o.notice) {
        m_o.notice(problem.isEmpty() ? Tr::tr("the records journal takes writes again")
                                     : Tr::tr("the records journal refuses writes: %1").arg(problem));
    }
    if (imported != m_recordsImported && m_o.notice) {
        m_o.notice(Tr::tr("%n pending attempt(s) recorded in the journal", nullptr, imported - m_recordsImported));
    }
    m_recordsProblem = problem;
    m_recordsImported = imported;
}

void StationNode::publishState(double /*nowS*/)
{
    State s;
    s.station = m_o.name;
    s.seq = m_stateSeq++;
    s.sentUs = wallUs();
    const solver::Simulation& sim = m_session->simulation();
    s.simTime = sim.state().t;
    s.q.assign(sim.state().q.data(), sim.state().q.data() + sim.state().q.size());
    s.tutorial = m_tutorial->spec.id;
    s.status = m_status;
    s.operatorCode = m_operator;
    const SessionProgress& p = m_session->progress();
    s.attemptTime = m_session->time();
    s.goal = p.goal;
    s.goals = static_cast<int>(m_tutorial->spec.goals.size());
    s.clearance = p.clearance;
    s.workerDistance = p.workerDistance;
    const TutorialResult r = m_session->result();
    s.score = m_status == "idle" ? 0.0 : r.score;
    s.endReason = r.endReason;
    if (p.overload) s.warnings |= WarnOverload;
    if (p.nearWorker) s.warnings |= WarnNearWorker;
    if (p.clearance >= 0 && p.clearance < m_tutorial->scoring().nearDistance) s.warnings |= WarnNearScene;
    for (const Fault& f : m_session->activeFaults()) {
        s.warnings |= WarnFault;
        s.faults += (s.faults.empty() ? "" : ",") + std::string(Fault::key(f.kind)) + (f.drive.empty() ? "" : ":" + f.drive);
    }
    if (m_records && m_records->offline()) s.warnings |= WarnRecordsOffline;
    if (!m_recordsProblem.isEmpty()) s.warnings |= WarnRecordsRefused;
    s.faults = clip(s.faults, limits::kText);
    s.endReason = clip(s.endReason, limits::kField);
    s.commands.assign(sim.state().u.data(), sim.state().u.data() + sim.state().u.size());
    m_bus.publish(s);
}

void StationNode::publishEvents()
{
    const std::string lang = m_o.language.toStdString();
    const std::vector<TutorialEvent>& events = m_session->events();
    for (; m_published < events.size(); ++m_published) {
        const TutorialEvent& e = events[m_published];
        Event out;
        out.station = m_o.name;
        out.seq = m_eventSeq++;
        out.t = e.t;
        out.tutorial = m_tutorial->spec.id;
        out.kind = TutorialEvent::key(e.kind);
        out.text = clip(e.text(m_tutorial.get(), lang).toStdString(), limits::kText);
        out.detail = clip(e.detail, limits::kField);
        out.value = e.value;
        out.penalty = e.penalty;
        m_bus.publish(out);
    }
}

void StationNode::instructorEvent(const Command& c, const std::string& what)
{
    // in the session's own list, so its record and its stream keep the order
    m_session->addInstructorEvent(what, c.sender);
}

bool StationNode::start(const std::string& tutorialId, const std::string& operatorCode, std::string& why)
{
    std::shared_ptr<const Tutorial> t = tutorialId.empty() ? m_tutorial : tutorial(tutorialId);
    if (!t) {
        why = "unknown-tutorial";
        return false;
    }
    if (m_recording && !m_session->ended()) {
        m_session->stop(TutorialEvent::Kind::Aborted);
        publishEvents();
        finishRecord(true);
    }
    m_tutorial = t;
    m_session = std::make_unique<TutorialSession>(m_tutorial);
    m_published = 0;
    m_engine.reset();
    if (m_o.demoInput && !m_tutorial->demoFile.empty()) {
        auto log = std::make_shared<InputLog>();
        QString error;
        if (InputLog::load(QString::fromStdString(m_tutorial->demoFile), *log, &error)) {
            m_engine = std::make_unique<StationEngine>();
            m_engine->setDrives(m_tutorial->model->nb, drivesOf(*m_tutorial->model));
            StationProfile p = m_tutorial->profile;
            p.devices.clear();
            m_engine->setProfile(p);
            m_engine->setReplayOnly(true);
            for (auto& d : replayDevices(log)) m_engine->addDevice(d);
            m_demo = log;
        }
    }
    m_operator = operatorCode;
    m_status = "running";
    m_simOffset = m_lastTick;
    if (m_records) {
        m_records->begin(m_tutorial, QString::fromStdString(operatorCode.empty() ? std::string("guest") : operatorCode));
        m_recording = true;
    }
    m_nextRecord = m_lastTick + 1.0;
    return true;
}

void StationNode::finishRecord(bool aborted)
{
    if (!m_recording) return;
    publishEvents();
    m_records->finish(m_session->events(), m_session->result(), aborted);
    m_recording = false;
}

void StationNode::handle(const Command& c)
{
    Reply r;
    r.station = m_o.name;
    r.sender = c.sender;
    r.nonce = c.nonce;
    std::string why;
    if (!m_guard.accept(c, wallMs(), why)) {
        r.accepted = false;
        r.message = why;
        m_bus.reply(r);
        return;
    }
    bool done = false;
    if (c.kind == "start") {
        done = start(c.arg, c.arg2, why);
        if (done) instructorEvent(c, "start");
    } else if (c.kind == "reset") {
        const std::string op = m_operator;
        done = start(m_tutorial->spec.id, op, why);
        if (done) instructorEvent(c, "reset");
    } else if (c.kind == "pause") {
        done = m_status == "running";
        if (done) {
            m_status = "paused";
            instructorEvent(c, "pause");
        } else {
            why = "not-running";
        }
    } else if (c.kind == "resume") {
        done = m_status == "paused";
        if (done) {
            m_status = "running";
            m_simOffset = m_lastTick - m_session->time();
            instructorEvent(c, "resume");
        } else {
            why = "not-paused";
        }
    } else if (c.kind == "stop") {
        done = m_status == "running" || m_status == "paused";
        if (done) {
            instructorEvent(c, "stop");
            m_session->stop(TutorialEvent::Kind::Aborted);
            m_status = "ended";
            publishEvents();
            finishRecord(true);
        } else {
            why = "not-running";
        }
    } else if (c.kind == "inject" || c.kind == "clear") {
        Fault f;
        if (!Fault::fromKey(c.arg, &f.kind)) {
            why = "unknown-fault";
        } else if (m_status != "running" && m_status != "paused") {
            why = "not-running";
        } else {
            f.drive = c.arg2;
            QString error;
            if (c.kind == "inject") {
                if (f.kind == Fault::Kind::StuckValve) f.opening = c.value;
                if (f.kind == Fault::Kind::WorkerIn) {
                    // arg2 "x,y,z" [m]: where the person walks to
                    const QStringList xyz = QString::fromStdString(c.arg2).split(',');
                    f.drive.clear();
                    if (xyz.size() == 3) f.where = {xyz[0].toDouble(), xyz[1].toDouble(), xyz[2].toDouble()};
                    f.worker = std::isnan(c.value) ? 0 : static_cast<int>(c.value);
                }
                done = m_session->inject(f, &error);
            } else {
                const bool worker = f.kind == Fault::Kind::WorkerIn;
                const int which = worker && !std::isnan(c.value) ? static_cast<int>(c.value) : -1;
                done = m_session->clearFault(f.kind, worker ? std::string() : f.drive, &error, which);
            }
            if (!done) why = error.toStdString();
        }
    } else {
        why = "unknown-command";
    }
    r.accepted = done;
    r.message = done ? std::string("done") : clip(why, limits::kText);
    publishEvents();
    m_bus.reply(r);
}

}  // namespace trainer::centre
