// SdlJoysticks on SDL's virtual joysticks: no hardware. Each test starts its own
// SdlJoysticks (which starts SDL's joystick subsystem, needed before a virtual
// device can be attached) and SDL drops the virtual devices when it stops.
#include "trainer/input/sdl_joysticks.h"

#include <SDL.h>

#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <vector>

using trainer::DeviceKind;
using trainer::DeviceStatus;
using trainer::InputDevice;
using trainer::SdlJoysticks;

namespace {

using Devices = std::vector<std::shared_ptr<InputDevice>>;

/// Attaches a virtual device named `name` (the name goes into SDL's GUID); returns
/// its device index.
int attachVirtual(const char* name, SDL_JoystickType type, int axes, int buttons, int hats)
{
    SDL_VirtualJoystickDesc desc{};
    desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
    desc.type = Uint16(type);
    desc.naxes = Uint16(axes);
    desc.nbuttons = Uint16(buttons);
    desc.nhats = Uint16(hats);
    desc.name = name;
    const int index = SDL_JoystickAttachVirtualEx(&desc);
    EXPECT_GE(index, 0) << SDL_GetError();
    return index;
}

int attachPad(const char* name)
{
    return attachVirtual(name, SDL_JOYSTICK_TYPE_GAMECONTROLLER, SDL_CONTROLLER_AXIS_MAX, 15, 0);
}

QString guidOf(int deviceIndex)
{
    std::array<char, 33> text{};
    SDL_JoystickGetGUIDString(SDL_JoystickGetDeviceGUID(deviceIndex), text.data(), int(text.size()));
    return QString::fromLatin1(text.data());
}

/// The device index of the virtual device with SDL instance `instance`, or −1.
int indexOf(SDL_JoystickID instance)
{
    for (int i = 0; i < SDL_NumJoysticks(); ++i)
        if (SDL_JoystickGetDeviceInstanceID(i) == instance) return i;
    return -1;
}

/// Polls the provider a few times (SDL may need a pump or two) until it has found
/// `count` new devices in all; returns them.
Devices pollUntilFound(SdlJoysticks& sdl, std::size_t count, double now = 0.0)
{
    Devices found;
    for (int i = 0; i < 10 && found.size() < count; ++i) {
        Devices more = sdl.poll(now);
        found.insert(found.end(), more.begin(), more.end());
    }
    return found;
}

/// The provider, then the device, as the station's input thread does.
void pollBoth(SdlJoysticks& sdl, InputDevice& device, double now)
{
    EXPECT_TRUE(sdl.poll(now).empty());
    device.poll(now);
}

/// The test's own handle on a virtual device, to set its values (SDL shares the
/// device with the provider's handle).
struct Handle {
    explicit Handle(int deviceIndex) : joystick(SDL_JoystickOpen(deviceIndex)) {}
    ~Handle() { if (joystick) SDL_JoystickClose(joystick); }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    SDL_Joystick* joystick;
};

}  // namespace

TEST(SdlJoysticks, StartsAndFindsNothingWithoutDevices)
{
    SdlJoysticks sdl;
    EXPECT_TRUE(sdl.problem().isEmpty()) << sdl.problem().toStdString();
    EXPECT_TRUE(sdl.poll(0.0).empty());
    EXPECT_TRUE(sdl.poll(0.01).empty());
    EXPECT_TRUE(sdl.devices().empty());
}

