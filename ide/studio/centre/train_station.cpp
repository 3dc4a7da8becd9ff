#include "ide/studio/centre/train_station.h"

#include "ide/i18n/language.h"
#include "ide/studio/train/train_page.h"
#include "trainer/training/faults.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QSysInfo>
#include <QTimer>

#include <chrono>

namespace studio {

namespace {

using namespace trainer::centre;

std::int64_t wallMs() { return QDateTime::currentMSecsSinceEpoch(); }

QString fileHash(const std::string& path)
{
    QFile f(QString::fromStdString(path));
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromLatin1(QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256).toHex());
}

/// The Train page as the station's host.
class PageHost : public TrainStation::Host {
public:
    explicit PageHost(TrainPage* page) : m_page(page), m_runner(page->runner()) {}
    std::vector<std::shared_ptr<const trainer::Tutorial>> tutorials() const override { return m_page->tutorials(); }
    QString language() const override { return i18n::current(); }
    std::shared_ptr<const TrainFrame> attemptFrame() const override
    {
        if (!m_page->attemptLive()) return nullptr;
        auto f = m_page->runner()->latest();
        return f && f->snapshot ? f : nullptr;
    }
    std::shared_ptr<const trainer::Tutorial> attemptTutorial() const override { return m_page->tutorial(); }
    QString attemptOperator() const override { return m_page->operatorId(); }
    std::shared_ptr<const TrainFrame> latestFrame() const override { return m_runner->latest(); }
    long startAttempt(const QString& id, const QString& op) override
    {
        return m_page->startAttemptFor(id, op) ? m_page->runner()->generation() : 0;
    }
    void setPaused(bool paused) override { m_page->runner()->setPaused(paused); }
    void stopAttempt() override { m_page->stopAttempt(); }
    void runInSession(TutorialRunner::SessionTask task, std::function<void(bool, const QString&)> done,
                      long generation) override
    {
        m_page->runner()->runInSession(std::move(task), std::move(done), generation);
    }
    void setLink(CentreLink link, const QString& name, const QString& detail) override
    {
        m_page->setCentreLink(link, name, detail);
    }

private:
    QPointer<TrainPage> m_page;
    TutorialRunner* m_runner;  // outlives the station (MainWindow owns it)
};

/// forPage(): the station owns its host.
class PageStation : public TrainStation {
public:
    PageStation(std::unique_ptr<PageHost> host, TrainStationOptions o)
        : TrainStation(host.get(), std::move(o)), m_ownHost(std::move(host))
    {
    }
    ~PageStation() override { shutdown(); }  // before the host goes

private:
    std::unique_ptr<PageHost> m_ownHost;
};

}  // namespace

std::unique_ptr<TrainStation> TrainStation::forPage(TrainPage* page, TrainStationOptions options)
{
    return std::make_unique<PageStation>(std::make_unique<PageHost>(page), std::move(options));
}

TrainStation::TrainStation(Host* host, TrainStationOptions options, QObject* parent)
    : QObject(parent), m_host(host), m_o(std::move(options))
{
    CentreKey key;
    if (m_o.keyFile.isEmpty()) {
        m_problem = tr("no key file was given (--centre-key)");
    } else {
        QString error;
        m_hasKey = key.load(m_o.keyFile, &error);
        // a node key serves only its own station
        if (m_hasKey) m_hasKey = key.mayServe(m_o.name.toStdString(), m_o.keyFile, &error);
        if (!m_hasKey) m_problem = error;
    }
    m_guard = std::make_unique<CommandGuard>(m_hasKey ? key : CentreKey());
    BusOptions net = m_o.network;
    net.reads = TopicCommand;
    net.node = m_o.name;  // with DDS Security, its identity in the PKI (DIR/nodes/NAME)
    if (m_hasKey) net.key = key;  // signs what the station says (without it, no one believes it)
    QString busError;
    m_bus = Bus::open(net, &busError);
    if (!m_bus) {
        m_problem = busError.isEmpty() ? tr("DDS refused to join the domain") : busError;
        m_host->setLink(CentreLink::Failed, m_o.name, m_problem);
        return;
    }
    m_host->setLink(m_hasKey ? CentreLink::Online : CentreLink::NoKey, m_o.name, m_problem);
    m_announce.node = m_o.name.toStdString();
    m_announce.role = "station";
    m_announce.host = QSysInfo::machineHostName().toStdString();
    m_announce.pid = static_cast<int>(QCoreApplication::applicationPid());
    m_announce.startedMs = static_cast<std::uint64_t>(wallMs());
    const auto all = m_host->tutorials();
    announceFor(all.empty() ? nullptr : all.front().get());
    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    m_timer->setInterval(4);
    connect(m_timer, &QTimer::timeout, this, &TrainStation::tick);
    m_timer->start();
    m_publisher = std::thread([this] { publishLoop(); });
}

