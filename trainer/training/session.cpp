#include "trainer/training/session.h"

#include "trainer/io/read_file.h"

#include "solver/contact/contact_geometry.h"
#include "solver/kinematics/kinematics.h"

#include <QCoreApplication>
#include <QLocale>
#include <QScopeGuard>

#include <algorithm>
#include <cmath>
#include <limits>

namespace trainer {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(TutorialSession)
};

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

/// A measure as the operator reads it: in the locale of the language (1,25 in Spanish;
/// i18n::install sets the default), without thousands separators.
QString shown(double v, int decimals)
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale.toString(v, 'f', decimals);
}

/// The largest angle of the rotation between two attitudes [rad].
double rotationAngle(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
    return Eigen::AngleAxisd(a.transpose() * b).angle();
}

}  // namespace

const char* TutorialEvent::key(Kind k)
{
    switch (k) {
    case Kind::GoalDone: return "goal";
    case Kind::Grasp: return "grasp";
    case Kind::MissedGrasp: return "missed-grasp";
    case Kind::Release: return "release";
    case Kind::Drop: return "drop";
    case Kind::Hit: return "hit";
    case Kind::HardHit: return "hard-hit";
    case Kind::NearMiss: return "near-miss";
    case Kind::WorkerZone: return "worker-zone";
    case Kind::WorkerHit: return "worker-hit";
    case Kind::Overload: return "overload";
    case Kind::LimitBang: return "limit-bang";
    case Kind::Saturation: return "pump-saturation";
    case Kind::Cavitation: return "cavitation";
    case Kind::TimeUp: return "time-up";
    case Kind::InputEnded: return "input-ended";
    case Kind::SolverError: return "solver-error";
    case Kind::Fault: return "fault";
    case Kind::FaultCleared: return "fault-cleared";
    case Kind::Instructor: return "instructor";
    case Kind::Aborted: return "aborted";
    }
    return "?";
}

QString TutorialEvent::label(Kind k)
{
    switch (k) {
    case Kind::GoalDone: return Tr::tr("Goal done");
    case Kind::Grasp: return Tr::tr("Grasp");
    case Kind::MissedGrasp: return Tr::tr("Missed grasp");
    case Kind::Release: return Tr::tr("Release");
    case Kind::Drop: return Tr::tr("Load dropped");
    case Kind::Hit: return Tr::tr("Hit");
    case Kind::HardHit: return Tr::tr("Hard hit");
    case Kind::NearMiss: return Tr::tr("Near miss");
    case Kind::WorkerZone: return Tr::tr("Worker's safety zone");
    case Kind::WorkerHit: return Tr::tr("Worker hit");
    case Kind::Overload: return Tr::tr("Overload");
    case Kind::LimitBang: return Tr::tr("Limit bang");
    case Kind::Saturation: return Tr::tr("Pump saturated");
    case Kind::Cavitation: return Tr::tr("Cavitation");
    case Kind::TimeUp: return Tr::tr("Time up");
    case Kind::InputEnded: return Tr::tr("Input ended");
    case Kind::SolverError: return Tr::tr("Simulation stopped");
    case Kind::Fault: return Tr::tr("Fault injected");
    case Kind::FaultCleared: return Tr::tr("Fault cleared");
    case Kind::Instructor: return Tr::tr("Instructor");
    case Kind::Aborted: return Tr::tr("Stopped");
    }
    return {};
}

namespace {

constexpr double kLiftedClear = 0.005;  // [m] a load taken counts once this clear of the scene
// a load released under CONTACT has come to rest when its centre of mass moves slower than
// kRestSpeed and it turns slower than kRestTurn for kSettleStill; not at rest kSettleLimit
// after its release, it is dropped
constexpr double kRestSpeed = 0.005;   // [m/s]
constexpr double kRestTurn = 0.01;     // [rad/s]
constexpr double kSettleStill = 0.5;   // [s]
constexpr double kSettleLimit = 10.0;  // [s]
// the way made towards a goal's target counts as work past this (TutorialResult::work)
constexpr double kWayDeadBand = 0.01;  // [m]

/// A fault event's sentence from its detail ("hose-burst LEVANTE PLUMA"…): the drive as
/// the model names it, the person in `language` (by `subject`, else by the English name).
QString faultText(const TutorialEvent& e, const Tutorial* tutorial, const std::string& language)
{
    const std::size_t space = e.detail.find(' ');
    const std::string key = e.detail.substr(0, space);
    QString who = space == std::string::npos ? QString() : QString::fromStdString(e.detail.substr(space + 1));
    Fault::Kind kind = Fault::Kind::PowerCut;
    if (!Fault::fromKey(key, &kind)) return TutorialEvent::label(e.kind) + ": " + QString::fromStdString(e.detail);
    if (kind == Fault::Kind::WorkerIn && tutorial) {
        const std::vector<Worker>& workers = tutorial->spec.workers;
        int w = e.subject;
        for (std::size_t i = 0; w < 0 && i < workers.size(); ++i) {
            if (!workers[i].name.empty() && workers[i].name.in("en") == who.toStdString()) w = int(i);
        }
        if (w >= 0 && std::size_t(w) < workers.size() && !workers[std::size_t(w)].name.empty())
            who = QString::fromStdString(workers[std::size_t(w)].name.in(language));
    }
    const bool cleared = e.kind == TutorialEvent::Kind::FaultCleared;
    switch (kind) {
    case Fault::Kind::HoseBurst:
        return cleared ? Tr::tr("Instructor: the hose of %1 was repaired").arg(who)
                       : Tr::tr("Instructor: a hose of %1 burst; the drive has no pressure").arg(who);
    case Fault::Kind::StuckValve:
        return cleared ? Tr::tr("Instructor: the valve of %1 was freed").arg(who)
                       : Tr::tr("Instructor: the valve of %1 stuck at %2 % of its opening").arg(who, shown(100.0 * e.value, 0));
    case Fault::Kind::WorkerIn:
        return cleared ? Tr::tr("Instructor: %1 left the work area").arg(who)
                       : Tr::tr("Instructor: %1 walked into the work area").arg(who);
    case Fault::Kind::PowerCut:
        return cleared ? Tr::tr("Instructor: the power is back")
                       : Tr::tr("Instructor: the power was cut; every valve closed");
    }
    return {};
}

}  // namespace