TEST(SdlJoysticks, VirtualGamepadIsFoundWithTheStandardLayout)
{
    SdlJoysticks sdl;
    ASSERT_TRUE(sdl.problem().isEmpty()) << sdl.problem().toStdString();
    const int index = attachPad("Padrob test pad");
    ASSERT_TRUE(SDL_IsGameController(index));  // SDL maps a virtual gamepad by itself
    const QString guid = guidOf(index);

    const Devices found = pollUntilFound(sdl, 1);
    ASSERT_EQ(found.size(), 1u);
    const InputDevice& pad = *found[0];
    EXPECT_EQ(pad.status(), DeviceStatus::Connected);
    EXPECT_TRUE(pad.statusText().isEmpty());
    EXPECT_EQ(pad.info().kind, DeviceKind::Gamepad);
    EXPECT_EQ(pad.info().name, "Padrob test pad");
    EXPECT_EQ(pad.info().id, "sdl:" + guid);
    EXPECT_EQ(guid.size(), 32);

    const QStringList axes{"leftx", "lefty", "rightx", "righty", "lefttrigger", "righttrigger"};
    ASSERT_EQ(pad.info().axes.size(), axes.size());
    for (qsizetype a = 0; a < axes.size(); ++a) {
        const bool trigger = a >= 4;
        EXPECT_EQ(pad.info().axes[a].name, axes[a]);
        EXPECT_EQ(pad.info().axes[a].rawMin, trigger ? 0.0 : -32768.0) << a;
        EXPECT_EQ(pad.info().axes[a].rawRest, 0.0) << a;
        EXPECT_EQ(pad.info().axes[a].rawMax, 32767.0) << a;
    }
    const QStringList first{"a", "b", "x", "y", "back", "guide", "start", "leftstick",
                            "rightstick", "leftshoulder", "rightshoulder", "dpup", "dpdown",
                            "dpleft", "dpright"};
    ASSERT_EQ(pad.info().buttons.size(), SDL_CONTROLLER_BUTTON_MAX);
    EXPECT_EQ(pad.info().buttons.mid(0, first.size()), first);
    EXPECT_EQ(pad.sample().axes.size(), 6u);
    EXPECT_EQ(pad.sample().buttons.size(), std::size_t(SDL_CONTROLLER_BUTTON_MAX));
    EXPECT_EQ(pad.sample().count, 0u);

    // found once; the provider keeps its share
    EXPECT_TRUE(sdl.poll(0.0).empty());
    ASSERT_EQ(sdl.devices().size(), 1u);
    EXPECT_EQ(sdl.devices()[0], found[0]);
}

TEST(SdlJoysticks, GamepadAxisAndButtonValuesArrive)
{
    SdlJoysticks sdl;
    const int index = attachPad("Padrob test pad values");
    Handle handle(index);
    ASSERT_NE(handle.joystick, nullptr) << SDL_GetError();
    const Devices found = pollUntilFound(sdl, 1);
    ASSERT_EQ(found.size(), 1u);
    InputDevice& pad = *found[0];

    // at rest: sticks and triggers 0, nothing pressed
    pollBoth(sdl, pad, 1.0);
    EXPECT_EQ(pad.sample().time, 1.0);
    EXPECT_EQ(pad.sample().count, 1u);
    for (double v : pad.sample().axes) EXPECT_EQ(v, 0.0);
    for (auto b : pad.sample().buttons) EXPECT_EQ(b, 0);

    ASSERT_EQ(SDL_JoystickSetVirtualAxis(handle.joystick, SDL_CONTROLLER_AXIS_LEFTX, 20000), 0);
    ASSERT_EQ(SDL_JoystickSetVirtualAxis(handle.joystick, SDL_CONTROLLER_AXIS_RIGHTY, -12000), 0);
    ASSERT_EQ(SDL_JoystickSetVirtualAxis(handle.joystick, SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 32767), 0);
    ASSERT_EQ(SDL_JoystickSetVirtualButton(handle.joystick, SDL_CONTROLLER_BUTTON_A, SDL_PRESSED), 0);
    ASSERT_EQ(SDL_JoystickSetVirtualButton(handle.joystick, SDL_CONTROLLER_BUTTON_DPAD_UP, SDL_PRESSED), 0);
    pollBoth(sdl, pad, 1.01);
    EXPECT_EQ(pad.sample().time, 1.01);
    EXPECT_EQ(pad.sample().count, 2u);
    const std::vector<double> axes{20000, 0, 0, -12000, 0, 32767};
    EXPECT_EQ(pad.sample().axes, axes);
    for (std::size_t b = 0; b < pad.sample().buttons.size(); ++b)
        EXPECT_EQ(pad.sample().buttons[b],
                  int(b) == SDL_CONTROLLER_BUTTON_A || int(b) == SDL_CONTROLLER_BUTTON_DPAD_UP ? 1 : 0)
            << pad.info().buttons[qsizetype(b)].toStdString();

    // a device polled without the provider pumps SDL itself: no stale readings
    ASSERT_EQ(SDL_JoystickSetVirtualAxis(handle.joystick, SDL_CONTROLLER_AXIS_LEFTX, -20000), 0);
    ASSERT_EQ(SDL_JoystickSetVirtualButton(handle.joystick, SDL_CONTROLLER_BUTTON_A, SDL_RELEASED), 0);
    pad.poll(1.02);
    EXPECT_EQ(pad.sample().axes[0], -20000.0);
    EXPECT_EQ(pad.sample().buttons[SDL_CONTROLLER_BUTTON_A], 0);
    EXPECT_EQ(pad.sample().count, 3u);
}

