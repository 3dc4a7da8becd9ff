// MainWindow: the model's file changed on disk (reloaded, keeping the pose), the bar
// that says the editor's text is not applied, and poses sent to the simulation.

#include "ide/studio/app/main_window.h"

#include "ide/studio/editor/editor_panel.h"
#include "ide/studio/sim/simulation_runner.h"

#include <QDir>
#include <QFileInfo>
#include <QHash>
#include <QLabel>
#include <QPushButton>
#include <QStatusBar>

namespace studio {

namespace {

/// What names tree joint j across two compilations of a model: its name (its id when it
/// has none), which coordinate of a free joint it is, and its type.
QString jointKey(const solver::Model& m, int j)
{
    const std::string& name = m.jointName[static_cast<std::size_t>(j)];
    return QStringLiteral("%1|%2|%3")
        .arg(name.empty() ? QStringLiteral("#%1").arg(m.jointId[static_cast<std::size_t>(j)]) : QString::fromStdString(name))
        .arg(m.freeSlot[static_cast<std::size_t>(j)])
        .arg(static_cast<int>(m.jointType[static_cast<std::size_t>(j)]));
}

/// `theta` of model `from` as a pose of model `to` (θ per tree joint, dim to.nb) when
/// both have the same joints (jointKey); nothing otherwise.
std::optional<Eigen::VectorXd> carryPose(const solver::Model& from, const Eigen::VectorXd& theta, const solver::Model& to)
{
    if (from.nb != to.nb || theta.size() < from.nb) return std::nullopt;
    QHash<QString, double> byKey;
    for (int j = 0; j < from.nb; ++j) byKey.insert(jointKey(from, j), theta[j]);
    Eigen::VectorXd out(to.nb);
    for (int j = 0; j < to.nb; ++j) {
        const auto it = byKey.constFind(jointKey(to, j));
        if (it == byKey.cend()) return std::nullopt;
        out[j] = *it;
    }
    return out;
}

}  // namespace

void MainWindow::onFileChangedOnDisk(const QString& path, bool deleted)
{
    if (deleted) {
        statusBar()->showMessage(tr("%1 was deleted or moved on disk; the text in the editor is kept — save it to "
                                    "write it again.").arg(QDir::toNativeSeparators(path)));
        return;
    }
    // unsaved edits are not replaced without asking: the editor offers to reload
    if (m_editor->isModified()) m_editor->offerReload(path);
    else reloadFromDisk();
}

void MainWindow::reloadFromDisk()
{
    const std::shared_ptr<const Snapshot> s = m_runner->latest();
    m_keptPose.reset();
    if (s && m_bundle && s->bundle == m_bundle)
        m_keptPose = KeptPose{m_bundle, s->theta, s->running, m_editor->filePath()};
    QString error;
    if (!m_editor->reload(&error)) {
        m_keptPose.reset();
        statusBar()->showMessage(error, 15000);
        return;
    }
    m_editor->apply();  // after its check; with errors it is not applied (restoreKeptPose never comes)
}

void MainWindow::restoreKeptPose()
{
    if (!m_keptPose) return;
    const KeptPose kept = *std::exchange(m_keptPose, std::nullopt);
    const QString name = QFileInfo(kept.file).fileName();
    const std::optional<Eigen::VectorXd> theta = carryPose(*kept.bundle->model, kept.theta, *m_bundle->model);
    if (theta) sendPose(*theta);
    statusBar()->showMessage(theta ? tr("%1 changed on disk and was reloaded; the pose is kept.").arg(name)
                                   : tr("%1 changed on disk and was reloaded; its joints changed, so it starts from "
                                        "the initial pose.").arg(name),
                             8000);
    if (kept.running) run();
}

bool MainWindow::sendPose(const Eigen::VectorXd& theta)
{
    if (!m_runner->setPositions(theta)) return false;
    ++m_posesSent;
    return true;
}

void MainWindow::updateUnappliedBar()
{
    m_unappliedText->setText(tr("The editor has changes that are not applied: the 3D view, the tree and the plots "
                                "show the model applied before. Apply (Ctrl+Return) to use them, or Revert."));
    m_unappliedApply->setText(tr("Apply"));
    m_unappliedRevert->setText(tr("Revert"));
    m_unappliedRevert->setToolTip(tr("Put the applied model's text back in the editor (Undo brings the edits back)"));
    m_unappliedBar->setVisible(m_editor->hasUnappliedChanges());
}

}  // namespace studio
