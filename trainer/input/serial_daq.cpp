#include "trainer/input/serial_daq.h"

#include <QLocale>
#include <QSerialPort>
#include <QSerialPortInfo>

#include <algorithm>
#include <string_view>

namespace trainer {

namespace {

constexpr qint64 kReadBufferSize = 64 * 1024;  // Qt's buffer between polls [bytes]
constexpr int kMaxReadRounds = 16;             // zero-timeout waits per poll: bounds a poll under a flood
constexpr int kMaxIdentRequests = 4;           // "?" per connection: at open and three more
constexpr double kIdentRequestInterval = 1.0;  // [s]
constexpr int kMaxRateRequests = 3;            // "R" per connection or setSampleRate()

}  // namespace

QList<SerialDaq::PortEntry> SerialDaq::availablePorts()
{
    QList<PortEntry> ports;
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts())
        ports.append({info.portName(), info.systemLocation(), info.description(), info.manufacturer()});
    return ports;
}

QList<qint32> SerialDaq::standardBaudRates()
{
    return {9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600};
}

SerialDaq::SerialDaq(const QString& portName, qint32 baudRate)
    : m_portName(portName), m_baudRate(baudRate), m_port(std::make_unique<QSerialPort>())
{
    m_info.id = QStringLiteral("serial:") + portName;
    m_info.kind = DeviceKind::SerialDaq;
    m_info.name = tr("DAQ console on %1").arg(portName);
    m_info.namedByPadrob = true;
    m_port->setReadBufferSize(kReadBufferSize);
    // a port that fails while open is closed at once (a failed descriptor would keep
    // waking the event loop) and reported by the next poll()
    QObject::connect(m_port.get(), &QSerialPort::errorOccurred, m_port.get(),
                     [this](QSerialPort::SerialPortError error) {
                         if (error != QSerialPort::ResourceError && error != QSerialPort::ReadError
                             && error != QSerialPort::WriteError)
                             return;
                         if (m_closing || !m_port->isOpen())
                             return;  // closing can report errors of its own
                         m_lost = true;
                         // Qt's text for a read error is often a stale errno (a hung-up
                         // pty reads "Inappropriate ioctl for device"): ours instead
                         if (error == QSerialPort::ResourceError)
                             m_lostReason = tr("device removed: %1").arg(m_port->errorString());
                         else if (error == QSerialPort::ReadError)
                             m_lostReason = tr("read error or hang-up");
                         else
                             m_lostReason = tr("write error");
                         closePort();
                     });
    open();
}

SerialDaq::~SerialDaq()
{
    QObject::disconnect(m_port.get(), &QSerialPort::errorOccurred, nullptr, nullptr);
}

void SerialDaq::closePort()
{
    if (m_closing || !m_port->isOpen())
        return;
    m_closing = true;
    m_port->close();
    m_closing = false;
}

bool SerialDaq::isOpen() const
{
    return m_port->isOpen();
}

double SerialDaq::stallTimeout() const
{
    if (m_stallTimeoutOverride > 0.0)
        return m_stallTimeoutOverride;
    const auto& id = m_parser.identification();
    if (!id)
        return kMinStallTimeout;
    return std::clamp(kStallPeriods / double(id->rate), kMinStallTimeout, kMaxStallTimeout);
}

void SerialDaq::open()
{
    ++m_openAttempts;
    m_port->clearError();
    m_port->setPortName(m_portName);
    m_port->setBaudRate(m_baudRate);
    m_port->setDataBits(QSerialPort::Data8);
    m_port->setParity(QSerialPort::NoParity);
    m_port->setStopBits(QSerialPort::OneStop);
    m_port->setFlowControl(QSerialPort::NoFlowControl);
    if (!m_port->open(QIODevice::ReadWrite)) {
        const QString reason = m_port->errorString();
        if (m_everOpened) {
            m_status = DeviceStatus::Disconnected;
            m_statusText = tr("The console on %1 is disconnected (%2); trying again every second.")
                               .arg(m_portName, reason);
        } else {
            m_status = DeviceStatus::Failed;
            m_statusText = tr("Cannot open %1: %2. Trying again every second.").arg(m_portName, reason);
        }
        return;
    }
    m_everOpened = true;
    m_lost = false;
    m_retryAt.reset();
    m_parser.resetStream();
    m_status = DeviceStatus::Connected;
    m_statusText.clear();
    m_lastGoodAt.reset();
    m_identLinesAtOpen = m_parser.stats().identLines;
    m_identLinesSeen = m_identLinesAtOpen;
    m_identRequests = 0;
    m_rateRequests = 0;
    requestIdentification();
    if (m_wantedRate) {
        send(daq::rateCommand(*m_wantedRate));
        ++m_rateRequests;
    }
}

void SerialDaq::portLost(double now)
{
    m_lost = false;
    closePort();
    m_status = DeviceStatus::Disconnected;
    m_statusText = tr("The console on %1 was disconnected (%2); trying again every second.")
                       .arg(m_portName, m_lostReason);
    m_retryAt = now + kRetryInterval;
}