QString TutorialEvent::text(const Tutorial* tutorial, const std::string& language) const
{
    if (kind == Kind::Fault || kind == Kind::FaultCleared) return faultText(*this, tutorial, language);
    QString d = QString::fromStdString(detail);
    if (tutorial && subject >= 0) {
        const bool worker = kind == Kind::WorkerZone || kind == Kind::WorkerHit;
        if (worker && std::size_t(subject) < tutorial->spec.workers.size() && !tutorial->spec.workers[std::size_t(subject)].name.empty())
            d = QString::fromStdString(tutorial->spec.workers[std::size_t(subject)].name.in(language));
        if (!worker && std::size_t(subject) < tutorial->spec.parts.size())
            d = QString::fromStdString(tutorial->spec.parts[std::size_t(subject)].name.in(language));
    }
    if (tutorial && kind == Kind::GoalDone) {
        // the goal as the HUD showed it (its NAME in the language), not its id
        for (const Goal& g : tutorial->spec.goals) {
            if (g.id == detail && !g.name.empty()) d = QString::fromStdString(g.name.in(language));
        }
    }
    const QString v = shown(value, 2);
    switch (kind) {
    case Kind::GoalDone: return Tr::tr("Goal done: %1").arg(d);
    case Kind::Grasp: return Tr::tr("The load is in the claws");
    case Kind::MissedGrasp: return Tr::tr("The claws closed %1 m away from the grip").arg(v);
    case Kind::Release: return Tr::tr("The load was released");
    case Kind::Drop: return Tr::tr("The load was released out of place and fell");
    case Kind::Hit: return Tr::tr("Touched %1 at %2 m/s").arg(d, v);
    case Kind::HardHit: return Tr::tr("Hit %1 hard, at %2 m/s: the attempt ends").arg(d, v);
    case Kind::NearMiss: return Tr::tr("Passed %1 m from %2").arg(v, d);
    case Kind::WorkerZone: return Tr::tr("Entered the safety zone of %1 (%2 m)").arg(d, v);
    case Kind::WorkerHit: return Tr::tr("Touched %1: the attempt ends").arg(d);
    case Kind::Overload: return Tr::tr("Relief valve of %1 opened (%2 kN)").arg(d, shown(value / 1000.0, 1));
    case Kind::LimitBang: return Tr::tr("%1 hit its end stop at full speed").arg(d);
    case Kind::Saturation:
        return Tr::tr("The pump %1 could not give the %2 L/min the levers asked for: every function slowed").arg(d, v);
    case Kind::Cavitation: return Tr::tr("%1 ran ahead of the oil: its cylinder cavitated").arg(d);
    case Kind::TimeUp: return Tr::tr("The time limit was reached");
    case Kind::InputEnded: return Tr::tr("The recorded input ended before the goals were done");
    case Kind::SolverError: return Tr::tr("The simulation stopped: %1").arg(detailText.empty() ? d : translated(detailText));
    case Kind::Fault:
    case Kind::FaultCleared: break;  // faultText
    case Kind::Instructor: {
        // detail: "ACTION:INSTRUCTOR" (trainer/centre/station_node.cpp)
        const qsizetype colon = d.indexOf(':');
        const QString action = colon < 0 ? d : d.left(colon), who = colon < 0 ? QString() : d.mid(colon + 1);
        if (action == "start") return Tr::tr("Instructor %1 started the attempt").arg(who);
        if (action == "pause") return Tr::tr("Instructor %1 paused the attempt").arg(who);
        if (action == "resume") return Tr::tr("Instructor %1 resumed the attempt").arg(who);
        if (action == "reset") return Tr::tr("Instructor %1 restarted the tutorial").arg(who);
        if (action == "stop") return Tr::tr("Instructor %1 stopped the attempt").arg(who);
        return Tr::tr("Instructor %1: %2").arg(who, action);
    }
    case Kind::Aborted: return Tr::tr("The attempt was stopped");
    }
    return {};
}

QString ScoreItem::label() const
{
    if (key == "time") return Tr::tr("Time");
    if (key == "path") return Tr::tr("Path");
    if (key == "smooth") return Tr::tr("Smoothness");
    if (key == "safety") return Tr::tr("Safety");
    return QString::fromStdString(key);
}

QString ScoreItem::advice() const
{
    // only what the work done could have earned and did not (nothing done: nothing lost)
    if (max <= 0 || points >= std::min(earnable, max) - 1e-9) return {};
    if (key == "time") return Tr::tr("Work faster: move several valves together once you are sure of the way.");
    if (key == "path") return Tr::tr("Take a straighter way: plan the movement before you start, and avoid going back and forth.");
    if (key == "smooth") return Tr::tr("Move the levers gently: open and close the valves gradually so the load does not jerk.");
    if (key == "safety") return Tr::tr("Keep clear of the mill, the cart and the people, do not force the cylinders against their relief valves and do not run into the end stops.");
    return {};
}

int TutorialResult::count(TutorialEvent::Kind k) const
{
    return int(std::count_if(events.begin(), events.end(), [k](const TutorialEvent& e) { return e.kind == k; }));
}

QStringList TutorialResult::improvements() const
{
    std::vector<const ScoreItem*> items;
    for (const ScoreItem& i : breakdown) items.push_back(&i);
    std::sort(items.begin(), items.end(),
              [](const ScoreItem* a, const ScoreItem* b) { return a->max - a->points > b->max - b->points; });
    QStringList out;
    if (!completed && work <= 0.0)
        out << Tr::tr("Nothing was done towards the goals: drive the machine towards the first one (the start "
                      "screen names the keys and levers of each drive).");
    else if (!completed)
        out << Tr::tr("Complete every goal: the stage is passed only when all are done.");
    for (const ScoreItem* i : items) {
        if (!i->advice().isEmpty()) out << i->advice();
    }
    return out;
}