TrainStation::~TrainStation() { shutdown(); }

void TrainStation::shutdown()
{
    if (m_timer) m_timer->stop();
    if (m_publisher.joinable()) {
        {
            std::lock_guard lock(m_publishMutex);
            m_quit = true;
        }
        m_publishWake.notify_all();
        m_publisher.join();
    }
    if (m_bus) m_bus->withdraw(m_o.name.toStdString());
    m_bus.reset();
}

void TrainStation::publishLoop()
{
    using Clock = std::chrono::steady_clock;
    const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / m_o.stateRate));
    auto next = Clock::now();
    for (;;) {
        {
            std::unique_lock lock(m_publishMutex);
            if (m_publishWake.wait_until(lock, next, [this] { return m_quit; })) return;
        }
        m_bus->publish(buildState());
        next += period;
        const auto now = Clock::now();
        if (next < now - period) next = now;  // far behind: do not race to catch up
    }
}

void TrainStation::announceFor(const trainer::Tutorial* tutorial)
{
    if (!m_bus) return;
    const std::string modelFile = tutorial ? tutorial->modelFile : std::string();
    if (!m_announce.tutorials.empty() && modelFile == m_announcedModel) return;
    m_announcedModel = modelFile;
    m_announce.model = QFileInfo(QString::fromStdString(modelFile)).completeBaseName().toStdString();
    m_announce.modelHash = fileHash(modelFile).toStdString();
    m_announce.tutorials.clear();
    for (const auto& t : m_host->tutorials())
        if (t->modelFile == modelFile) m_announce.tutorials.push_back(t->spec.id);
    m_announce.language = m_host->language().toStdString();
    m_bus->announce(m_announce);
}

std::shared_ptr<const trainer::Tutorial> TrainStation::findTutorial(const std::string& id) const
{
    for (const auto& t : m_host->tutorials())
        if (t->spec.id == id) return t;
    return nullptr;
}

namespace {

StationStatus statusOf(const TrainFrame* f, bool live)
{
    if (!f) return StationStatus::Idle;
    if (f->ended || !live) return StationStatus::Ended;
    return f->paused ? StationStatus::Paused : StationStatus::Running;
}

}  // namespace

StationStatus TrainStation::status() const
{
    return statusOf(m_attempt ? m_attempt->frame.get() : nullptr, m_host->attemptFrame() != nullptr);
}

void TrainStation::tick()
{
    if (!m_bus) return;
    // the live attempt's newest frame (or the last attempt's, held)
    if (auto f = m_host->attemptFrame()) {
        if (!m_attempt || m_attempt->frame->generation != f->generation) {
            Attempt a;
            a.tutorial = m_host->attemptTutorial();
            a.operatorCode = m_host->attemptOperator().toStdString();
            m_attempt = std::move(a);
            if (m_attempt->tutorial) announceFor(m_attempt->tutorial.get());
        }
        m_attempt->frame = std::move(f);
    } else if (m_attempt) {
        // the attempt just ended and the page took it: its last frame (the end's events)
        auto last = m_host->latestFrame();
        if (last && last->snapshot && last->generation == m_attempt->frame->generation) m_attempt->frame = std::move(last);
    }
    for (const Command& c : m_bus->takeCommands())
        if (c.target == m_announce.node) handle(c);
    if (m_pending && !m_host->attemptFrame()) {
        const PendingStart p = *m_pending;
        m_pending.reset();
        doStart(p);
    }
    publishEvents();
    std::lock_guard lock(m_publishMutex);
    m_published.attempt = m_attempt;
    m_published.live = m_host->attemptFrame() != nullptr;
}

State TrainStation::buildState()
{
    Published p;
    {
        std::lock_guard lock(m_publishMutex);
        p = m_published;
    }
    // the runner's newest frame while the attempt is live (the GUI's copy lags behind it)
    std::shared_ptr<const TrainFrame> frame = p.attempt ? p.attempt->frame : nullptr;
    if (p.live && frame) {
        auto newest = m_host->latestFrame();
        if (newest && newest->snapshot && newest->generation == frame->generation) frame = std::move(newest);
    }
    StationSituation x;
    x.station = m_announce.node;
    x.status = statusOf(frame.get(), p.live);
    if (frame && p.attempt->tutorial) {
        const TrainFrame& f = *frame;
        const Snapshot& snap = *f.snapshot;
        x.tutorial = p.attempt->tutorial.get();
        x.operatorCode = p.attempt->operatorCode;
        x.simTime = snap.t;
        x.q = std::span<const double>(snap.theta.data(), static_cast<std::size_t>(snap.theta.size()));
        x.commands = std::span<const double>(snap.u.data(), static_cast<std::size_t>(snap.u.size()));
        x.progress = f.progress;
        x.score = f.score;
        if (f.output) x.endReason = f.output->result.endReason;
        x.faults = f.faults;
    }
    return trainer::centre::buildState(x, m_stateSeq++);
}

