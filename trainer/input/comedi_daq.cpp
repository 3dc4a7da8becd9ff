#include "trainer/input/comedi_daq.h"

#include <comedilib.h>

namespace trainer {

ComediDaq::ComediDaq(const QString& deviceFile) : m_file(deviceFile)
{
    m_info.id = QStringLiteral("comedi:") + deviceFile;
    m_info.kind = DeviceKind::Comedi;
    m_info.name = tr("Comedi card %1").arg(deviceFile);
    open();
}

ComediDaq::~ComediDaq()
{
    close();
}

void ComediDaq::close()
{
    if (m_device)
        comedi_close(m_device);
    m_device = nullptr;
    m_subdevice = -1;
}

void ComediDaq::open()
{
    ++m_openAttempts;
    comedi_t* device = comedi_open(m_file.toLocal8Bit().constData());
    if (!device) {
        m_status = DeviceStatus::Failed;
        m_statusText = tr("Cannot open the Comedi card %1: %2. The card's kernel driver must be loaded and "
                          "the device configured with comedi_config. Trying again every 2 s.")
                           .arg(m_file, QString::fromLocal8Bit(comedi_strerror(comedi_errno())));
        return;
    }
    const int subdevice = comedi_find_subdevice_by_type(device, COMEDI_SUBD_AI, 0);
    const int channels = subdevice < 0 ? 0 : comedi_get_n_channels(device, unsigned(subdevice));
    if (channels <= 0) {
        comedi_close(device);
        m_status = DeviceStatus::Failed;
        m_statusText = tr("The Comedi card %1 has no analog inputs. Trying again every 2 s.").arg(m_file);
        return;
    }
    m_device = device;
    m_subdevice = subdevice;

    // the axes, as the driver describes them
    DeviceInfo info = m_info;
    if (const char* board = comedi_get_board_name(device); board && *board)
        info.name = QString::fromLocal8Bit(board);
    info.axes.clear();
    m_channels.clear();
    for (int c = 0; c < channels; ++c) {
        const double maxdata = double(comedi_get_maxdata(device, unsigned(subdevice), unsigned(c)));
        info.axes.append({tr("AI %1").arg(c), 0.0, maxdata / 2.0, maxdata});
        m_channels.push_back(unsigned(c));
    }
    bool changed = info.name != m_info.name || info.axes.size() != m_info.axes.size();
    for (qsizetype i = 0; !changed && i < info.axes.size(); ++i)
        changed = info.axes[i].rawMax != m_info.axes[i].rawMax;
    if (changed) {
        m_info = std::move(info);
        m_sample.axes.resize(m_channels.size());
        for (std::size_t i = 0; i < m_channels.size(); ++i)
            m_sample.axes[i] = m_info.axes[qsizetype(i)].rawRest;
        ++m_infoVersion;
    }
    m_retryAt.reset();
    m_status = DeviceStatus::Connected;
    m_statusText.clear();
}

void ComediDaq::poll(double now)
{
    if (!m_device) {
        if (!m_retryAt) {
            m_retryAt = now + kRetryInterval;
        } else if (now >= *m_retryAt) {
            m_retryAt = now + kRetryInterval;
            open();
        }
        if (!m_device)
            return;
    }
    for (std::size_t i = 0; i < m_channels.size(); ++i) {
        lsampl_t value = 0;
        if (comedi_data_read(m_device, unsigned(m_subdevice), m_channels[i], 0, AREF_GROUND, &value) < 0) {
            ++m_failedReads;
            const QString reason = QString::fromLocal8Bit(comedi_strerror(comedi_errno()));
            close();
            m_status = DeviceStatus::Disconnected;
            m_statusText = tr("Reading the Comedi card %1 failed (%2); trying again every 2 s.").arg(m_file, reason);
            m_retryAt = now + kRetryInterval;
            return;
        }
        m_sample.axes[i] = double(value);
    }
    m_sample.time = now;
    ++m_sample.count;
    m_status = DeviceStatus::Connected;
    m_statusText.clear();
}

}  // namespace trainer
