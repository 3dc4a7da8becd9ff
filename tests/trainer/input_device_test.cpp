#include "trainer/input/input_device.h"

#include <gtest/gtest.h>

TEST(InputDevice, EveryKindHasAName)
{
    using trainer::DeviceKind;
    for (DeviceKind k : {DeviceKind::Joystick, DeviceKind::Gamepad, DeviceKind::SerialDaq, DeviceKind::Comedi,
                         DeviceKind::Keyboard, DeviceKind::Replay})
        EXPECT_FALSE(trainer::kindName(k).isEmpty());
}