void TrainStation::publishEvents()
{
    if (!m_attempt || !m_attempt->frame || !m_attempt->tutorial) return;
    const TrainFrame& f = *m_attempt->frame;
    if (f.generation != m_generation) {
        m_generation = f.generation;
        m_publishedEvents = 0;
    }
    const std::string lang = m_host->language().toStdString();
    for (; m_publishedEvents < f.events.size(); ++m_publishedEvents)
        m_bus->publish(buildEvent(m_announce.node, m_eventSeq++, *m_attempt->tutorial, f.events[m_publishedEvents], lang));
}

void TrainStation::reply(const Command& c, bool accepted, const std::string& message)
{
    if (!m_bus) return;
    Reply r;
    r.station = m_announce.node;
    r.sender = c.sender;
    r.nonce = c.nonce;
    r.accepted = accepted;
    r.message = clip(message, limits::kText);
    m_bus->reply(r);
}

void TrainStation::instructorEvent(CommandKind kind, const std::string& sender, long generation)
{
    const std::string action = key(kind);
    m_host->runInSession(
        [action, sender](trainer::TutorialSession& s, QString&) {
            s.addInstructorEvent(action, sender);
            return true;
        },
        {}, generation);
}

bool TrainStation::doStart(const PendingStart& p)
{
    const long g = m_host->startAttempt(QString::fromStdString(p.tutorial), QString::fromStdString(p.operatorCode));
    if (g == 0) return false;
    instructorEvent(p.action, p.sender, g);
    return true;
}

void TrainStation::handle(const Command& c)
{
    std::string why;
    if (!m_guard->accept(c, wallMs(), why)) {
        reply(c, false, why);
        return;
    }
    const StationStatus st = status();
    const CommandKind kind = commandKind(c.kind);
    const long generation = m_attempt && m_attempt->frame ? m_attempt->frame->generation : 0;
    Refusal refusal = Refusal::UnknownCommand;
    FaultCommand fault;
    if (refused(c, kind, st, &fault, &refusal)) {
        reply(c, false, key(refusal));
        return;
    }
    switch (kind) {
    case CommandKind::Start:
    case CommandKind::Reset: {
        PendingStart p;
        p.action = kind;
        p.sender = c.sender;
        if (kind == CommandKind::Start) {
            p.tutorial = c.arg;
            p.operatorCode = c.arg2;
        } else if (m_attempt && m_attempt->tutorial) {
            p.tutorial = m_attempt->tutorial->spec.id;
            p.operatorCode = m_attempt->operatorCode;
        }
        if (p.tutorial.empty()) {
            const auto all = m_host->tutorials();
            if (m_attempt && m_attempt->tutorial) p.tutorial = m_attempt->tutorial->spec.id;
            else if (!all.empty()) p.tutorial = all.front()->spec.id;
        }
        bool done = false;
        if (findTutorial(p.tutorial)) {
            if (m_host->attemptFrame()) {
                // the attempt on now ends first (aborted, recorded as the trainee's Stop
                // does), then the new one starts (tick())
                if (attemptOn(st)) m_host->stopAttempt();
                m_pending = p;
                done = true;
            } else {
                m_pending.reset();
                done = doStart(p);
            }
        }
        reply(c, done, done ? kDone : key(Refusal::UnknownTutorial));
        return;
    }
    case CommandKind::Pause:
        m_host->setPaused(true);
        instructorEvent(kind, c.sender, generation);
        break;
    case CommandKind::Resume:
        instructorEvent(kind, c.sender, generation);
        m_host->setPaused(false);
        break;
    case CommandKind::Stop:
        instructorEvent(kind, c.sender, generation);
        m_host->stopAttempt();
        break;
    case CommandKind::Inject:
    case CommandKind::Clear: {
        // the session does it in the runner's thread; the reply waits for its answer
        QPointer<TrainStation> self(this);
        m_host->runInSession(
            [kind, fault](trainer::TutorialSession& s, QString& error) { return applyFault(s, kind, fault, &error); },
            [self, c](bool ok, const QString& error) {
                if (self) self->reply(c, ok, ok ? std::string(kDone) : error.toStdString());
            },
            generation);
        return;
    }
    case CommandKind::Unknown: return;  // (refused above)
    }
    reply(c, true, kDone);
}

}  // namespace studio