TutorialSession::TutorialSession(std::shared_ptr<const Tutorial> tutorial, const SessionOptions& options)
    : m_tutorial(std::move(tutorial)), m_options(options)
{
    const Tutorial& t = *m_tutorial;
    const solver::Model& m = *t.model;
    solver::SimulationOptions so;
    so.integrator.method = solver::IntegrationMethod::Rk4Fixed;
    so.integrator.step = options.dt;
    m_sim = std::make_unique<solver::Simulation>(t.model, so);
    for (const auto& [j, theta] : t.initialTheta) m_sim->setInitial(j, theta, 0.0);
    m_sim->evaluate();
    m_commands.assign(std::size_t(m.nb), 0.0);
    m_reliefOpen.assign(std::size_t(m.nb), 0);
    m_stuck.assign(std::size_t(m.nb), std::numeric_limits<double>::quiet_NaN());
    m_workerOffsets.assign(t.spec.workers.size(), Eigen::Isometry3d::Identity());
    if (t.spec.scoring.avoidScene || !t.spec.workers.empty()) {
        solver::Diagnostics diags;
        m_world = std::make_unique<solver::CollisionWorld>(*t.modelSpec, m, t.sceneSpec.get(), diags);
        std::vector<int> all;
        for (const std::vector<int>& ids : t.workerShapes) {
            m_workerShapes.push_back(m_world->sceneShapes(ids));
            all.insert(all.end(), m_workerShapes.back().begin(), m_workerShapes.back().end());
        }
        m_world->excludeFromScene(all);
        m_inZone.assign(m_workerShapes.size(), 0);
    }
    m_lastTrack = m_lastGoalPoint = trackPoint();
    m_progress.goal = 0;
    sample();
}

TutorialSession::~TutorialSession() = default;

double TutorialSession::time() const
{
    return m_sim->state().t;
}

void TutorialSession::setCommands(std::span<const double> u)
{
    const std::size_t n = std::min(u.size(), m_commands.size());
    for (std::size_t j = 0; j < n; ++j) m_commands[j] = m_tutorial->enabled[j] ? u[j] : 0.0;
}

bool TutorialSession::advanceTo(double t)
{
    while (!ended() && time() < t - 0.5 * m_options.dt) step();
    return !ended();
}

void TutorialSession::stop(TutorialEvent::Kind why)
{
    if (ended()) return;
    addEvent(why, 0.0, 0.0, {});
    end(why == TutorialEvent::Kind::InputEnded ? "input-ended" : "aborted", false);
}

bool TutorialSession::step()
{
    if (ended()) return false;
    const solver::Model& m = *m_tutorial->model;
    // the operator's levers, unless a valve is stuck or the power is cut (faults)
    for (int j = 0; j < m.nb; ++j) {
        const std::size_t k = std::size_t(j);
        const double u = m_powerCut ? 0.0 : std::isnan(m_stuck[k]) ? m_commands[k] : m_stuck[k];
        m_sim->setCommand(j, u);
    }
    m_qdBefore.assign(m_sim->state().qd.data(), m_sim->state().qd.data() + m.nb);
    m_simEvents.clear();
    std::string error;
    solver::Text errorText;
    ++m_step;
    const double next = double(m_step) * m_options.dt;
    if (!m_sim->advanceTo(next, m_simEvents, error, &errorText)) {
        addEvent(TutorialEvent::Kind::SolverError, 0.0, 0.0, error);
        m_result.events.back().detailText = std::move(errorText);
        end("solver-error", false);
        return false;
    }
    handleSolverEvents(m_simEvents, m_qdBefore);
    recordImpacts();
    m_progress.t = time();
    checkGrip();
    if (!ended()) checkGoal();
    if (!ended() && m_world && time() - m_lastCheck >= m_options.checkPeriod - 1e-9) checkClearances();
    track();
    sample();
    if (!ended() && time() >= m_tutorial->scoring().timeLimit - 1e-9) {
        addEvent(TutorialEvent::Kind::TimeUp, time(), 0.0, {});
        end("time-up", false);
    }
    // hints that apply now
    m_progress.hints.clear();
    const std::vector<Hint>& hints = m_tutorial->spec.hints;
    const std::vector<Goal>& goals = m_tutorial->spec.goals;
    for (std::size_t k = 0; k < hints.size(); ++k) {
        const bool goalMatches = hints[k].goal.empty() ||
                                 (m_progress.goal < int(goals.size()) && goals[std::size_t(m_progress.goal)].id == hints[k].goal);
        if (goalMatches && time() - m_goalStart >= hints[k].after) m_progress.hints.push_back(int(k));
    }
    return !ended();
}

void TutorialSession::handleSolverEvents(const std::vector<solver::SimulationEvent>& events,
                                         const std::vector<double>& qdBefore)
{
    const solver::Model& m = *m_tutorial->model;
    const Scoring& sc = m_tutorial->scoring();
    using K = solver::SimulationEvent::Kind;
    for (const solver::SimulationEvent& e : events) {
        if (e.kind == K::PumpSaturation) {
            // fluid power: more asked of the pump than it gives (each time it starts)
            if (e.side > 0 && e.pump >= 0 && std::size_t(e.pump) < m.pumps.size()) {
                const solver::CompiledPump& p = m.pumps[std::size_t(e.pump)];
                addEvent(TutorialEvent::Kind::Saturation, e.value * 60000.0, sc.overloadPenalty,
                         p.name.empty() ? "PUMP " + std::to_string(p.id) : p.name);
            }
            continue;
        }
        const int j = e.joint;
        if (j < 0 || j >= m.nb) continue;
        if (e.kind == K::Cavitation) {
            if (e.side > 0) addEvent(TutorialEvent::Kind::Cavitation, 0.0, sc.overloadPenalty, driveName(j));
            continue;
        }
        const bool driven = m.drive[j].type != solver::DriveType::None;
        if (e.kind == K::ReliefOpen) {
            m_reliefOpen[std::size_t(j)] = 1;
            addEvent(TutorialEvent::Kind::Overload, std::abs(e.value), sc.overloadPenalty, driveName(j));
        } else if (e.kind == K::ReliefClose) {
            m_reliefOpen[std::size_t(j)] = 0;
        } else if (e.kind == K::LimitHit && driven && !isClaw(j)) {  // claws close onto their stops
            const solver::CompiledDrive& d = m.drive[j];
            const double signedRate = qdBefore[std::size_t(j)] * m.coordinateRate(j, m_sim->state().q[j]);
            const double rate = std::abs(signedRate);
            // the speed of that direction (a cylinder retracts faster than it extends)
            double top = d.type == solver::DriveType::Motor ? d.w0
                         : signedRate >= 0 ? d.vmax : (d.vmin > 0 ? d.vmin : d.vmax);
            if (d.type == solver::DriveType::FluidPower) {
                // the valve's nominal flow over the area it fills
                const solver::CompiledCircuit& c = m.circuits[std::size_t(d.circuit)];
                top = c.qn / (signedRate >= 0 ? c.areaA : c.areaB);
            }
            if (top > 0 && rate > sc.limitSpeedFraction * top) {
                addEvent(TutorialEvent::Kind::LimitBang, rate, sc.limitPenalty, driveName(j));
            }
        }
    }
    m_progress.overload = std::any_of(m_reliefOpen.begin(), m_reliefOpen.end(), [](char c) { return c != 0; });
}