TEST(SdlJoysticks, PlainJoystickHasNumberedAxesButtonsAndHatsAsButtons)
{
    SdlJoysticks sdl;
    const int index = attachVirtual("Padrob test stick", SDL_JOYSTICK_TYPE_UNKNOWN, 3, 4, 1);
    ASSERT_FALSE(SDL_IsGameController(index));
    const QString guid = guidOf(index);
    Handle handle(index);
    ASSERT_NE(handle.joystick, nullptr) << SDL_GetError();
    const Devices found = pollUntilFound(sdl, 1);
    ASSERT_EQ(found.size(), 1u);
    InputDevice& stick = *found[0];

    EXPECT_EQ(stick.status(), DeviceStatus::Connected);
    EXPECT_TRUE(stick.statusText().isEmpty());
    EXPECT_EQ(stick.info().kind, DeviceKind::Joystick);
    EXPECT_EQ(stick.info().name, "Padrob test stick");
    EXPECT_EQ(stick.info().id, "sdl:" + guid);
    ASSERT_EQ(stick.info().axes.size(), 3);
    for (qsizetype a = 0; a < 3; ++a) {
        EXPECT_EQ(stick.info().axes[a].name, QString("Axis %1").arg(a + 1));
        EXPECT_EQ(stick.info().axes[a].rawMin, -32768.0);
        EXPECT_EQ(stick.info().axes[a].rawRest, 0.0);
        EXPECT_EQ(stick.info().axes[a].rawMax, 32767.0);
    }
    const QStringList buttons{"Button 1", "Button 2", "Button 3", "Button 4",
                              "Hat 1 up", "Hat 1 right", "Hat 1 down", "Hat 1 left"};
    EXPECT_EQ(stick.info().buttons, buttons);

    ASSERT_EQ(SDL_JoystickSetVirtualAxis(handle.joystick, 2, -12345), 0);
    ASSERT_EQ(SDL_JoystickSetVirtualButton(handle.joystick, 3, SDL_PRESSED), 0);
    ASSERT_EQ(SDL_JoystickSetVirtualHat(handle.joystick, 0, SDL_HAT_RIGHTUP), 0);
    pollBoth(sdl, stick, 0.5);
    EXPECT_EQ(stick.sample().axes, (std::vector<double>{0, 0, -12345}));
    EXPECT_EQ(stick.sample().buttons, (std::vector<std::uint8_t>{0, 0, 0, 1, 1, 1, 0, 0}));

    ASSERT_EQ(SDL_JoystickSetVirtualHat(handle.joystick, 0, SDL_HAT_LEFTDOWN), 0);
    pollBoth(sdl, stick, 0.51);
    EXPECT_EQ(stick.sample().buttons, (std::vector<std::uint8_t>{0, 0, 0, 1, 0, 0, 1, 1}));
    EXPECT_EQ(stick.sample().count, 2u);
}

