// MainWindow's tools: the Simulation toolbar of the Model workspace (the Simulation
// menu's own actions, with icons, and the speed) and View ▸ Record Video… (frames of
// the 3D view to a video file through ffmpeg, VideoRecorder). The rest of the window
// is in main_window.cpp and main_window_menus.cpp.

#include "ide/studio/app/main_window.h"

#include "ide/studio/app/menu_items.h"
#include "ide/studio/editor/editor_panel.h"
#include "ide/studio/train/train_page.h"
#include "ide/studio/view/video_recorder.h"
#include "ide/studio/view/viewport.h"
#include "ide/studio/view/viewport_layout.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QIcon>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPainter>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>

namespace studio {

namespace {

/// Why a recording did not start or did not end well (not modal: the window goes on).
void showRecordingProblem(QWidget* parent, const QString& message)
{
    auto* box = new QMessageBox(QMessageBox::Warning, MainWindow::tr("Record Video"), message, QMessageBox::Ok, parent);
    box->setObjectName("RecordingProblemBox");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::NonModal);
    box->show();
}

}  // namespace

void MainWindow::buildSimulationBar()
{
    MenuItems& m = *m_items;
    // the Simulation menu's actions themselves (enabled, shortcuts and all), with the
    // theme's icons, else the style's
    const auto icon = [this](const char* theme, QStyle::StandardPixmap fallback) {
        return QIcon::fromTheme(QString::fromLatin1(theme), style()->standardIcon(fallback));
    };
    m_runAction->setIcon(icon("media-playback-start", QStyle::SP_MediaPlay));
    m_pauseAction->setIcon(icon("media-playback-pause", QStyle::SP_MediaPause));
    m_stepAction->setIcon(icon("media-skip-forward", QStyle::SP_MediaSkipForward));
    m_resetAction->setIcon(icon("media-skip-backward", QStyle::SP_MediaSkipBackward));
    auto* bar = new QToolBar;
    bar->setObjectName("SimulationBar");
    bar->setToolButtonStyle(Qt::ToolButtonIconOnly);
    bar->addActions({m_runAction, m_pauseAction, m_stepAction, m_resetAction});
    // the speed: the choices of Simulation ▸ Speed, the two kept in step
    m_speedLabel = new QLabel;
    m_speedLabel->setContentsMargins(8, 0, 4, 0);
    bar->addWidget(m_speedLabel);
    m_speedBox = new QComboBox;
    m_speedBox->setObjectName("SpeedBox");
    for (const auto& [action, s] : m.speeds) {
        m_speedBox->addItem(QString(), s);
        if (action->isChecked()) m_speedBox->setCurrentIndex(m_speedBox->count() - 1);
    }
    m_speedLabel->setBuddy(m_speedBox);
    bar->addWidget(m_speedBox);
    connect(m_speedBox, &QComboBox::activated, this, [this](int i) {
        if (i >= 0 && std::size_t(i) < m_items->speeds.size()) m_items->speeds[std::size_t(i)].first->trigger();
    });
    connect(m_speedGroup, &QActionGroup::triggered, this, [this](QAction* a) {
        for (std::size_t i = 0; i < m_items->speeds.size(); ++i)
            if (m_items->speeds[i].first == a) m_speedBox->setCurrentIndex(int(i));
    });
    bar->addSeparator();
    m.record->setIcon(icon("media-record", QStyle::SP_DialogNoButton));
    bar->addAction(m.record);
    m_modelSpace->addToolBar(Qt::TopToolBarArea, bar);

    // the recording and its indicator in the status bar
    m_recorder = new VideoRecorder(this);
    m_recordingLabel = new QLabel;
    m_recordingLabel->setObjectName("RecordingLabel");
    m_recordingLabel->setStyleSheet("QLabel { color: white; background: #c62828; border-radius: 4px; "
                                    "padding: 1px 8px; font-weight: bold; }");
    m_recordingLabel->hide();
    statusBar()->addPermanentWidget(m_recordingLabel);
    connect(m_recorder, &VideoRecorder::progressed, this, &MainWindow::updateRecordingLabel);
    connect(m_recorder, &VideoRecorder::finished, this, [this](bool ok, const QString& message) {
        updateRecordingLabel();
        if (ok) {
            statusBar()->showMessage(tr("Video saved: %1 (%2 s)")
                                         .arg(QDir::toNativeSeparators(m_recorder->path()),
                                              QLocale().toString(m_recorder->seconds(), 'f', 1)),
                                     10000);
            return;
        }
        showRecordingProblem(this, message);
    });
}

