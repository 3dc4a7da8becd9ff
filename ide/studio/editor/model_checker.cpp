#include "ide/studio/editor/model_checker.h"

#include <QElapsedTimer>

namespace studio {

ModelChecker::ModelChecker(QObject* parent) : QObject(parent)
{
    m_worker = new QObject;
    m_worker->moveToThread(&m_thread);
    m_thread.setObjectName(QStringLiteral("padrob-model-check"));
    m_thread.start(QThread::LowPriority);
}

ModelChecker::~ModelChecker()
{
    m_thread.quit();
    m_thread.wait();  // a running check ends first; its result is dropped with us
    delete m_worker;
}

void ModelChecker::check(quint64 revision, const QString& text, const QString& filePath)
{
    Job job{revision, text, filePath};
    if (m_running) {
        m_pending = std::move(job);
        return;
    }
    start(std::move(job));
}

void ModelChecker::start(Job job)
{
    m_running = true;
    QMetaObject::invokeMethod(
        m_worker,
        [this, job = std::move(job)] {
            QElapsedTimer clock;
            clock.start();
            Result r;
            r.revision = job.revision;
            r.diagnostics.setFile(job.filePath.toStdString());
            r.bundle = makeBundle(job.text, job.filePath, r.diagnostics);
            r.elapsedMs = clock.elapsed();
            // back to the GUI thread (this object lives there and outlives the worker)
            QMetaObject::invokeMethod(this, [this, r = std::move(r)] { deliver(r); }, Qt::QueuedConnection);
        },
        Qt::QueuedConnection);
}

void ModelChecker::deliver(const Result& result)
{
    m_running = false;
    if (m_pending) {
        Job next = std::move(*m_pending);
        m_pending.reset();
        start(std::move(next));
    }
    emit finished(result);
}

}  // namespace studio