void TutorialSession::checkGrip()
{
    const Tutorial& t = *m_tutorial;
    if (!t.spec.grip.present || t.loadBody < 0 || t.toolBody < 0) return;
    const solver::Model& m = *t.model;
    const solver::State& s = m_sim->state();
    auto past = [&](const Tutorial::Target& target, const Tutorial::Target& other) {
        // past `target` going away from `other`
        const double q = m.coordinate(target.joint, s.q[target.joint]);
        return (q - target.value) * (target.value - other.value) >= 0;
    };
    bool closed = true, open = true;
    for (std::size_t k = 0; k < t.gripClose.size(); ++k) {
        closed = closed && past(t.gripClose[k], t.gripOpen[k]);
        open = open && past(t.gripOpen[k], t.gripClose[k]);
    }
    const solver::Data& d = m_sim->data();
    if (closed && !m_wasClosed && !m_grasped && !m_fixed) {
        const Eigen::Vector3d pt = solver::bodyPointPosition(d, t.toolBody, t.spec.grip.toolPoint);
        const Eigen::Vector3d pl = solver::bodyPointPosition(d, t.loadBody, t.spec.grip.loadPoint);
        const Eigen::Matrix3d wanted = d.X_wb[std::size_t(t.toolBody)].linear() * t.spec.grip.relative;
        const double dist = (pt - pl).norm();
        const double ang = rotationAngle(wanted, d.X_wb[std::size_t(t.loadBody)].linear());
        if (dist <= t.spec.grip.tolerance && ang <= t.spec.grip.angleTolerance) {
            std::string error;
            if (m_sim->weld(t.toolBody, t.loadBody, m_simEvents, error)) {
                m_grasped = true;
                m_loadResting = true;
                m_settling = false;
                addEvent(TutorialEvent::Kind::Grasp, dist, 0.0, {});
            }
        } else {
            addEvent(TutorialEvent::Kind::MissedGrasp, dist, 0.0, {});
        }
    } else if (open && !m_wasOpen && m_grasped) {
        std::string error;
        m_sim->release(t.toolBody, t.loadBody, m_simEvents, error);
        m_grasped = false;
        addEvent(TutorialEvent::Kind::Release, 0.0, 0.0, {});
        const std::vector<Goal>& goals = t.spec.goals;
        const bool placing = m_progress.goal < int(goals.size()) && goals[std::size_t(m_progress.goal)].kind == Goal::Kind::Place;
        if (placing && m.contact) {
            // contact holds it (its seat, its neighbours) or lets it fall: judged at rest (checkGoal)
            m_settling = true;
            m_settleStart = time();
            m_stillSince = -1.0;
        } else if (placing && m_progress.withinTolerance) {
            // without contact nothing but its stops can hold it: placed where it was let go
            const Goal& g = goals[std::size_t(m_progress.goal)];
            if (g.fix && m_sim->weld(-1, t.loadBody, m_simEvents, error)) m_fixed = true;
            goalDone();
        } else {
            addEvent(TutorialEvent::Kind::Drop, 0.0, t.scoring().dropPenalty, {});
        }
    }
    m_wasClosed = closed;
    m_wasOpen = open;
    m_progress.grasped = m_grasped;
}

void TutorialSession::checkGoal()
{
    const Tutorial& t = *m_tutorial;
    const std::vector<Goal>& goals = t.spec.goals;
    if (m_progress.goal >= int(goals.size())) return;
    const std::size_t k = std::size_t(m_progress.goal);
    const Goal& g = goals[k];
    const solver::Model& m = *t.model;
    const solver::Data& d = m_sim->data();
    const solver::State& s = m_sim->state();
    bool within = false;
    m_progress.distance = -1.0;
    m_progress.positioned = false;
    m_progress.angleError = -1.0;
    m_progress.angleTolerance = 0.0;
    auto aligned = [&](int body) {
        // every ALIGN within its ANGTOL; the HUD shows the one furthest out
        bool all = true;
        double worst = -std::numeric_limits<double>::infinity();
        for (const Alignment& a : g.align) {
            const Eigen::Vector3d w = d.X_wb[std::size_t(body)].linear() * a.local;
            const double error = angleBetween(w, a.world);
            all = all && error <= a.tolerance;
            if (error - a.tolerance > worst) {
                worst = error - a.tolerance;
                m_progress.angleError = error;
                m_progress.angleTolerance = a.tolerance;
            }
        }
        return all;
    };
    switch (g.kind) {
    case Goal::Kind::Reach: {
        const int b = t.goalBody[k];
        const double dist = (solver::bodyPointPosition(d, b, g.point) - g.target).norm();
        m_progress.distance = dist;
        m_progress.positioned = dist <= g.tolerance;
        within = aligned(b) && m_progress.positioned;
        if (m_enteredGoal) m_result.overshoot = std::max(m_result.overshoot, dist - g.tolerance);
        break;
    }
    case Goal::Kind::Joint:
        within = true;
        for (const Tutorial::Target& jt : t.goalJoints[k]) {
            within = within && std::abs(m.coordinate(jt.joint, s.q[jt.joint]) - jt.value) <= jt.tolerance;
        }
        break;
    case Goal::Kind::Grasp:
        if (m_grasped) {
            goalDone();
            return;
        }
        break;
    case Goal::Kind::Place: {
        const double dist = (solver::comPosition(m, d, t.loadBody) - g.target).norm();
        m_progress.distance = dist;
        m_progress.positioned = dist <= g.tolerance;
        within = aligned(t.loadBody) && (m_grasped || m_settling) && m_progress.positioned;
        if (m_enteredGoal) m_result.overshoot = std::max(m_result.overshoot, dist - g.tolerance);
        if (m_settling) {
            // released under CONTACT: placed once it rests within tolerance (FIX: then
            // bolted there), dropped when it rests elsewhere or has not come to rest
            const std::size_t b = std::size_t(t.loadBody);
            const Eigen::Vector3d com = solver::comPosition(m, d, t.loadBody);
            const double v = (d.vel[b] + d.omega[b].cross(com - d.X_wb[b].translation())).norm();
            const bool still = v < kRestSpeed && d.omega[b].norm() < kRestTurn;
            if (!still) m_stillSince = -1.0;
            else if (m_stillSince < 0) m_stillSince = time();
            const bool rested = still && time() - m_stillSince >= kSettleStill - 1e-9;
            if (rested || time() - m_settleStart >= kSettleLimit - 1e-9) {
                m_settling = false;
                if (rested && within) {
                    std::string error;
                    if (g.fix && m_sim->weld(-1, t.loadBody, m_simEvents, error)) m_fixed = true;
                    m_progress.withinTolerance = true;
                    goalDone();
                    return;
                }
                addEvent(TutorialEvent::Kind::Drop, dist, t.scoring().dropPenalty, {});
            }
        }
        break;  // done when released within tolerance (checkGrip) or rested there (above)
    }
    }
    if (m_goalStartDistance < 0 && m_progress.distance >= 0) m_goalStartDistance = m_progress.distance;
    m_progress.withinTolerance = within;
    if (within) m_enteredGoal = true;
    if (g.kind == Goal::Kind::Reach || g.kind == Goal::Kind::Joint) {
        m_progress.dwell = within ? m_progress.dwell + m_options.dt : 0.0;
        if (within && m_progress.dwell >= g.dwell - 1e-9) goalDone();
    }
}