TEST(SdlJoysticks, UnpluggedDeviceComesBackAsTheSameObject)
{
    SdlJoysticks sdl;
    int index = attachPad("Padrob test pad replug");
    const QString guid = guidOf(index);
    const SDL_JoystickID firstInstance = SDL_JoystickGetDeviceInstanceID(index);
    std::shared_ptr<InputDevice> pad;
    {
        Handle handle(index);
        const Devices found = pollUntilFound(sdl, 1);
        ASSERT_EQ(found.size(), 1u);
        pad = found[0];
        ASSERT_EQ(SDL_JoystickSetVirtualAxis(handle.joystick, SDL_CONTROLLER_AXIS_LEFTY, 20000), 0);
        ASSERT_EQ(SDL_JoystickSetVirtualButton(handle.joystick, SDL_CONTROLLER_BUTTON_B, SDL_PRESSED), 0);
        pollBoth(sdl, *pad, 2.0);
        EXPECT_EQ(pad->sample().axes[1], 20000.0);
        EXPECT_EQ(pad->sample().buttons[SDL_CONTROLLER_BUTTON_B], 1);

        // unplug (while the test still holds its own handle)
        ASSERT_EQ(SDL_JoystickDetachVirtual(indexOf(firstInstance)), 0);
    }
    EXPECT_TRUE(sdl.poll(2.1).empty());
    pad->poll(2.1);
    EXPECT_EQ(pad->status(), DeviceStatus::Disconnected);
    EXPECT_EQ(pad->statusText(), "Unplugged; waiting for it to come back");
    EXPECT_EQ(pad->sample().axes[1], 20000.0);  // the last values stay
    EXPECT_EQ(pad->sample().buttons[SDL_CONTROLLER_BUTTON_B], 1);
    EXPECT_EQ(pad->sample().time, 2.0);
    EXPECT_EQ(pad->sample().count, 1u);
    pad->poll(2.2);
    EXPECT_EQ(pad->sample().count, 1u);

    // plugged again: the same object, the same id, Connected, fresh readings
    index = attachPad("Padrob test pad replug");
    EXPECT_EQ(guidOf(index), guid);
    EXPECT_NE(SDL_JoystickGetDeviceInstanceID(index), firstInstance);  // SDL: a new instance
    Handle handle(index);
    ASSERT_EQ(SDL_JoystickSetVirtualAxis(handle.joystick, SDL_CONTROLLER_AXIS_LEFTY, -7000), 0);
    EXPECT_TRUE(pollUntilFound(sdl, 1, 3.0).empty());
    ASSERT_EQ(sdl.devices().size(), 1u);
    EXPECT_EQ(sdl.devices()[0], pad);
    EXPECT_EQ(pad->status(), DeviceStatus::Connected);
    EXPECT_TRUE(pad->statusText().isEmpty());
    EXPECT_EQ(pad->info().id, "sdl:" + guid);
    pollBoth(sdl, *pad, 3.0);
    EXPECT_EQ(pad->sample().axes[1], -7000.0);
    EXPECT_EQ(pad->sample().buttons[SDL_CONTROLLER_BUTTON_B], 0);
    EXPECT_EQ(pad->sample().time, 3.0);
    EXPECT_EQ(pad->sample().count, 2u);
}

TEST(SdlJoysticks, IdenticalDevicesAreNumberedAndComeBackInOrder)
{
    SdlJoysticks sdl;
    const int first = attachVirtual("Padrob twin stick", SDL_JOYSTICK_TYPE_UNKNOWN, 2, 2, 0);
    const int second = attachVirtual("Padrob twin stick", SDL_JOYSTICK_TYPE_UNKNOWN, 2, 2, 0);
    const QString guid = guidOf(first);
    ASSERT_EQ(guidOf(second), guid);  // SDL: identical devices, identical GUIDs
    const SDL_JoystickID firstInstance = SDL_JoystickGetDeviceInstanceID(first);
    const SDL_JoystickID secondInstance = SDL_JoystickGetDeviceInstanceID(second);

    const Devices found = pollUntilFound(sdl, 2);
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0]->info().id, "sdl:" + guid);
    EXPECT_EQ(found[1]->info().id, "sdl:" + guid + "#2");

    // both unplugged, one comes back: it is the first of the two
    ASSERT_EQ(SDL_JoystickDetachVirtual(indexOf(secondInstance)), 0);
    ASSERT_EQ(SDL_JoystickDetachVirtual(indexOf(firstInstance)), 0);
    EXPECT_TRUE(sdl.poll(1.0).empty());
    EXPECT_EQ(found[0]->status(), DeviceStatus::Disconnected);
    EXPECT_EQ(found[1]->status(), DeviceStatus::Disconnected);
    attachVirtual("Padrob twin stick", SDL_JOYSTICK_TYPE_UNKNOWN, 2, 2, 0);
    EXPECT_TRUE(sdl.poll(1.1).empty());
    EXPECT_EQ(found[0]->status(), DeviceStatus::Connected);
    EXPECT_EQ(found[1]->status(), DeviceStatus::Disconnected);

    // a third identical one while the second is away takes the second's place
    attachVirtual("Padrob twin stick", SDL_JOYSTICK_TYPE_UNKNOWN, 2, 2, 0);
    EXPECT_TRUE(sdl.poll(1.2).empty());
    EXPECT_EQ(found[1]->status(), DeviceStatus::Connected);
    EXPECT_EQ(found[1]->info().id, "sdl:" + guid + "#2");

    // and one more is new: #3
    attachVirtual("Padrob twin stick", SDL_JOYSTICK_TYPE_UNKNOWN, 2, 2, 0);
    const Devices third = pollUntilFound(sdl, 1, 1.3);
    ASSERT_EQ(third.size(), 1u);
    EXPECT_EQ(third[0]->info().id, "sdl:" + guid + "#3");
}

