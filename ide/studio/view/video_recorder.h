#pragma once
// VideoRecorder: a video of the 3D view. Frames come from a source (a function that
// draws one, e.g. Viewport::grabFramebuffer(), or several screens side by side) at a
// fixed rate and go as raw RGBA over a pipe to the `ffmpeg` program (Debian package
// ffmpeg, a recommendation of padrob's .deb), which encodes them with H.264 (libx264)
// into the file: .mp4, .mkv or .mov by the file's name.
//
// The video plays at the wall clock's pace: at every tick the frames due since the
// start are written, the newest drawing repeated when drawing took longer than a frame
// (on a software OpenGL a large view draws slower than 25 frames a second). Every frame
// has the size of the first (even width and height, as yuv420p needs); a view resized
// meanwhile is scaled to it.
//
// start() refuses, with a sentence saying why: no ffmpeg on the PATH (or where
// setProgram() says), a name that is not a regular file (a folder, a device, a pipe), a
// protected file (the model being edited, the scene), a folder that cannot be written,
// a view that cannot draw. stop() closes the pipe; finished() comes when ffmpeg has
// written the file (or failed, with its message).

#include <QElapsedTimer>
#include <QImage>
#include <QObject>
#include <QSize>
#include <QString>
#include <QStringList>

#include <functional>

class QProcess;
class QTimer;

namespace studio {

class VideoRecorder : public QObject {
    Q_OBJECT
public:
    using FrameSource = std::function<QImage()>;
    static constexpr int kDefaultFps = 25;

    explicit VideoRecorder(QObject* parent = nullptr);
    /// A recording still going is stopped and its file finished (waits for ffmpeg).
    ~VideoRecorder() override;

    /// The encoder program: "ffmpeg" found on the PATH unless set (tests set a missing
    /// one). "" when it cannot be found.
    QString program() const;
    void setProgram(const QString& program) { m_program = program; }

    /// Starts recording frames of `source` at `fps` (1 … 60) into `path` (".mp4" added
    /// when it has none of .mp4, .mkv, .mov); never overwrites a file of `protectedPaths`.
    /// False with `error` set when it cannot.
    bool start(const QString& path, FrameSource source, const QStringList& protectedPaths, QString* error,
               int fps = kDefaultFps);
    /// Stops: the pipe is closed and ffmpeg finishes the file (finished()).
    void stop();
    bool isRecording() const { return m_process != nullptr && !m_stopping; }

    /// The file being (or last) written.
    QString path() const { return m_path; }
    QSize frameSize() const { return m_size; }
    int fps() const { return m_fps; }
    /// Frames written so far.
    long frames() const { return m_frames; }
    /// Seconds recorded so far.
    double seconds() const { return m_fps > 0 ? double(m_frames) / m_fps : 0.0; }

signals:
    /// A frame (or several) written: for a "recording" indicator.
    void progressed();
    /// ffmpeg finished the file (ok), or failed (`message` says why).
    void finished(bool ok, const QString& message);

private:
    void capture();
    void write(const QImage& frame, long copies);
    void onProcessFinished(int exitCode);

    QString m_program;
    QString m_path;
    FrameSource m_source;
    QProcess* m_process = nullptr;
    QTimer* m_timer = nullptr;
    QElapsedTimer m_clock;
    QSize m_size;
    int m_fps = kDefaultFps;
    long m_frames = 0;
    bool m_stopping = false;
};

}  // namespace studio
