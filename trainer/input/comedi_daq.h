#pragma once
// ComediDaq: a data-acquisition card driven by Comedi (Linux kernel driver plus
// comedilib), its analog inputs read as axes. Built only when comedilib is found
// (PADROB_HAVE_COMEDI).
//
// Identity: id "comedi:<device file>" (e.g. "comedi:/dev/comedi0"); name the board's
// name as the driver gives it, else "Comedi card <file>". Axes "AI 0"…"AI n−1" (the
// card's channel numbers) of the first analog-input subdevice, raw readings
// 0…maxdata (nominal rest at mid-range); no buttons. info() changes once the card
// opens (infoVersion() counts the changes).
//
// poll() reads every channel once with comedi_data_read (range 0, ground reference):
// a short synchronous conversion per channel, no waiting for data to arrive.
// Status: Connected while reads succeed; Failed when the file cannot be opened or
// has no analog input (the text says why, with the hint that the card's kernel driver
// must be loaded and configured with comedi_config); Disconnected when a read fails
// on an open card (closed). Either way poll() tries again every 2 s of station time.

#include "trainer/input/input_device.h"

#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

struct comedi_t_struct;  // comedilib's comedi_t, kept out of this header

namespace trainer {

class ComediDaq final : public InputDevice {
    Q_DECLARE_TR_FUNCTIONS(trainer::ComediDaq)

public:
    static constexpr double kRetryInterval = 2.0;  ///< [s] between attempts to open

    /// Opens the card now; a card that cannot be opened leaves the device Failed,
    /// retried from poll().
    explicit ComediDaq(const QString& deviceFile);
    ~ComediDaq() override;
    ComediDaq(const ComediDaq&) = delete;
    ComediDaq& operator=(const ComediDaq&) = delete;

    const DeviceInfo& info() const override { return m_info; }
    void poll(double now) override;
    const DeviceSample& sample() const override { return m_sample; }
    DeviceStatus status() const override { return m_status; }
    QString statusText() const override { return m_statusText; }
    /// Channel readings that failed on an open card.
    std::uint64_t droppedSamples() const override { return m_failedReads; }

    QString deviceFile() const { return m_file; }
    bool isOpen() const { return m_device != nullptr; }
    /// Raised each time info() changes (starts at 0).
    std::uint64_t infoVersion() const { return m_infoVersion; }
    /// Attempts to open the card so far (the constructor's included).
    std::uint64_t openAttempts() const { return m_openAttempts; }

private:
    void open();
    void close();

    QString m_file;
    comedi_t_struct* m_device = nullptr;
    int m_subdevice = -1;
    std::vector<unsigned> m_channels;  // channel numbers read, in axis order

    DeviceInfo m_info;
    std::uint64_t m_infoVersion = 0;
    DeviceSample m_sample;
    DeviceStatus m_status = DeviceStatus::Disconnected;
    QString m_statusText;
    std::uint64_t m_openAttempts = 0;
    std::uint64_t m_failedReads = 0;
    std::optional<double> m_retryAt;  // [s] next attempt (set by the first poll after a failure)
};

}  // namespace trainer
