#include "trainer/input/sdl_joysticks.h"

#include <SDL.h>

#include <algorithm>
#include <array>
#include <utility>

namespace trainer {

/// How many times SDL has been pumped (SDL_PumpEvents or SDL_JoystickUpdate) by the
/// provider or its devices: a device pumps only when nobody has since its last read.
struct SdlJoysticks::Pump {
    std::uint64_t rounds = 0;
};

namespace {

constexpr double kAxisMin = SDL_JOYSTICK_AXIS_MIN;  // −32768
constexpr double kAxisMax = SDL_JOYSTICK_AXIS_MAX;  // 32767

QString guidString(SDL_JoystickGUID guid)
{
    std::array<char, 33> text{};  // 32 hex digits and the terminator
    SDL_JoystickGetGUIDString(guid, text.data(), int(text.size()));
    return QString::fromLatin1(text.data());
}

QString sdlError()
{
    return QString::fromUtf8(SDL_GetError());
}

}  // namespace

class SdlJoysticks::Device : public InputDevice {
    Q_DECLARE_TR_FUNCTIONS(trainer::SdlJoysticks)

public:
    Device(std::shared_ptr<Pump> pump, QString id, QString guid)
        : m_pump(std::move(pump)), m_guid(std::move(guid))
    {
        m_info.id = std::move(id);
    }
    ~Device() override { close(DeviceStatus::Disconnected, {}); }
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    const DeviceInfo& info() const override { return m_info; }
    const DeviceSample& sample() const override { return m_sample; }
    DeviceStatus status() const override { return m_status; }
    QString statusText() const override { return m_statusText; }

    void poll(double now) override
    {
        if (!m_joystick) return;
        // pump SDL unless the provider or another device did since our last read
        if (m_pump->rounds == m_round) {
            SDL_JoystickUpdate();
            ++m_pump->rounds;
        }
        m_round = m_pump->rounds;
        if (!checkAttached()) return;

        if (m_pad) {
            for (int a = 0; a < SDL_CONTROLLER_AXIS_MAX; ++a)
                m_sample.axes[std::size_t(a)] =
                    SDL_GameControllerGetAxis(m_pad, SDL_GameControllerAxis(a));
            for (int b = 0; b < SDL_CONTROLLER_BUTTON_MAX; ++b)
                m_sample.buttons[std::size_t(b)] =
                    SDL_GameControllerGetButton(m_pad, SDL_GameControllerButton(b)) ? 1 : 0;
        } else {
            for (int a = 0; a < m_axes; ++a)
                m_sample.axes[std::size_t(a)] = SDL_JoystickGetAxis(m_joystick, a);
            for (int b = 0; b < m_buttons; ++b)
                m_sample.buttons[std::size_t(b)] = SDL_JoystickGetButton(m_joystick, b) ? 1 : 0;
            // each hat: four buttons up, right, down, left after the real buttons
            static constexpr std::array<Uint8, 4> kHatBits{SDL_HAT_UP, SDL_HAT_RIGHT, SDL_HAT_DOWN,
                                                           SDL_HAT_LEFT};
            for (int h = 0; h < m_hats; ++h) {
                const Uint8 hat = SDL_JoystickGetHat(m_joystick, h);
                for (std::size_t k = 0; k < kHatBits.size(); ++k)
                    m_sample.buttons[std::size_t(m_buttons + 4 * h) + k] = (hat & kHatBits[k]) ? 1 : 0;
            }
        }
        m_sample.time = now;
        ++m_sample.count;
    }

    const QString& guid() const { return m_guid; }
    /// SDL's instance id while the device is open (or failed to open); −1 otherwise.
    SDL_JoystickID instanceId() const { return m_instance; }

