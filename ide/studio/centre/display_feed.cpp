#include "ide/studio/centre/display_feed.h"

#include "ide/paths/paths.h"

#include "ide/studio/train/tutorial_runner.h"
#include "trainer/training/tutorial.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>

namespace studio {

// ---------------------------------------------------------------- StateBuffer

bool StateBuffer::push(std::uint64_t seq, double simTime, std::vector<double> q, double arrivalS)
{
    if (!m_states.empty()) {
        const Sample& last = m_states.back();
        if (seq == last.seq && simTime == last.simTime) {
            m_lastArrival = arrivalS;  // the same state again: the station is there
            return false;
        }
        if (seq < last.seq || simTime < last.simTime - 1e-9) {
            // the station restarted (its seq counts from 0 again) or began a new attempt
            // (its simulated time from 0 again): what came before is another motion
            m_states.clear();
            ++m_restarts;
        }
    }
    m_lastArrival = arrivalS;
    const double transit = arrivalS - simTime;
    if (m_states.empty()) {
        m_offset = transit;
        m_stood = false;
        m_states.push_back(Sample{seq, simTime, std::move(q)});
        return true;
    }
    if (simTime <= m_states.back().simTime) {
        // simulated time stands still (paused, idle): the newest pose; the clock is
        // anchored again when it moves
        m_states.back() = Sample{seq, simTime, std::move(q)};
        m_stood = true;
        return true;
    }
    if (m_stood || transit > m_offset + kReanchor) {
        // moving again after a pause, or far later than the clock expects (the station
        // fell behind real time, the network stalled): this state is drawn kDelay after
        // now, and the pose holds the newest before it until then (never going back)
        m_offset = transit;
        m_states.erase(m_states.begin(), m_states.end() - 1);
    } else if (transit < m_offset) {
        m_offset = transit;  // the least delayed state sets the clock
    } else {
        m_offset += 0.02 * (transit - m_offset);  // drift with the station's clock, slowly
    }
    m_stood = false;
    m_states.push_back(Sample{seq, simTime, std::move(q)});
    while (m_states.size() > kKeep) m_states.pop_front();
    return true;
}

bool StateBuffer::sample(double nowS, std::vector<double>& q) const { return at(playTime(nowS), q); }

bool StateBuffer::at(double simTime, std::vector<double>& q) const
{
    if (m_states.empty()) return false;
    if (simTime <= m_states.front().simTime) {
        q = m_states.front().q;
        return true;
    }
    if (simTime >= m_states.back().simTime) {
        q = m_states.back().q;
        return true;
    }
    // the first state after simTime (there is one, and one before it)
    const auto after = std::upper_bound(m_states.begin(), m_states.end(), simTime,
                                        [](double t, const Sample& s) { return t < s.simTime; });
    const Sample& b = *after;
    const Sample& a = *(after - 1);
    if (a.q.size() != b.q.size()) {
        q = b.q;
        return true;
    }
    const double w = (simTime - a.simTime) / (b.simTime - a.simTime);
    q.resize(a.q.size());
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = a.q[i] + w * (b.q[i] - a.q[i]);
    return true;
}

void StateBuffer::clear()
{
    m_states.clear();
    m_offset = 0;
    m_lastArrival = -1;
    m_stood = false;
}

// ---------------------------------------------------------------- DisplayFeed

DisplayFeed::DisplayFeed(std::string station) : m_station(std::move(station)) {}

void DisplayFeed::setStation(const std::string& station)
{
    if (station == m_station) return;
    m_station = station;
    m_announce = {};
    m_hasAnnounce = m_hasState = m_left = false;
    m_latest = {};
    m_buffer.clear();
    m_modelKey.clear();
    m_bundle.reset();
    m_problem.clear();
    m_sceneFor.clear();
    m_sceneKnown = false;
    m_scene.reset();
}

void DisplayFeed::announce(const trainer::centre::Announce& a)
{
    if (a.node != m_station || a.role != "station") return;
    m_announce = a;
    m_hasAnnounce = true;
    m_left = false;
    loadModel();
}

void DisplayFeed::withdraw(const std::string& node)
{
    if (node == m_station) m_left = true;
}

void DisplayFeed::push(const trainer::centre::State& s, double nowS)
{
    // after it withdrew, only a new announcement brings it back: a state that arrives
    // late (states are best effort, the withdrawal reliable) does not
    if (s.station != m_station || m_left) return;
    m_hasState = true;
    m_buffer.push(s.seq, s.simTime, s.q, nowS);
    m_latest = s;
    m_latest.q.clear();
    if (!m_sceneKnown || s.tutorial != m_sceneFor) loadScene(s.tutorial);
}

DisplayFeed::Presence DisplayFeed::presence(double nowS) const
{
    if (m_left) return Presence::Left;
    if (!m_hasState) return Presence::Waiting;
    if (nowS - m_buffer.lastArrival() > kSilentAfter) return Presence::Silent;
    return Presence::Up;
}

bool DisplayFeed::pose(double nowS, std::vector<double>& q) const
{
    if (!m_buffer.sample(nowS, q)) return false;
    return !m_bundle || static_cast<int>(q.size()) == m_bundle->model->nq;
}

QString DisplayFeed::fileHash(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromLatin1(QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256).toHex());
}

