#pragma once
// SerialDaq: the replica console (valve levers on potentiometers, a microcontroller
// streaming the Padrob DAQ protocol over USB serial: docs/daq-protocol.md) as an
// InputDevice.
//
// Identity: id "serial:<port name>" with the port name exactly as given (use the same
// spelling every time, e.g. "/dev/ttyACM0" or a /dev/serial/by-id/… link); name from
// the identification line, else "DAQ console on <port>". Axes "Lever 1"…"Lever N",
// raw ADC readings, nominal range 0 / (2^bits − 1)/2 / 2^bits − 1 (bits from the
// identification, 10 before it); no buttons.
//
// info() changes when the channel count becomes known (the identification line, or
// before one the first good sample line), and again if the box identifies itself
// differently (another name, channel count or resolution, e.g. after a re-plug):
// each change raises infoVersion(), so an owner that caches the axes compares it
// after poll(). Until then info() has no axes and sample() no values.
//
// Threads: created, polled and destroyed in one thread. That thread needs no event
// loop: poll() reads with zero-timeout waits (QSerialPort::waitForReadyRead(0)); if it
// has one, Qt also fills the port's buffer between polls (bounded to 64 KiB).
//
// Status:
// - Connected: the port is open and a good sample came within the stall timeout.
// - Stalled: the port is open but no good sample for longer than stallTimeout()
//   (the text says for how long); the next good line brings it back.
// - Failed: the port could not be opened (the text has the port and the system's
//   reason); poll() tries again every second of station time.
// - Disconnected: the port went away while open (USB unplugged, read error, hang-up):
//   it is closed and poll() tries to reopen it every second, until it is back.
// The host sends "?" after every open (again every second, up to three more times,
// until an identification comes: a Nano resets when the port opens and misses the
// first one) and, after setSampleRate(), "R<hz>" until the box reports that rate.

#include "trainer/input/daq_protocol.h"
#include "trainer/input/input_device.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

QT_BEGIN_NAMESPACE
class QSerialPort;
QT_END_NAMESPACE

namespace trainer {

class SerialDaq final : public InputDevice {
    Q_DECLARE_TR_FUNCTIONS(trainer::SerialDaq)

public:
    static constexpr qint32 kDefaultBaudRate = 115200;
    static constexpr double kRetryInterval = 1.0;        ///< [s] between attempts to (re)open
    static constexpr double kMinStallTimeout = 0.25;     ///< [s]
    /// [s] The longest a silent box keeps its valves: whatever rate it claims (a box
    /// that says 1 Hz and freezes with a lever held must not hold that valve open 20 s).
    static constexpr double kMaxStallTimeout = 0.3;
    static constexpr int kStallPeriods = 20;             ///< sample periods before Stalled

    /// A serial port of this computer, for a port chooser. Pseudo-terminals and
    /// links are not listed: the UI should let a person type a path too.
    struct PortEntry {
        QString name;            ///< what to pass to the constructor, e.g. "ttyACM0"
        QString systemLocation;  ///< e.g. "/dev/ttyACM0" (also accepted by the constructor)
        QString description;     ///< e.g. "USB2.0-Serial", may be empty
        QString manufacturer;    ///< may be empty
    };
    static QList<PortEntry> availablePorts();
    /// 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600.
    static QList<qint32> standardBaudRates();

    /// Opens the port now (8N1, no flow control) and sends "?"; a port that cannot be
    /// opened leaves the device Failed, retried from poll().
    explicit SerialDaq(const QString& portName, qint32 baudRate = kDefaultBaudRate);
    ~SerialDaq() override;
    SerialDaq(const SerialDaq&) = delete;
    SerialDaq& operator=(const SerialDaq&) = delete;

    const DeviceInfo& info() const override { return m_info; }
    /// Reads what the port has (never blocks), feeds the parser, updates sample(),
    /// status and info; reopens a lost port when its retry is due.
    void poll(double now) override;
    /// The newest good sample: raw readings, time = the poll() that received it,
    /// count = good sample lines received so far.
    const DeviceSample& sample() const override { return m_sample; }
    DeviceStatus status() const override { return m_status; }
    QString statusText() const override { return m_statusText; }
    /// Lines dropped as corrupt (checksum, syntax, channel count, too long).
    std::uint64_t droppedSamples() const override { return m_parser.stats().droppedLines(); }

    /// Raised each time info() changes (starts at 0).
    std::uint64_t infoVersion() const { return m_infoVersion; }
    /// The parser's counters: good lines, dropped by reason, garbage, lost samples.
    const daq::Stats& stats() const { return m_parser.stats(); }
    /// The box's newest identification line, if one came.
    const std::optional<daq::Identification>& identification() const { return m_parser.identification(); }

    QString portName() const { return m_portName; }
    qint32 baudRate() const { return m_baudRate; }
    bool isOpen() const;
    /// Attempts to open the port so far (the constructor's included).
    std::uint64_t openAttempts() const { return m_openAttempts; }

    /// [s] How long without a good sample before Stalled: the value set, or by default
    /// 20 periods at the identification's rate, within 0.25…0.3 s (kMaxStallTimeout).
    double stallTimeout() const;
    /// seconds ≤ 0 returns to the default; a value set is not capped (tests).
    void setStallTimeout(double seconds) { m_stallTimeoutOverride = seconds; }

    /// Asks the box for rate `hz` (1…1000) now if the port is open, and again after
    /// every reopen, until an identification reports it (three tries each time).
    /// False, and nothing sent, when hz is out of range.
    bool setSampleRate(int hz);
    /// Sends "?" now (the identification comes back through poll()).
    void requestIdentification();

private:
    void open();
    void closePort();
    void portLost(double now);
    void send(const std::string& bytes);
    void updateInfo();
    void updateRequests(double now);

    QString m_portName;
    qint32 m_baudRate;
    std::unique_ptr<QSerialPort> m_port;
    daq::Parser m_parser;
    std::array<char, 4096> m_chunk{};

    DeviceInfo m_info;
    std::uint64_t m_infoVersion = 0;
    int m_infoChannels = 0;                 // the parser's channels and identifications
    std::uint64_t m_infoIdentLines = 0;     // when m_info was last checked
    DeviceSample m_sample;
    DeviceStatus m_status = DeviceStatus::Disconnected;
    QString m_statusText;

    bool m_everOpened = false;
    bool m_closing = false;                 // inside closePort(): errors it raises are ignored
    bool m_lost = false;                    // the port failed while open: set by its error signal
    QString m_lostReason;
    std::uint64_t m_openAttempts = 0;
    std::optional<double> m_retryAt;        // [s] next open attempt (set by the first poll after a failure)
    std::optional<double> m_lastGoodAt;     // [s] newest good sample, or the first poll after opening

    std::uint64_t m_identLinesAtOpen = 0;   // to tell whether this connection has identified
    std::uint64_t m_identLinesSeen = 0;     // identification lines handled by updateRequests
    int m_identRequests = 0;                // "?" sent since open
    std::optional<double> m_identRequestAt; // [s] the last "?" (set at the first poll after sending)
    std::optional<int> m_wantedRate;
    int m_rateRequests = 0;                 // "R" sent since open or setSampleRate

    double m_stallTimeoutOverride = 0.0;
};

}  // namespace trainer