TEST(SdlJoysticks, DeviceWithoutAxesSaysItCannotDriveAValve)
{
    SdlJoysticks sdl;
    const int buttonsOnly = attachVirtual("Padrob test buttons", SDL_JOYSTICK_TYPE_UNKNOWN, 0, 2, 0);
    attachVirtual("Padrob test nothing", SDL_JOYSTICK_TYPE_UNKNOWN, 0, 0, 0);
    Handle handle(buttonsOnly);
    const Devices found = pollUntilFound(sdl, 2);
    ASSERT_EQ(found.size(), 2u);
    for (const auto& device : found) {
        SCOPED_TRACE(device->info().name.toStdString());
        EXPECT_EQ(device->status(), DeviceStatus::Connected);
        EXPECT_TRUE(device->info().axes.isEmpty());
        EXPECT_TRUE(device->statusText().contains("no axes") || device->statusText().contains("neither axes"))
            << device->statusText().toStdString();
        EXPECT_TRUE(device->statusText().contains("valve"));
        pollBoth(sdl, *device, 0.1);
        EXPECT_TRUE(device->sample().axes.empty());
        EXPECT_EQ(device->sample().count, 1u);
    }
    EXPECT_EQ(found[0]->info().buttons, (QStringList{"Button 1", "Button 2"}));
    EXPECT_TRUE(found[1]->info().buttons.isEmpty());
    EXPECT_NE(found[0]->statusText(), found[1]->statusText());

    ASSERT_EQ(SDL_JoystickSetVirtualButton(handle.joystick, 1, SDL_PRESSED), 0);
    pollBoth(sdl, *found[0], 0.2);
    EXPECT_EQ(found[0]->sample().buttons, (std::vector<std::uint8_t>{0, 1}));
}

TEST(SdlJoysticks, SeveralInSequenceInOneProcess)
{
    for (int round = 0; round < 3; ++round) {
        SCOPED_TRACE(round);
        std::shared_ptr<InputDevice> kept;
        {
            SdlJoysticks sdl;
            ASSERT_TRUE(sdl.problem().isEmpty()) << sdl.problem().toStdString();
            EXPECT_NE(SDL_WasInit(SDL_INIT_GAMECONTROLLER), 0u);
            // the previous round's virtual device went with SDL's joystick subsystem
            EXPECT_EQ(SDL_NumJoysticks(), 0);
            const int index = attachPad("Padrob test pad sequence");
            Handle handle(index);
            ASSERT_EQ(SDL_JoystickSetVirtualAxis(handle.joystick, SDL_CONTROLLER_AXIS_RIGHTX, 1000 * (round + 1)), 0);
            const Devices found = pollUntilFound(sdl, 1);
            ASSERT_EQ(found.size(), 1u);
            kept = found[0];
            pollBoth(sdl, *kept, 0.0);
            EXPECT_EQ(kept->sample().axes[2], 1000.0 * (round + 1));
        }
        // SDL stopped (nothing else in this binary holds it); the device outlives it harmlessly
        EXPECT_EQ(SDL_WasInit(SDL_INIT_JOYSTICK | SDL_INIT_GAMECONTROLLER), 0u);
        EXPECT_EQ(kept->status(), DeviceStatus::Disconnected);
        EXPECT_FALSE(kept->statusText().isEmpty());
        kept->poll(1.0);
        EXPECT_EQ(kept->sample().count, 1u);
        EXPECT_EQ(kept->sample().axes[2], 1000.0 * (round + 1));
    }
}