    /// Opens SDL's device `deviceIndex` and reads its layout: Connected, or Failed
    /// with SDL's reason. Used when it is found and when it comes back.
    void open(int deviceIndex)
    {
        close(DeviceStatus::Disconnected, {});
        m_instance = SDL_JoystickGetDeviceInstanceID(deviceIndex);
        m_round = m_pump->rounds;
        if (SDL_IsGameController(deviceIndex)) {
            m_pad = SDL_GameControllerOpen(deviceIndex);
            if (m_pad) m_joystick = SDL_GameControllerGetJoystick(m_pad);
        }
        if (!m_joystick) m_joystick = SDL_JoystickOpen(deviceIndex);  // a plain joystick (or a pad SDL failed to map)
        if (!m_joystick) {
            const QString why = sdlError();
            if (const char* name = SDL_JoystickNameForIndex(deviceIndex)) m_info.name = QString::fromUtf8(name);
            m_status = DeviceStatus::Failed;
            m_statusText = tr("SDL cannot open it: %1").arg(why);
            return;
        }
        readLayout();
        m_status = DeviceStatus::Connected;
        if (m_info.axes.isEmpty() && m_info.buttons.isEmpty())
            m_statusText = tr("It has neither axes nor buttons, so it cannot drive a valve.");
        else if (m_info.axes.isEmpty())
            m_statusText = tr("It has no axes, so it cannot drive a valve (its buttons can still be used).");
        else
            m_statusText.clear();
    }

    /// Closes SDL's handle (if open), keeping the last readings; `status` and `text`
    /// say why.
    void close(DeviceStatus status, QString text)
    {
        if (m_pad)
            SDL_GameControllerClose(m_pad);  // closes its joystick too
        else if (m_joystick)
            SDL_JoystickClose(m_joystick);
        m_pad = nullptr;
        m_joystick = nullptr;
        m_instance = -1;
        m_status = status;
        m_statusText = std::move(text);
    }

    /// False, after closing the device as unplugged, when SDL says it is gone.
    bool checkAttached()
    {
        if (!m_joystick) return false;
        if (SDL_JoystickGetAttached(m_joystick)) return true;
        close(DeviceStatus::Disconnected, unpluggedText());
        return false;
    }

    static QString unpluggedText() { return tr("Unplugged; waiting for it to come back"); }

private:
    void readLayout()
    {
        m_info.axes.clear();
        m_info.buttons.clear();
        if (m_pad) {
            const char* name = SDL_GameControllerName(m_pad);
            m_info.name = name ? QString::fromUtf8(name) : tr("Unnamed gamepad");
            m_info.kind = DeviceKind::Gamepad;
            for (int a = 0; a < SDL_CONTROLLER_AXIS_MAX; ++a) {
                const bool trigger =
                    a == SDL_CONTROLLER_AXIS_TRIGGERLEFT || a == SDL_CONTROLLER_AXIS_TRIGGERRIGHT;
                m_info.axes.append({QString::fromLatin1(SDL_GameControllerGetStringForAxis(
                                        SDL_GameControllerAxis(a))),
                                    trigger ? 0.0 : kAxisMin, 0.0, kAxisMax});
            }
            for (int b = 0; b < SDL_CONTROLLER_BUTTON_MAX; ++b)
                m_info.buttons.append(QString::fromLatin1(
                    SDL_GameControllerGetStringForButton(SDL_GameControllerButton(b))));
            m_axes = SDL_CONTROLLER_AXIS_MAX;
            m_buttons = SDL_CONTROLLER_BUTTON_MAX;
            m_hats = 0;
        } else {
            const char* name = SDL_JoystickName(m_joystick);
            m_info.name = name ? QString::fromUtf8(name) : tr("Unnamed joystick");
            m_info.kind = DeviceKind::Joystick;
            m_axes = std::max(0, SDL_JoystickNumAxes(m_joystick));
            m_buttons = std::max(0, SDL_JoystickNumButtons(m_joystick));
            m_hats = std::max(0, SDL_JoystickNumHats(m_joystick));
            for (int a = 0; a < m_axes; ++a)
                m_info.axes.append({tr("Axis %1").arg(a + 1), kAxisMin, 0.0, kAxisMax});
            for (int b = 0; b < m_buttons; ++b)
                m_info.buttons.append(tr("Button %1").arg(b + 1));
            for (int h = 0; h < m_hats; ++h) {
                m_info.buttons.append(tr("Hat %1 up").arg(h + 1));
                m_info.buttons.append(tr("Hat %1 right").arg(h + 1));
                m_info.buttons.append(tr("Hat %1 down").arg(h + 1));
                m_info.buttons.append(tr("Hat %1 left").arg(h + 1));
            }
        }
        // the last readings stay until the next poll (a returning device normally
        // has the same layout)
        m_sample.axes.resize(std::size_t(m_info.axes.size()), 0.0);
        m_sample.buttons.resize(std::size_t(m_info.buttons.size()), 0);
    }