void TutorialSession::goalDone()
{
    const std::vector<Goal>& goals = m_tutorial->spec.goals;
    const Goal& g = goals[std::size_t(m_progress.goal)];
    addEvent(TutorialEvent::Kind::GoalDone, 0.0, 0.0, g.id);
    const Eigen::Vector3d p = trackPoint();
    m_result.idealLength += (p - m_lastGoalPoint).norm();
    m_lastGoalPoint = p;
    ++m_progress.goal;
    m_result.goalsDone = m_progress.goal;
    m_progress.dwell = 0.0;
    m_progress.withinTolerance = false;
    m_enteredGoal = false;
    m_goalStart = time();
    m_goalStartDistance = -1.0;
    if (m_progress.goal >= int(goals.size())) end("completed", true);
}

void TutorialSession::recordImpacts()
{
    const solver::Model& m = *m_tutorial->model;
    if (!m.contact || !m.contact->geometry) return;
    m_impact.resize(std::size_t(m.nb), 0.0);
    const std::vector<solver::ContactShape>& shapes = m.contact->geometry->shapes;
    for (const solver::ContactPoint& c : m_sim->data().contacts) {
        const double approach = -c.normalSpeed;
        if (!(approach > 0)) continue;
        for (const int shape : {c.shapeA, c.shapeB}) {
            const int body = shapes[std::size_t(shape)].body;
            if (body >= 0) m_impact[std::size_t(body)] = std::max(m_impact[std::size_t(body)], approach);
        }
    }
}

void TutorialSession::checkClearances()
{
    const Tutorial& t = *m_tutorial;
    const solver::Model& m = *t.model;
    const solver::Data& d = m_sim->data();
    const Scoring& sc = t.scoring();
    m_lastCheck = time();
    m_world->update(d);
    // the impacts recorded since the last check count for this one only
    const auto forgetImpacts = qScopeGuard([this] { std::fill(m_impact.begin(), m_impact.end(), 0.0); });
    // the load counts while carried, except near the place it is being set down on (its
    // SEAT zone: a liner slid into its slot touches its neighbours): there only a hard
    // hit counts
    // A load just taken still lies on what held it (a liner on its cart's timbers) until the
    // machine's oil has built the pressure to lift it: it counts once it has come clear.
    if (m_grasped && m_loadResting && sc.avoidScene) {
        const solver::Clearance c = m_world->bodyToScene(t.loadBody);
        if (!c.valid() || c.distance > kLiftedClear) m_loadResting = false;
    }
    bool loadCounts = m_grasped && !m_loadResting;
    bool seating = false;
    const std::vector<Goal>& goals = t.spec.goals;
    if (loadCounts && m_progress.goal < int(goals.size())) {
        const Goal& g = goals[std::size_t(m_progress.goal)];
        const double seat = g.seat > 0 ? g.seat : 3 * g.tolerance;
        if (g.kind == Goal::Kind::Place && m_progress.distance >= 0 && m_progress.distance < seat) {
            loadCounts = false;
            seating = true;
        }
    }
    auto pointSpeed = [&](int body, const Eigen::Vector3d& world) {
        const std::size_t b = std::size_t(body);
        const double now = (d.vel[b] + d.omega[b].cross(world - d.X_wb[b].translation())).norm();
        // under CONTACT the touch has already stopped it: the speed it came in at
        return b < m_impact.size() ? std::max(now, m_impact[b]) : now;
    };
    if (sc.avoidScene && seating) {
        const solver::Clearance c = m_world->bodyToScene(t.loadBody);
        if (c.valid() && c.distance <= 0.0) {
            const double v = pointSpeed(t.loadBody, c.pointA);
            if (v > sc.hardSpeed) {
                addEvent(TutorialEvent::Kind::HardHit, v, sc.hitPenalty, shapeName(c.shapeB), partOf(c.shapeB));
                end("hard-hit", false);
                return;
            }
        }
    }
    if (sc.avoidScene) {
        m_skip.assign(std::size_t(m.nb), 0);
        if (t.loadBody >= 0 && !loadCounts) m_skip[std::size_t(t.loadBody)] = 1;
        solver::Clearance best = m_world->machineToScene(m_skip);
        int bestBody = best.valid() ? m_world->shapes()[std::size_t(best.shapeA)].body : -1;
        // the arm against the load lying there (the fingers may touch it)
        if (t.loadBody >= 0 && !m_grasped && !m_fixed) {
            for (int b = 0; b < m.nb; ++b) {
                if (b == t.loadBody || std::find(t.fingerBodies.begin(), t.fingerBodies.end(), b) != t.fingerBodies.end()) continue;
                if (m.parent[std::size_t(b)] >= 0 && b > t.loadBody) continue;
                const solver::Clearance c = m_world->between(b, t.loadBody);
                if (c.distance < best.distance) {
                    best = c;
                    bestBody = b;
                }
            }
        }
        m_progress.clearance = best.valid() ? best.distance : -1.0;
        if (best.valid()) {
            if (best.distance <= 0.0 && !m_touching) {
                m_touching = true;
                const double v = pointSpeed(bestBody, best.pointA);
                const std::string what = shapeName(best.shapeB);
                const int part = partOf(best.shapeB);
                if (v > sc.hardSpeed) {
                    addEvent(TutorialEvent::Kind::HardHit, v, sc.hitPenalty, what, part);
                    end("hard-hit", false);
                    return;
                }
                addEvent(TutorialEvent::Kind::Hit, v, sc.hitPenalty, what, part);
            } else if (best.distance > 0.01) {
                m_touching = false;
            }
            if (best.distance > 0.0 && best.distance < sc.nearDistance && !m_near && !m_touching) {
                m_near = true;
                addEvent(TutorialEvent::Kind::NearMiss, best.distance, 0.0, shapeName(best.shapeB), partOf(best.shapeB));
            } else if (best.distance > 2 * sc.nearDistance) {
                m_near = false;
            }
        }
    }
    // the people
    m_progress.workerDistance = -1.0;
    m_progress.nearWorker = false;
    for (std::size_t w = 0; w < m_workerShapes.size(); ++w) {
        const Worker& worker = t.spec.workers[w];
        solver::Clearance best;
        for (int b = 0; b < m.nb; ++b) {
            if (b == t.loadBody && !m_grasped) continue;
            // only what is within reach of the zone matters (the HUD shows nearer than that)
            const solver::Clearance c = m_world->bodyToShapes(b, m_workerShapes[w], std::min(best.distance, worker.zone + 1.0));
            if (c.distance < best.distance) best = c;
        }
        if (!best.valid()) continue;
        if (m_progress.workerDistance < 0 || best.distance < m_progress.workerDistance) m_progress.workerDistance = best.distance;
        const std::string who = worker.name.empty() ? "G " + std::to_string(worker.graphicIds.front()) : worker.name.in("en");
        if (best.distance <= 0.0) {
            addEvent(TutorialEvent::Kind::WorkerHit, 0.0, worker.penalty, who, int(w));
            end("worker-hit", false);
            return;
        }
        if (best.distance < worker.zone) {
            m_progress.nearWorker = true;
            if (!m_inZone[w]) {
                m_inZone[w] = 1;
                addEvent(TutorialEvent::Kind::WorkerZone, best.distance, worker.penalty, who, int(w));
            }
        } else if (best.distance > worker.zone + 0.2) {
            m_inZone[w] = 0;
        }
    }
}