QString DisplayFeed::findModel(const std::string& model, const std::string& hash, QString* error)
{
    const QString name = QString::fromStdString(model);
    // a plain name only: an announcement never reaches outside the models folder
    if (name.isEmpty() || name.contains('/') || name.contains('\\') || name.startsWith('.')) {
        if (error) *error = tr("The station announced no usable model name (“%1”).").arg(name);
        return {};
    }
    const QString path = paths::modelsDir() + "/" + name + ".pad";
    if (!QFileInfo::exists(path)) {
        if (error)
            *error = tr("The station's model “%1” is not installed on this computer (%2).")
                         .arg(name, QDir::toNativeSeparators(path));
        return {};
    }
    const QString here = fileHash(path);
    if (here.isEmpty()) {
        if (error) *error = tr("The model file %1 cannot be read.").arg(QDir::toNativeSeparators(path));
        return {};
    }
    if (!hash.empty() && here.compare(QString::fromStdString(hash), Qt::CaseInsensitive) != 0) {
        if (error)
            *error = tr("The station runs another version of the model “%1” than the one installed on this "
                        "computer (%2): install the same model files on both computers.")
                         .arg(name, QDir::toNativeSeparators(path));
        return {};
    }
    return path;
}

void DisplayFeed::loadModel()
{
    const std::string key = m_announce.model + "#" + m_announce.modelHash;
    if (key == m_modelKey) return;
    m_modelKey = key;
    m_bundle.reset();
    m_problem.clear();
    QString error;
    const QString path = findModel(m_announce.model, m_announce.modelHash, &error);
    if (path.isEmpty()) {
        m_problem = error;
        return;
    }
    solver::Diagnostics diags(path.toStdString());
    m_bundle = makeBundleFromFile(path, diags);
    if (!m_bundle) {
        QString first;
        for (const solver::Diagnostic& d : diags) {
            if (d.severity == solver::Severity::Error) {
                first = QString::fromStdString(d.format());
                break;
            }
        }
        m_problem = tr("The station's model %1 has errors on this computer: %2")
                        .arg(QDir::toNativeSeparators(path), first);
    }
}

void DisplayFeed::loadScene(const std::string& tutorialId)
{
    m_sceneFor = tutorialId;
    m_sceneKnown = true;
    m_scene.reset();
    if (tutorialId.empty()) return;
    if (!m_tutorialsRead) {
        // which file holds which tutorial (their headers only; the one used is loaded in full)
        m_tutorialsRead = true;
        for (const QFileInfo& fi : QDir(paths::tutorialsDir()).entryInfoList({"*.tut"}, QDir::Files, QDir::Name)) {
            QFile f(fi.absoluteFilePath());
            if (!f.open(QIODevice::ReadOnly)) continue;
            solver::Diagnostics ignored(fi.absoluteFilePath().toStdString());
            const trainer::TutorialSpec spec =
                trainer::parseTutorial(f.readAll().toStdString(), fi.absoluteFilePath().toStdString(), ignored);
            if (!spec.id.empty()) m_tutorialFiles.emplace(spec.id, fi.absoluteFilePath());
        }
    }
    const auto it = m_tutorialFiles.find(tutorialId);
    if (it == m_tutorialFiles.end()) return;  // not installed here: the machine without its scene
    solver::Diagnostics diags(it->second.toStdString());
    const auto t = trainer::loadTutorial(it->second.toStdString(), diags);
    if (t) m_scene = makeTutorialScene(*t);
}

}  // namespace studio
