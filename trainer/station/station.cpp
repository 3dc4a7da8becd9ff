#include "trainer/station/station.h"

#include "trainer/input/input_log.h"
#include "trainer/input/sdl_joysticks.h"

#include <QThread>
#include <QTimer>


namespace trainer {

Station::Station(CommandSink sink)
    : m_sink(std::move(sink)), m_engine(std::make_unique<StationEngine>()), m_epoch(std::chrono::steady_clock::now())
{
}

Station::~Station()
{
    stop();
}

double Station::now() const
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_epoch).count();
}

void Station::start(bool withSdl)
{
    if (m_thread) return;
    m_thread = new QThread;
    m_thread->setObjectName("padrob-input");
    moveToThread(m_thread);
    // runs in the new thread as it starts (connected before it exists: no hand-over)
    connect(m_thread, &QThread::started, this, [this, withSdl] { begin(withSdl); }, Qt::DirectConnection);
    m_thread->start();
}

void Station::begin(bool withSdl)
{
    if (withSdl) m_engine->addProvider(std::make_unique<SdlJoysticks>());
    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    m_timer->setInterval(kPeriodMs);
    connect(m_timer, &QTimer::timeout, this, &Station::tick);
    m_timer->start();
    tick();
}

void Station::finish()
{
    delete m_timer;
    m_timer = nullptr;
    m_engine.reset();  // the devices (QSerialPort, SDL) die in their own thread
    moveToThread(nullptr);
    QThread::currentThread()->quit();
}

void Station::stop()
{
    if (!m_thread) {
        m_engine.reset();
        return;
    }
    {
        std::lock_guard lock(m_postMutex);
        m_stopping = true;
    }
    m_thread->wait();  // the next tick finishes
    delete m_thread;
    m_thread = nullptr;
    std::lock_guard lock(m_postMutex);
    m_queue.clear();
    m_doneCount = m_postCount;
    m_posted.notify_all();
}

bool Station::isRunning() const
{
    return m_thread && m_thread->isRunning();
}

void Station::post(std::function<void(StationEngine&)> f)
{
    if (!m_thread) {
        if (m_engine) f(*m_engine);
        return;
    }
    std::lock_guard lock(m_postMutex);
    if (m_stopping) return;
    m_queue.push_back(std::move(f));
    ++m_postCount;
}

void Station::call(std::function<void(StationEngine&)> f)
{
    if (!m_thread) {
        if (m_engine) f(*m_engine);
        return;
    }
    std::unique_lock lock(m_postMutex);
    if (m_stopping) return;
    m_queue.push_back([&f](StationEngine& e) { f(e); });
    const std::uint64_t mine = ++m_postCount;
    m_posted.wait(lock, [&] { return m_doneCount >= mine; });
}

bool Station::startRecording(InputRecorder& recorder, const QString& path, QString* error, StationProfile* profile)
{
    bool ok = false, ran = false;
    call([&](StationEngine& e) {
        ran = true;
        ok = recorder.start(path, e.state().time, error);
        if (ok) e.setRecorder(&recorder);
        if (profile) *profile = e.profile();
    });
    if (!ran && error) *error = tr("the station is not running");
    return ok;
}

bool Station::stopRecording(InputRecorder& recorder, QString* error)
{
    bool ok = false, ran = false;
    call([&](StationEngine& e) {
        ran = true;
        e.setRecorder(nullptr);
        ok = recorder.stop(error);
    });
    if (!ran) ok = recorder.stop(error);  // no engine any more: nobody else uses it
    return ok;
}

void Station::drain()
{
    for (;;) {
        std::function<void(StationEngine&)> f;
        {
            std::lock_guard lock(m_postMutex);
            if (m_queue.empty()) return;
            f = std::move(m_queue.front());
            m_queue.pop_front();
        }
        if (m_engine) f(*m_engine);
        m_lastPublish = -1.0;  // the change shows in the next state
        std::lock_guard lock(m_postMutex);
        ++m_doneCount;
        m_posted.notify_all();
    }
}

std::shared_ptr<const StationState> Station::latest() const
{
    std::lock_guard lock(m_stateMutex);
    return m_state;
}

void Station::tick()
{
    bool stopping = false;
    {
        std::lock_guard lock(m_postMutex);
        stopping = m_stopping;
    }
    if (stopping) {
        finish();
        return;
    }
    drain();
    if (!m_engine) return;
    const double t = now();
    if (m_engine->update(t) && m_sink) m_sink(m_engine->commands());
    if (m_lastPublish < 0.0 || t - m_lastPublish >= 1.0 / kStateRate) {
        m_lastPublish = t;
        auto state = std::make_shared<const StationState>(m_engine->state());
        std::lock_guard lock(m_stateMutex);
        m_state = std::move(state);
    }
}

}  // namespace trainer
