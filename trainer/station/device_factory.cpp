#include "trainer/station/device_factory.h"

#include "trainer/input/serial_daq.h"
#ifdef PADROB_HAVE_COMEDI
#include "trainer/input/comedi_daq.h"
#endif

#include <QCoreApplication>

namespace trainer {

std::shared_ptr<InputDevice> openDevice(const DeviceSetting& setting, QString* why)
{
    if (setting.id.startsWith(QLatin1String("serial:"))) {
        const QString port = setting.id.mid(7);
        if (port.isEmpty()) {
            if (why) *why = QCoreApplication::translate("trainer::Station", "“serial:” needs a port name, e.g. serial:/dev/ttyACM0");
            return nullptr;
        }
        return std::make_shared<SerialDaq>(port, setting.baud);
    }
    if (setting.id.startsWith(QLatin1String("comedi:"))) {
#ifdef PADROB_HAVE_COMEDI
        return std::make_shared<ComediDaq>(setting.id.mid(7));
#else
        if (why)
            *why = QCoreApplication::translate("trainer::Station",
                                               "%1: this Padrob was built without Comedi (install libcomedi-dev "
                                               "and build again); the card is ignored")
                       .arg(setting.id);
        return nullptr;
#endif
    }
    if (why)
        *why = QCoreApplication::translate("trainer::Station", "%1: unknown kind of device; it is ignored").arg(setting.id);
    return nullptr;
}

}  // namespace trainer