Eigen::Vector3d TutorialSession::trackPoint() const
{
    const Tutorial& t = *m_tutorial;
    if (t.trackBody < 0) return Eigen::Vector3d::Zero();
    return solver::bodyPointPosition(m_sim->data(), t.trackBody, t.trackPoint);
}

void TutorialSession::track()
{
    const Eigen::Vector3d p = trackPoint();
    m_result.pathLength += (p - m_lastTrack).norm();
    m_lastTrack = p;
    const double h = m_options.jerkInterval;
    if (m_lastJerkSample < 0 || time() - m_lastJerkSample >= h - 1e-9) {
        m_lastJerkSample = time();
        m_jerkWindow.push_back(p);
        if (m_jerkWindow.size() > 4) m_jerkWindow.erase(m_jerkWindow.begin());
        if (m_jerkWindow.size() == 4) {
            const Eigen::Vector3d j =
                (m_jerkWindow[3] - 3 * m_jerkWindow[2] + 3 * m_jerkWindow[1] - m_jerkWindow[0]) / (h * h * h);
            m_jerkSquares += j.squaredNorm();
            ++m_jerkCount;
        }
    }
}

void TutorialSession::sample()
{
    if (m_lastSample >= 0 && time() - m_lastSample < m_options.sampleEvery - 1e-9 && !ended()) return;
    m_lastSample = time();
    const solver::Model& m = *m_tutorial->model;
    const solver::State& s = m_sim->state();
    const solver::Data& d = m_sim->data();
    SessionSample x;
    x.t = s.t;
    x.q.assign(s.q.data(), s.q.data() + m.nb);
    x.driveForce.resize(std::size_t(m.nb));
    for (int j = 0; j < m.nb; ++j) x.driveForce[std::size_t(j)] = float(d.driveForce[j]);
    x.relief.assign(m_reliefOpen.begin(), m_reliefOpen.end());
    x.track = trackPoint();
    x.clearance = m_progress.clearance < 0 ? std::numeric_limits<float>::infinity() : float(m_progress.clearance);
    x.grasped = m_grasped;
    m_samples.push_back(std::move(x));
}

void TutorialSession::addEvent(TutorialEvent::Kind kind, double value, double penalty, std::string detail, int subject)
{
    TutorialEvent e;
    e.subject = subject;
    e.kind = kind;
    e.t = time();
    e.value = value;
    e.penalty = penalty;
    e.detail = std::move(detail);
    m_result.penalties += penalty;
    m_progress.penalties = m_result.penalties;
    m_result.events.push_back(std::move(e));
}

void TutorialSession::addInstructorEvent(const std::string& action, const std::string& sender)
{
    TutorialEvent e;
    e.kind = TutorialEvent::Kind::Instructor;
    e.t = time();
    e.value = std::numeric_limits<double>::quiet_NaN();
    e.detail = action + ":" + sender;
    m_result.events.push_back(std::move(e));
}

void TutorialSession::end(const std::string& reason, bool completed)
{
    if (m_result.ended) return;
    m_result.ended = true;
    m_result.endReason = reason;
    m_result.completed = completed;
    m_result.time = time();
    sample();
}

TutorialResult TutorialSession::result() const
{
    TutorialResult r = m_result;
    r.time = time();
    r.finalPoint = trackPoint();
    if (m_tutorial->trackBody >= 0) r.finalAxes = m_sim->data().X_wb[std::size_t(m_tutorial->trackBody)].linear();
    if (m_tutorial->loadBody >= 0) r.finalLoad = solver::comPosition(*m_tutorial->model, m_sim->data(), m_tutorial->loadBody);
    r.rmsJerk = m_jerkCount > 0 ? std::sqrt(m_jerkSquares / double(m_jerkCount)) : 0.0;
    scoreInto(r);
    return r;
}

double TutorialSession::score() const
{
    // the measures the score is made of, and nothing else (not the events)
    TutorialResult r;
    r.completed = m_result.completed;
    r.endReason = m_result.endReason;
    r.pathLength = m_result.pathLength;
    r.idealLength = m_result.idealLength;
    r.penalties = m_result.penalties;
    r.time = time();
    r.rmsJerk = m_jerkCount > 0 ? std::sqrt(m_jerkSquares / double(m_jerkCount)) : 0.0;
    scoreInto(r);
    return r.score;
}