    std::shared_ptr<Pump> m_pump;
    std::uint64_t m_round = 0;              ///< m_pump->rounds at our last read
    QString m_guid;                         ///< SDL's GUID string, as found
    DeviceInfo m_info;
    DeviceSample m_sample;
    DeviceStatus m_status = DeviceStatus::Disconnected;
    QString m_statusText;
    SDL_GameController* m_pad = nullptr;    ///< set for a gamepad
    SDL_Joystick* m_joystick = nullptr;     ///< the pad's joystick, or the plain joystick
    SDL_JoystickID m_instance = -1;
    int m_axes = 0;                         ///< counts as read from SDL at open
    int m_buttons = 0;
    int m_hats = 0;
};

SdlJoysticks::SdlJoysticks() : m_pump(std::make_shared<Pump>())
{
    SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    if (SDL_InitSubSystem(SDL_INIT_JOYSTICK | SDL_INIT_GAMECONTROLLER) != 0) {
        m_problem = tr("Joysticks and gamepads cannot be used: SDL did not start (%1).").arg(sdlError());
        return;
    }
    m_started = true;
}

SdlJoysticks::~SdlJoysticks()
{
    for (const auto& device : m_devices)
        device->close(DeviceStatus::Disconnected, tr("Closed: the joystick back end was stopped"));
    if (m_started) SDL_QuitSubSystem(SDL_INIT_JOYSTICK | SDL_INIT_GAMECONTROLLER);
}

std::vector<std::shared_ptr<InputDevice>> SdlJoysticks::poll(double /*now*/)
{
    std::vector<std::shared_ptr<InputDevice>> found;
    if (!m_started) return found;

    // one pump, then drain the queue without pumping again (SDL_PollEvent would
    // pump on every call); only plug and unplug matter
    SDL_PumpEvents();
    ++m_pump->rounds;
    std::array<SDL_Event, 64> events;
    for (;;) {
        const int n = SDL_PeepEvents(events.data(), int(events.size()), SDL_GETEVENT, SDL_FIRSTEVENT,
                                     SDL_LASTEVENT);
        for (int i = 0; i < n; ++i) {
            if (events[std::size_t(i)].type == SDL_JOYDEVICEADDED)
                m_scanNeeded = true;  // its device index may be stale by now: rescan
            else if (events[std::size_t(i)].type == SDL_JOYDEVICEREMOVED)
                detach(events[std::size_t(i)].jdevice.which);
        }
        if (n < int(events.size())) break;
    }

    // a device SDL has let go of, whatever happened to its event
    for (const auto& device : m_devices) device->checkAttached();

    if (m_scanNeeded) {
        m_scanNeeded = false;
        const int count = SDL_NumJoysticks();
        for (int index = 0; index < count; ++index) {
            const SDL_JoystickID instance = SDL_JoystickGetDeviceInstanceID(index);
            if (instance < 0) continue;
            const bool known = std::any_of(m_devices.begin(), m_devices.end(),
                                           [&](const auto& d) { return d->instanceId() == instance; });
            if (!known) attach(index, found);
        }
    }
    return found;
}

void SdlJoysticks::attach(int deviceIndex, std::vector<std::shared_ptr<InputDevice>>& found)
{
    const QString guid = guidString(SDL_JoystickGetDeviceGUID(deviceIndex));

    // a device coming back: the first disconnected one with its GUID
    for (const auto& device : m_devices) {
        if (device->guid() == guid && device->status() == DeviceStatus::Disconnected) {
            device->open(deviceIndex);
            return;
        }
    }

    const auto twins = std::count_if(m_devices.begin(), m_devices.end(),
                                     [&](const auto& d) { return d->guid() == guid; });
    QString id = QStringLiteral("sdl:") + guid;
    if (twins > 0) id += QStringLiteral("#%1").arg(twins + 1);
    auto device = std::make_shared<Device>(m_pump, id, guid);
    device->open(deviceIndex);
    m_devices.push_back(device);
    found.push_back(device);
}

void SdlJoysticks::detach(std::int32_t instanceId)
{
    for (const auto& device : m_devices) {
        if (device->instanceId() == instanceId) {
            device->close(DeviceStatus::Disconnected, Device::unpluggedText());
            return;
        }
    }
}

QString SdlJoysticks::problem() const
{
    return m_problem;
}

std::vector<std::shared_ptr<InputDevice>> SdlJoysticks::devices() const
{
    return {m_devices.begin(), m_devices.end()};
}

}  // namespace trainer