void MainWindow::retranslateTools()
{
    // the toolbar's tips name the shortcuts
    for (QAction* a : {m_runAction, m_pauseAction, m_stepAction, m_resetAction}) {
        const QString text = QString(a->text()).remove(QLatin1Char('&'));
        a->setToolTip(tr("%1 (%2)", "an action and its shortcut")
                          .arg(text, a->shortcut().toString(QKeySequence::NativeText)));
    }
    m_speedLabel->setText(tr("Speed:"));
    m_speedBox->setToolTip(tr("Simulated seconds per second of the wall clock (Simulation ▸ Speed)"));
    for (int i = 0; i < m_speedBox->count(); ++i)
        m_speedBox->setItemText(i, QStringLiteral("×%1").arg(QLocale().toString(m_speedBox->itemData(i).toDouble())));
    updateRecordingLabel();
}

// ---------------------------------------------------------------- the recording

QImage MainWindow::recordedFrame() const
{
    // the Train attempt's view while it shows, else the Model workspace's screens side by side
    if (workspace() == Workspace::Train) {
        Viewport* v = m_trainPage->attemptViewport();
        return v->isVisible() ? v->grabFramebuffer() : QImage();
    }
    if (m_viewports->screens() == 1 || m_viewports->separateWindows()) return m_viewports->viewport(0)->grabFramebuffer();
    QList<QImage> frames;
    int width = 0, height = 0;
    for (int i = 0; i < m_viewports->screens(); ++i) {
        frames << m_viewports->viewport(i)->grabFramebuffer();
        if (frames.back().isNull()) return {};
        width += frames.back().width();
        height = std::max(height, frames.back().height());
    }
    QImage out(width, height, QImage::Format_RGB32);
    out.fill(Qt::black);
    QPainter p(&out);
    int x = 0;
    for (const QImage& f : frames) {
        p.drawImage(x, 0, f);
        x += f.width();
    }
    return out;
}

bool MainWindow::startRecording(const QString& path, QString* error)
{
    QStringList protectedPaths = {m_editor->filePath(), m_scenePath};
    const bool ok = m_recorder->start(path, [this] { return recordedFrame(); }, protectedPaths, error);
    updateRecordingLabel();
    return ok;
}

void MainWindow::stopRecording()
{
    m_recorder->stop();
    updateRecordingLabel();
}

void MainWindow::toggleRecording()
{
    if (m_recorder->isRecording()) return stopRecording();
    QString error;
    if (m_recorder->program().isEmpty()) {
        startRecording(QString(), &error);  // (says that ffmpeg is missing, before asking for a file)
    } else {
        const QString start = QStandardPaths::writableLocation(QStandardPaths::MoviesLocation) + "/padrob.mp4";
        const QString path = QFileDialog::getSaveFileName(this, tr("Record Video"), start,
                                                          tr("Videos (*.mp4 *.mkv *.mov)"));
        if (path.isEmpty() || startRecording(path, &error)) return;
    }
    showRecordingProblem(this, error);
}

void MainWindow::updateRecordingLabel()
{
    const bool on = m_recorder->isRecording();
    m_items->record->setText(on ? tr("Stop &Recording") : tr("&Record Video…"));
    m_items->record->setToolTip(on ? tr("Stop recording the 3D view") : tr("Record a video of the 3D view (ffmpeg)"));
    m_recordingLabel->setVisible(on);
    if (!on) return;
    const int s = int(m_recorder->seconds());
    m_recordingLabel->setText(tr("● REC %1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0')));
    m_recordingLabel->setToolTip(QDir::toNativeSeparators(m_recorder->path()));
}

}  // namespace studio
