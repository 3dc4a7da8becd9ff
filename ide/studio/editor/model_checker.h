#pragma once
// ModelChecker: loads and compiles model text (studio::makeBundle) on a worker
// thread, so that a big file never blocks the editor while the modeler types.
// One check runs at a time; a check asked for while one runs waits, and only the
// newest waiting one is kept (older texts are out of date anyway). Results come
// back in the GUI thread through `finished`, tagged with the caller's revision.
// (STYLE habit 9: a parentless worker object moved to a QThread.)

#include "ide/studio/model/model_bundle.h"
#include "solver/core/diagnostic.h"

#include <QObject>
#include <QString>
#include <QThread>

#include <memory>
#include <optional>

namespace studio {

class ModelChecker : public QObject {
    Q_OBJECT
public:
    struct Result {
        quint64 revision = 0;                       ///< as given to check()
        std::shared_ptr<const ModelBundle> bundle;  ///< null when the text has errors
        solver::Diagnostics diagnostics;            ///< load and compile, in order
        qint64 elapsedMs = 0;                       ///< time the check took
    };

    explicit ModelChecker(QObject* parent = nullptr);
    /// Waits for a running check to end.
    ~ModelChecker() override;

    /// Checks `text` (named `filePath`, the base of mesh paths) in the background.
    void check(quint64 revision, const QString& text, const QString& filePath);
    /// A check is running or waiting.
    bool isBusy() const { return m_running || m_pending.has_value(); }

signals:
    void finished(const studio::ModelChecker::Result& result);

private:
    struct Job {
        quint64 revision;
        QString text, filePath;
    };
    void start(Job job);
    void deliver(const Result& result);

    QThread m_thread;
    QObject* m_worker = nullptr;  // lives in m_thread; runs the jobs
    bool m_running = false;
    std::optional<Job> m_pending;
};

}  // namespace studio
