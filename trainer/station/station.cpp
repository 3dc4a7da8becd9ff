#include "trainer/station/station.h"

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
    m_thread->start();
    post([this, withSdl](StationEngine& e) {
        if (withSdl) e.addProvider(std::make_unique<SdlJoysticks>());
        m_timer = new QTimer(this);
        m_timer->setTimerType(Qt::PreciseTimer);
        m_timer->setInterval(kPeriodMs);
        connect(m_timer, &QTimer::timeout, this, &Station::tick);
        m_timer->start();
        tick();
    });
}

void Station::stop()
{
    if (!m_thread) {
        m_engine.reset();
        return;
    }
    // the engine, its devices (QSerialPort, SDL) and the timer die in their own thread
    QMetaObject::invokeMethod(
        this,
        [this] {
            delete m_timer;
            m_timer = nullptr;
            m_engine.reset();
            moveToThread(nullptr);
            QThread::currentThread()->quit();
        },
        Qt::QueuedConnection);
    m_thread->wait();
    delete m_thread;
    m_thread = nullptr;
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
    QMetaObject::invokeMethod(
        this,
        [this, f = std::move(f)] {
            if (m_engine) f(*m_engine);
            m_lastPublish = -1.0;  // the change shows in the next state
        },
        Qt::QueuedConnection);
}

void Station::call(std::function<void(StationEngine&)> f)
{
    if (!m_thread) {
        if (m_engine) f(*m_engine);
        return;
    }
    QMetaObject::invokeMethod(
        this,
        [this, &f] {
            if (m_engine) f(*m_engine);
            m_lastPublish = -1.0;
        },
        Qt::BlockingQueuedConnection);
}

std::shared_ptr<const StationState> Station::latest() const
{
    std::lock_guard lock(m_stateMutex);
    return m_state;
}

void Station::tick()
{
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
