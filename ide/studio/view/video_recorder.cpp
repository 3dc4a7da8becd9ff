#include "ide/studio/view/video_recorder.h"

#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace studio {

namespace {

/// The same file (both existing), whatever the links and relative parts of the names.
bool sameFile(const QFileInfo& a, const QString& b)
{
    const QFileInfo fb(b);
    return !b.isEmpty() && a.exists() && fb.exists() && a.canonicalFilePath() == fb.canonicalFilePath();
}

}  // namespace

VideoRecorder::VideoRecorder(QObject* parent) : QObject(parent)
{
    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &VideoRecorder::capture);
}

VideoRecorder::~VideoRecorder()
{
    if (!m_process) return;
    m_timer->stop();
    m_process->disconnect(this);
    m_process->closeWriteChannel();
    m_process->waitForFinished(10000);
}

QString VideoRecorder::program() const
{
    if (!m_program.isEmpty()) return QFileInfo(m_program).isExecutable() ? m_program : QString();
    return QStandardPaths::findExecutable(QStringLiteral("ffmpeg"));
}

bool VideoRecorder::start(const QString& path, FrameSource source, const QStringList& protectedPaths, QString* error,
                          int fps)
{
    const auto fail = [error](const QString& why) {
        if (error) *error = why;
        return false;
    };
    if (m_process) return fail(tr("A video is being recorded already."));
    const QString ffmpeg = program();
    if (ffmpeg.isEmpty())
        return fail(tr("Recording a video needs the program ffmpeg, which was not found. Install it (on Debian and "
                       "Ubuntu: sudo apt install ffmpeg) and try again."));
    QString target = path;
    const QString suffix = QFileInfo(target).suffix().toLower();
    if (suffix != QLatin1String("mp4") && suffix != QLatin1String("mkv") && suffix != QLatin1String("mov"))
        target += QStringLiteral(".mp4");
    const QFileInfo fi(target);
    const QString shown = QDir::toNativeSeparators(fi.absoluteFilePath());
    // (exists() follows links: a link to a folder or a device is not a regular file either)
    if ((fi.exists() || fi.isSymLink()) && !fi.isFile())
        return fail(tr("%1 is not a regular file (a folder, a device or a pipe): it is not overwritten.").arg(shown));
    for (const QString& p : protectedPaths)
        if (sameFile(fi, p))
            return fail(tr("%1 is a file Padrob Studio has open (the model or the scene): it is not overwritten.")
                            .arg(shown));
    const QFileInfo folder(fi.absolutePath());
    if (!folder.isDir() || !folder.isWritable())
        return fail(tr("The folder %1 cannot be written.").arg(QDir::toNativeSeparators(folder.absoluteFilePath())));
    const QImage first = source ? source() : QImage();
    if (first.isNull() || first.width() < 2 || first.height() < 2)
        return fail(tr("The 3D view cannot be drawn (no OpenGL 3.3): there is nothing to record."));

    m_fps = std::clamp(fps, 1, 60);
    m_size = QSize(first.width() & ~1, first.height() & ~1);  // yuv420p: even sizes
    m_path = fi.absoluteFilePath();
    m_source = std::move(source);
    m_frames = 0;
    m_stopping = false;
    m_process = new QProcess(this);
    m_process->setProcessChannelMode(QProcess::SeparateChannels);
    const QStringList args = {
        "-hide_banner", "-loglevel", "error", "-nostdin", "-y",
        // the frames as they come: raw RGBA of a fixed size and rate, on the standard input
        "-f", "rawvideo", "-pix_fmt", "rgba", "-video_size",
        QStringLiteral("%1x%2").arg(m_size.width()).arg(m_size.height()), "-framerate", QString::number(m_fps),
        "-i", "pipe:0",
        // H.264 in 4:2:0, which every player reads
        "-an", "-c:v", "libx264", "-preset", "veryfast", "-pix_fmt", "yuv420p", m_path};
    connect(m_process, &QProcess::finished, this, [this](int exitCode) { onProcessFinished(exitCode); });
    m_process->start(ffmpeg, args);
    if (!m_process->waitForStarted(5000)) {
        const QString why = m_process->errorString();
        delete m_process;
        m_process = nullptr;
        return fail(tr("ffmpeg (%1) could not be started: %2").arg(ffmpeg, why));
    }
    m_clock.start();
    write(first, 1);
    m_timer->start(1000 / m_fps);
    return true;
}

void VideoRecorder::capture()
{
    if (!m_process || m_stopping) return;
    // the frames due by now, the newest drawing for each (the video keeps the clock's pace)
    const long due = long(std::floor(m_clock.nsecsElapsed() * 1e-9 * m_fps)) + 1;
    if (due <= m_frames) return;
    const QImage frame = m_source();
    if (frame.isNull()) return;
    write(frame, due - m_frames);
}

void VideoRecorder::write(const QImage& image, long copies)
{
    QImage frame = image.convertToFormat(QImage::Format_RGBA8888);
    if (frame.size() != m_size) {
        frame = frame.width() >= m_size.width() && frame.height() >= m_size.height() &&
                        frame.width() - m_size.width() <= 1 && frame.height() - m_size.height() <= 1
                    ? frame.copy(0, 0, m_size.width(), m_size.height())
                    : frame.scaled(m_size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    }
    const QByteArray bytes(reinterpret_cast<const char*>(frame.constBits()), qsizetype(frame.sizeInBytes()));
    const qint64 backlog = 8 * qint64(bytes.size());
    for (long i = 0; i < copies; ++i) {
        m_process->write(bytes);
        ++m_frames;
        // ffmpeg behind: wait for it rather than pile the frames up in memory
        while (m_process->bytesToWrite() > backlog && m_process->state() == QProcess::Running)
            m_process->waitForBytesWritten(200);
    }
    emit progressed();
}

void VideoRecorder::stop()
{
    if (!m_process || m_stopping) return;
    m_timer->stop();
    m_stopping = true;
    m_process->closeWriteChannel();
}

void VideoRecorder::onProcessFinished(int exitCode)
{
    m_timer->stop();
    const QString log = QString::fromLocal8Bit(m_process->readAllStandardError()).trimmed();
    const bool ok = m_stopping && exitCode == 0 && m_process->exitStatus() == QProcess::NormalExit;
    m_process->deleteLater();
    m_process = nullptr;
    m_stopping = false;
    QString message;
    if (!ok) {
        message = tr("ffmpeg stopped with an error while writing %1").arg(QDir::toNativeSeparators(m_path));
        if (!log.isEmpty()) message += QStringLiteral(":\n") + log.right(600);
    }
    emit finished(ok, message);
}

}  // namespace studio
