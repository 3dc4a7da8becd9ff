#pragma once
// A gamepad made with SDL's virtual joystick API, for GUI tests that drive the
// station as an operator with a gamepad would: the test's own share of SDL (the
// station's SdlJoysticks counts on top of it), a device and the test's handle on it.
// The station finds it as it finds a real pad (hot-plug).

#include <SDL.h>

namespace studio::test {

struct VirtualPad {
    SDL_Joystick* pad = nullptr;
    int index = -1;
    bool sdl = false;

    VirtualPad()
    {
        sdl = SDL_InitSubSystem(SDL_INIT_JOYSTICK | SDL_INIT_GAMECONTROLLER) == 0;
        if (!sdl) return;
        SDL_VirtualJoystickDesc desc{};
        desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
        desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
        desc.naxes = SDL_CONTROLLER_AXIS_MAX;
        desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
        desc.name = "Padrob test gamepad";
        index = SDL_JoystickAttachVirtualEx(&desc);
        if (index >= 0) pad = SDL_JoystickOpen(index);
    }
    VirtualPad(const VirtualPad&) = delete;
    VirtualPad& operator=(const VirtualPad&) = delete;
    void unplug()
    {
        if (pad) SDL_JoystickClose(pad);
        if (index >= 0) SDL_JoystickDetachVirtual(index);
        pad = nullptr;
        index = -1;
    }
    ~VirtualPad()
    {
        unplug();
        if (sdl) SDL_QuitSubSystem(SDL_INIT_JOYSTICK | SDL_INIT_GAMECONTROLLER);
    }
};

}  // namespace studio::test