double TutorialSession::workDone(double* approach) const
{
    if (approach) *approach = 0.0;
    const std::vector<Goal>& goals = m_tutorial->spec.goals;
    const int n = int(goals.size());
    if (m_result.completed || m_progress.goal >= n) return 1.0;
    // the current goal: the way made from where it began towards its tolerance
    double partial = 0.0;
    const Goal& g = goals[std::size_t(m_progress.goal)];
    if (m_goalStartDistance >= 0 && m_progress.distance >= 0) {
        // less a centimetre: a machine settling on its oil has done no work
        const double made = std::max(0.0, m_goalStartDistance - m_progress.distance - kWayDeadBand);
        const double span = m_goalStartDistance - g.tolerance - kWayDeadBand;
        partial = span > 1e-9 ? std::min(1.0, made / span) : 0.0;
        if (approach) *approach = made;
    }
    return (double(m_progress.goal) + partial) / double(n);
}

void TutorialSession::scoreInto(TutorialResult& r) const
{
    const Scoring& sc = m_tutorial->scoring();
    const bool completed = r.completed;
    double approach = 0.0;
    r.work = completed ? 1.0 : workDone(&approach);
    const double work = r.work;
    ScoreItem time{"time", r.time, 0.0, sc.wTime, completed ? sc.wTime : 0.0};
    if (completed) {
        const double span = std::max(sc.timeLimit - sc.parTime, 1e-9);
        time.points = sc.wTime * std::clamp((sc.timeLimit - r.time) / span, 0.0, 1.0);
    }
    // path, smoothness and safety: their quality (0–1) × their weight × the work done
    const double ideal = r.idealLength + approach;
    const double efficiency = r.pathLength > 1e-6 ? std::min(1.0, ideal / r.pathLength) : work > 0 ? 1.0 : 0.0;
    const double gentle = std::clamp(1.0 - r.rmsJerk / sc.jerkReference, 0.0, 1.0);
    const double safe = sc.wSafety > 0 ? std::max(0.0, 1.0 - r.penalties / sc.wSafety) : 1.0;
    ScoreItem path{"path", 100.0 * efficiency, sc.wPath * efficiency * work, sc.wPath, sc.wPath * work};
    ScoreItem smooth{"smooth", r.rmsJerk, sc.wSmooth * gentle * work, sc.wSmooth, sc.wSmooth * work};
    ScoreItem safety{"safety", r.penalties, sc.wSafety * safe * work, sc.wSafety, sc.wSafety * work};
    const double overflow = std::max(0.0, r.penalties - sc.wSafety);
    r.breakdown = {time, path, smooth, safety};
    r.score = std::clamp(time.points + path.points + smooth.points + safety.points - overflow, 0.0, 100.0);
    const bool hard = r.endReason == "hard-hit" || r.endReason == "worker-hit";
    r.passed = completed && !hard && r.score >= sc.pass - 1e-9;
    r.stars = 0;
    if (r.passed) {
        const double third = (100.0 - sc.pass) / 3.0;
        r.stars = r.score >= sc.pass + 2 * third ? 3 : r.score >= sc.pass + third ? 2 : 1;
    }
}

int TutorialSession::partOf(int shape) const
{
    if (!m_world || shape < 0 || std::size_t(shape) >= m_world->shapes().size()) return -1;
    const solver::CollisionShape& s = m_world->shapes()[std::size_t(shape)];
    if (s.body >= 0) return -1;
    const std::vector<Part>& parts = m_tutorial->spec.parts;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        if (parts[k].scene != s.scene) continue;
        if (std::find(parts[k].graphicIds.begin(), parts[k].graphicIds.end(), s.graphicId) != parts[k].graphicIds.end()) return int(k);
    }
    return -1;
}

std::string TutorialSession::shapeName(int shape) const
{
    if (!m_world || shape < 0 || std::size_t(shape) >= m_world->shapes().size()) return "?";
    if (const int part = partOf(shape); part >= 0) return m_tutorial->spec.parts[std::size_t(part)].name.in("en");
    const solver::CollisionShape& s = m_world->shapes()[std::size_t(shape)];
    const solver::Model& m = *m_tutorial->model;
    if (s.body >= 0) {
        const std::string name = m.bodyName.size() > std::size_t(s.body) ? m.bodyName[std::size_t(s.body)] : std::string();
        return name.empty() ? "body " + std::to_string(m.bodyId[std::size_t(s.body)]) : name;
    }
    return s.describe();
}

bool TutorialSession::isClaw(int joint) const
{
    for (const Tutorial::Target& c : m_tutorial->gripClose) {
        if (c.joint == joint) return true;
    }
    return false;
}

int TutorialSession::findDrive(const std::string& name, QString* error) const
{
    const solver::Model& m = *m_tutorial->model;
    const QString wanted = QString::fromStdString(name).trimmed();
    QStringList valid;
    for (int j = 0; j < m.nb; ++j) {
        const solver::DriveType type = m.drive[std::size_t(j)].type;
        if (type != solver::DriveType::Hydraulic && type != solver::DriveType::FluidPower) continue;
        const QString n = QString::fromStdString(driveName(j));
        if (n.compare(wanted, Qt::CaseInsensitive) == 0) return j;
        valid << n;
    }
    if (error) {
        *error = valid.isEmpty() ? Tr::tr("There is no drive \"%1\": this machine has no hydraulic drives").arg(wanted)
                                 : Tr::tr("There is no drive \"%1\" on this machine; its hydraulic drives are: %2")
                                       .arg(wanted, valid.join(QStringLiteral(", ")));
    }
    return -1;
}

Eigen::Vector3d TutorialSession::workerAnchor(int w) const
{
    const Tutorial& t = *m_tutorial;
    if (w < 0 || std::size_t(w) >= t.workerShapes.size() || t.workerShapes[std::size_t(w)].empty() || !t.sceneSpec)
        return Eigen::Vector3d::Zero();
    const int id = t.workerShapes[std::size_t(w)].front();
    for (const solver::GraphicSpec& g : t.sceneSpec->graphics) {
        if (g.id == id && g.body == 0) return g.position;
    }
    return Eigen::Vector3d::Zero();
}

Eigen::Isometry3d TutorialSession::workerOffset(int worker) const
{
    if (worker < 0 || std::size_t(worker) >= m_workerOffsets.size()) return Eigen::Isometry3d::Identity();
    return m_workerOffsets[std::size_t(worker)];
}

