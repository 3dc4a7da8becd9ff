#pragma once
// The input log: what devices read, with its timing, for demonstrations and tests.
// Raw readings are recorded (before calibration and mapping), so a replay goes
// through the station exactly as the devices did. Text, one file for any number of
// devices (format in docs/station.md):
//
//   # padrob input log 1
//   #device 0 {"id":"sdl:03…","name":"Xbox 360 Controller","kind":"gamepad",
//              "axes":[{"name":"leftx","min":-32768,"rest":0,"max":32767},…],
//              "buttons":["a","b",…]}
//   0.000000,0,0,0,0,0,0,0,0,0,…       t [s], device, axes…, buttons (0/1)…
//   0.012000,0,1200,-32768,…
//
// A line is written when a device's sample changes. Times start at 0 and never go
// back.

#include "trainer/input/input_device.h"

#include <QFile>
#include <QHash>
#include <QList>
#include <QString>

#include <memory>
#include <vector>

namespace trainer {

struct LoggedSample {
    double time = 0.0;
    int device = 0;
    std::vector<double> axes;
    std::vector<std::uint8_t> buttons;
};

struct InputLog {
    QList<DeviceInfo> devices;
    std::vector<LoggedSample> samples;  ///< in time order
    double duration() const { return samples.empty() ? 0.0 : samples.back().time; }

    /// Reads a log (trainer/io/read_file.h: a regular file, at most kMaxInputLogBytes).
    /// False with `error` ("x.log: line 12: …", translated) when the file cannot be read
    /// or is malformed; `out` is then untouched.
    static bool load(const QString& path, InputLog& out, QString* error);
    static bool parse(const QByteArray& text, InputLog& out, QString* error);
};

/// Records the samples the station reads to a log file (in the station's thread).
class InputRecorder {
public:
    InputRecorder() = default;
    ~InputRecorder();
    /// Starts a new log at `path` (replaced); time 0 is `now`. False with `error`.
    bool start(const QString& path, double now, QString* error = nullptr);
    /// Writes `sample` of `device` at station time `now` (ignored when not started).
    void record(double now, const InputDevice& device, const DeviceSample& sample);
    /// Flushes and closes. False with `error` when the disk refused.
    bool stop(QString* error = nullptr);
    bool isRecording() const { return m_file.isOpen(); }
    std::uint64_t linesWritten() const { return m_lines; }

private:
    QFile m_file;
    QHash<QString, int> m_index;  ///< device id → index in the log
    double m_origin = 0.0;
    double m_lastFlush = 0.0;
    std::uint64_t m_lines = 0;
};

/// Plays one device of a log with its timing: the recorded device's id and kind (so
/// the same profile applies), isReplay() true. Its clock starts at the first poll (or
/// start()); speed, pause and seek serve demonstrations.
class ReplayDevice : public InputDevice {
public:
    ReplayDevice(std::shared_ptr<const InputLog> log, int device);

    /// Plays from log time `from` [s], starting at station time `now`.
    void start(double now, double from = 0.0);
    void setSpeed(double speed);
    void setPaused(bool paused);
    /// Log time now [s].
    double position() const;
    bool finished() const;

    const DeviceInfo& info() const override { return m_info; }
    void poll(double now) override;
    const DeviceSample& sample() const override { return m_sample; }
    DeviceStatus status() const override { return DeviceStatus::Connected; }
    bool isReplay() const override { return true; }

private:
    std::shared_ptr<const InputLog> m_log;
    int m_device = 0;
    DeviceInfo m_info;
    DeviceSample m_sample;
    std::size_t m_next = 0;
    double m_origin = 0.0, m_from = 0.0, m_speed = 1.0, m_lastNow = 0.0;
    bool m_started = false, m_paused = false;
};

/// Every device of a log as replay devices.
std::vector<std::shared_ptr<ReplayDevice>> replayDevices(std::shared_ptr<const InputLog> log);

}  // namespace trainer