void SerialDaq::send(const std::string& bytes)
{
    if (!m_port->isOpen())
        return;
    m_port->write(bytes.data(), qint64(bytes.size()));
    // hands the bytes to the system without waiting (flush() would wait for the line)
    m_port->waitForBytesWritten(0);
}

void SerialDaq::requestIdentification()
{
    if (!m_port->isOpen())
        return;
    send(daq::identificationRequest());
    ++m_identRequests;
    m_identRequestAt.reset();  // the next poll() starts its clock
}

bool SerialDaq::setSampleRate(int hz)
{
    if (hz < daq::kMinRate || hz > daq::kMaxRate)
        return false;
    m_wantedRate = hz;
    m_rateRequests = 0;
    if (m_port->isOpen()) {
        send(daq::rateCommand(hz));
        ++m_rateRequests;
    }
    return true;
}

void SerialDaq::poll(double now)
{
    if (m_lost)
        portLost(now);
    if (!m_port->isOpen()) {
        if (!m_retryAt) {
            m_retryAt = now + kRetryInterval;
        } else if (now >= *m_retryAt) {
            m_retryAt = now + kRetryInterval;
            open();
        }
        if (!m_port->isOpen())
            return;
    }
    if (!m_lastGoodAt)
        m_lastGoodAt = now;  // the stall clock starts at the first poll after opening

    // what Qt has buffered, then what the system has, a bounded number of times
    if (m_port->bytesToWrite() > 0)
        m_port->waitForBytesWritten(0);
    std::size_t samples = 0;
    for (int round = 0; round < kMaxReadRounds && m_port->isOpen(); ++round) {
        qint64 n = 0;
        while (m_port->isOpen() && (n = m_port->read(m_chunk.data(), qint64(m_chunk.size()))) > 0)
            samples += m_parser.feed(std::string_view(m_chunk.data(), std::size_t(n)));
        if (!m_port->isOpen() || !m_port->waitForReadyRead(0))
            break;
    }
    updateInfo();
    if (samples > 0) {
        const daq::Sample& s = m_parser.latest();
        for (int i = 0; i < s.channels && std::size_t(i) < m_sample.axes.size(); ++i)
            m_sample.axes[std::size_t(i)] = s.values[std::size_t(i)];
        m_sample.time = now;
        m_sample.count += samples;
        m_lastGoodAt = now;
    }
    if (m_lost) {
        portLost(now);
        return;
    }
    updateRequests(now);

    const double silent = now - *m_lastGoodAt;
    if (silent > stallTimeout()) {
        m_status = DeviceStatus::Stalled;
        m_statusText = tr("No data from the console on %1 for %2 s.")
                           .arg(m_portName, QLocale().toString(silent, 'f', 1));
    } else {
        m_status = DeviceStatus::Connected;
        m_statusText.clear();
    }
}

void SerialDaq::updateRequests(double now)
{
    // "?" again while this connection has not identified (a board that resets on open
    // misses the first one)
    if (m_parser.stats().identLines == m_identLinesAtOpen && m_identRequests > 0
        && m_identRequests < kMaxIdentRequests) {
        if (!m_identRequestAt)
            m_identRequestAt = now;
        else if (now - *m_identRequestAt >= kIdentRequestInterval)
            requestIdentification();
    }
    // "R" again while the box reports another rate
    if (m_parser.stats().identLines != m_identLinesSeen) {
        m_identLinesSeen = m_parser.stats().identLines;
        const auto& id = m_parser.identification();
        if (m_wantedRate && id && id->rate != *m_wantedRate && m_rateRequests < kMaxRateRequests) {
            send(daq::rateCommand(*m_wantedRate));
            ++m_rateRequests;
        }
    }
}

void SerialDaq::updateInfo()
{
    // only an identification or the first good line can change it
    if (m_parser.channels() == m_infoChannels && m_parser.stats().identLines == m_infoIdentLines)
        return;
    m_infoChannels = m_parser.channels();
    m_infoIdentLines = m_parser.stats().identLines;

    const auto& id = m_parser.identification();
    const int channels = m_parser.channels();
    const int bits = id ? id->bits : 10;
    const QString name = id && !id->name.empty() ? QString::fromStdString(id->name)
                                                 : tr("DAQ console on %1").arg(m_portName);
    const double rawMax = double((1u << bits) - 1u);
    if (name == m_info.name && m_info.axes.size() == channels
        && (channels == 0 || m_info.axes.front().rawMax == rawMax))
        return;

    m_info.name = name;
    m_info.namedByPadrob = !(id && !id->name.empty());
    m_info.axes.clear();
    for (int i = 0; i < channels; ++i)
        m_info.axes.append({tr("Lever %1").arg(i + 1), 0.0, rawMax / 2.0, rawMax});
    m_sample.axes.assign(std::size_t(channels), rawMax / 2.0);
    ++m_infoVersion;
}

}  // namespace trainer