Eigen::Vector3d TutorialSession::workerPosition(int worker) const
{
    return workerOffset(worker) * workerAnchor(worker);
}

void TutorialSession::placeWorker(int w, const Eigen::Isometry3d& offset)
{
    m_workerOffsets[std::size_t(w)] = offset;
    if (m_world && std::size_t(w) < m_workerShapes.size()) m_world->placeSceneShapes(m_workerShapes[std::size_t(w)], offset);
    m_lastCheck = -1.0;  // the checker looks at the people at the next step
}

namespace {

std::string workerName(const Tutorial& t, int w)
{
    const Worker& worker = t.spec.workers[std::size_t(w)];
    return worker.name.empty() ? "G " + std::to_string(worker.graphicIds.front()) : worker.name.in("en");
}

bool fail(QString* error, const QString& message)
{
    if (error) *error = message;
    return false;
}

}  // namespace

bool TutorialSession::inject(const Fault& fault, QString* error)
{
    if (ended()) return fail(error, Tr::tr("The attempt has ended: no fault can be injected"));
    const Tutorial& t = *m_tutorial;
    Fault f = fault;
    std::string detail = Fault::key(f.kind);
    double value = 0.0;
    int subject = -1;
    auto same = [&](const Fault& a) {
        if (a.kind != f.kind) return false;
        if (Fault::onDrive(a.kind)) return a.drive == f.drive;
        if (a.kind == Fault::Kind::WorkerIn) return a.worker == f.worker;
        return true;
    };
    switch (f.kind) {
    case Fault::Kind::HoseBurst:
    case Fault::Kind::StuckValve: {
        const int j = findDrive(f.drive, error);
        if (j < 0) return false;
        f.drive = driveName(j);
        detail += " " + f.drive;
        if (f.kind == Fault::Kind::HoseBurst) {
            if (!m_sim->setDriveFault(j, f.hose))
                return fail(error, Tr::tr("A burst hose's damping and residual force must be zero or more"));
            m_reliefOpen[std::size_t(j)] = 0;  // no relief valve on a drive without pressure
        } else {
            if (std::isnan(f.opening)) f.opening = m_sim->state().u[j];
            if (!(f.opening >= -1.0 && f.opening <= 1.0))
                return fail(error, Tr::tr("A stuck valve's opening is a command from -1 to 1, not %1").arg(shown(f.opening, 2)));
            m_stuck[std::size_t(j)] = f.opening;
            value = f.opening;
        }
        break;
    }
    case Fault::Kind::WorkerIn: {
        const int n = int(t.spec.workers.size());
        if (n == 0) return fail(error, Tr::tr("This tutorial has no worker who could walk in (it has no WORKER)"));
        if (f.worker < 0 || f.worker >= n)
            return fail(error, Tr::tr("There is no worker %1 in this tutorial: its workers are numbered 0 to %2")
                                   .arg(f.worker)
                                   .arg(n - 1));
        if (std::size_t(f.worker) >= m_workerShapes.size() || m_workerShapes[std::size_t(f.worker)].empty())
            return fail(error, Tr::tr("Worker %1 has no graphics in the scene that could be moved").arg(f.worker));
        if (!f.where.allFinite()) return fail(error, Tr::tr("The place a worker walks to must be a finite position"));
        Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
        offset.translation() = f.where - workerAnchor(f.worker);
        placeWorker(f.worker, offset);
        detail += " " + workerName(t, f.worker);
        subject = f.worker;
        break;
    }
    case Fault::Kind::PowerCut: m_powerCut = true; break;
    }
    m_faults.erase(std::remove_if(m_faults.begin(), m_faults.end(), same), m_faults.end());
    m_faults.push_back(f);
    addEvent(TutorialEvent::Kind::Fault, value, 0.0, detail, subject);
    return true;
}

bool TutorialSession::clearFault(Fault::Kind kind, const std::string& drive, QString* error, int worker)
{
    if (ended()) return fail(error, Tr::tr("The attempt has ended: no fault can be cleared"));
    const Tutorial& t = *m_tutorial;
    std::string detail = Fault::key(kind);
    int j = -1;
    std::string name;
    if (Fault::onDrive(kind)) {
        j = findDrive(drive, error);
        if (j < 0) return false;
        name = driveName(j);
    }
    std::vector<Fault> cleared;
    for (auto it = m_faults.begin(); it != m_faults.end();) {
        const bool match = it->kind == kind && (!Fault::onDrive(kind) || it->drive == name) &&
                           (kind != Fault::Kind::WorkerIn || worker < 0 || it->worker == worker);
        if (match) {
            cleared.push_back(*it);
            it = m_faults.erase(it);
        } else {
            ++it;
        }
    }
    if (cleared.empty()) {
        switch (kind) {
        case Fault::Kind::HoseBurst: return fail(error, Tr::tr("No hose of %1 has burst").arg(QString::fromStdString(name)));
        case Fault::Kind::StuckValve: return fail(error, Tr::tr("The valve of %1 is not stuck").arg(QString::fromStdString(name)));
        case Fault::Kind::WorkerIn:
            return fail(error, worker < 0 ? Tr::tr("No worker has walked in") : Tr::tr("Worker %1 has not walked in").arg(worker));
        case Fault::Kind::PowerCut: return fail(error, Tr::tr("The power has not been cut"));
        }
        return false;
    }
    for (const Fault& f : cleared) {
        std::string d = detail;
        int subject = -1;
        switch (kind) {
        case Fault::Kind::HoseBurst:
            m_sim->clearDriveFault(j);
            d += " " + name;
            break;
        case Fault::Kind::StuckValve:
            m_stuck[std::size_t(j)] = std::numeric_limits<double>::quiet_NaN();
            d += " " + name;
            break;
        case Fault::Kind::WorkerIn:
            placeWorker(f.worker, Eigen::Isometry3d::Identity());
            d += " " + workerName(t, f.worker);
            subject = f.worker;
            break;
        case Fault::Kind::PowerCut: m_powerCut = false; break;
        }
        addEvent(TutorialEvent::Kind::FaultCleared, 0.0, 0.0, d, subject);
    }
    return true;
}

std::string TutorialSession::driveName(int joint) const
{
    const solver::Model& m = *m_tutorial->model;
    const std::string name = m.jointName.size() > std::size_t(joint) ? m.jointName[std::size_t(joint)] : std::string();
    return name.empty() ? "C " + std::to_string(m.jointId[std::size_t(joint)]) : name;
}

}  // namespace trainer
