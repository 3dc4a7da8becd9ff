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
    if (m_status == StationStatus::Running) {
        // real time: the simulation follows the wall clock from its start or resumption
        m_pacer.runDue([&] {
            if (m_session->ended()) return false;
            if (m_engine) {
                m_engine->update(m_session->time());
                m_session->setCommands(m_engine->commands());
            } else if (m_o.input) {
                m_input = m_o.input();
                m_session->setCommands(m_input);
            }
            m_session->step();
            return true;
        });
        if (m_session->ended()) {
            m_status = StationStatus::Ended;
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
    const solver::Simulation& sim = m_session->simulation();
    const std::vector<Fault> faults = m_session->activeFaults();
    StationSituation x;
    x.station = m_o.name;
    x.status = m_status;
    x.tutorial = m_tutorial.get();
    x.operatorCode = m_operator;
    x.simTime = sim.state().t;
    x.q = std::span<const double>(sim.state().q.data(), static_cast<std::size_t>(sim.state().q.size()));
    x.commands = std::span<const double>(sim.state().u.data(), static_cast<std::size_t>(sim.state().u.size()));
    x.progress = m_session->progress();
    x.progress.t = m_session->time();
    x.score = m_session->score();
    x.endReason = m_session->endReason();
    x.faults = faults;
    x.recordsOffline = m_records && m_records->offline();
    x.recordsRefused = !m_recordsProblem.isEmpty();
    m_bus.publish(buildState(x, m_stateSeq++));
}

void StationNode::publishEvents()
{
    const std::string lang = m_o.language.toStdString();
    const std::vector<TutorialEvent>& events = m_session->events();
    for (; m_published < events.size(); ++m_published)
        m_bus.publish(buildEvent(m_o.name, m_eventSeq++, *m_tutorial, events[m_published], lang));
}

void StationNode::instructorEvent(const Command& c, const std::string& what)
{
    // in the session's own list, so its record and its stream keep the order
    m_session->addInstructorEvent(what, c.sender);
}

bool StationNode::start(const std::string& tutorialId, const std::string& operatorCode)
{
    std::shared_ptr<const Tutorial> t = tutorialId.empty() ? m_tutorial : tutorial(tutorialId);
    if (!t) return false;
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
    m_status = StationStatus::Running;
    m_pacer.anchor(m_session->time(), 1.0);
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
    const CommandKind kind = commandKind(c.kind);
    bool done = false;
    Refusal refusal = Refusal::UnknownCommand;
    FaultCommand fault;
    if (refused(c, kind, m_status, &fault, &refusal)) {
        why = key(refusal);
    } else {
        switch (kind) {
        case CommandKind::Start:
        case CommandKind::Reset: {
            const bool reset = kind == CommandKind::Reset;
            const std::string op = m_operator;
            done = reset ? start(m_tutorial->spec.id, op) : start(c.arg, c.arg2);
            if (done) instructorEvent(c, key(kind));
            else why = key(Refusal::UnknownTutorial);
            break;
        }
        case CommandKind::Pause:
            m_status = StationStatus::Paused;
            instructorEvent(c, key(kind));
            done = true;
            break;
        case CommandKind::Resume:
            m_status = StationStatus::Running;
            m_pacer.anchor(m_session->time(), 1.0);
            instructorEvent(c, key(kind));
            done = true;
            break;
        case CommandKind::Stop:
            instructorEvent(c, key(kind));
            m_session->stop(TutorialEvent::Kind::Aborted);
            m_status = StationStatus::Ended;
            publishEvents();
            finishRecord(true);
            done = true;
            break;
        case CommandKind::Inject:
        case CommandKind::Clear: {
            QString error;
            done = applyFault(*m_session, kind, fault, &error);
            if (!done) why = error.toStdString();
            break;
        }
        case CommandKind::Unknown: break;  // (refused above)
        }
    }
    r.accepted = done;
    r.message = done ? std::string(kDone) : clip(why, limits::kText);
    publishEvents();
    m_bus.reply(r);
}

}  // namespace trainer::centre
