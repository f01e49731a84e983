#include "config/kiosk_config.hpp"

#include <array>

namespace steerseg::config {

namespace {

constexpr std::array<std::string_view, 4> kPlatformNames{"auto", "kms", "window", "offscreen"};
constexpr std::array<std::string_view, 5> kInputKindNames{"shuttle", "radial", "powermate",
                                                          "gpio_input", "gpio_led"};

} // namespace

std::string_view platformName(DisplayPlatform platform) {
    return kPlatformNames.at(static_cast<std::size_t>(platform));
}

std::optional<DisplayPlatform> parsePlatform(std::string_view word) {
    for (std::size_t i = 0; i < kPlatformNames.size(); ++i) {
        if (kPlatformNames[i] == word) {
            return static_cast<DisplayPlatform>(i);
        }
    }
    return std::nullopt;
}

std::string_view inputDeviceKindName(InputDeviceKind kind) {
    return kInputKindNames.at(static_cast<std::size_t>(kind));
}

std::optional<InputDeviceKind> parseInputDeviceKind(std::string_view word) {
    for (std::size_t i = 0; i < kInputKindNames.size(); ++i) {
        if (kInputKindNames[i] == word) {
            return static_cast<InputDeviceKind>(i);
        }
    }
    return std::nullopt;
}

// Keep equal to config/steerseg.toml, whose comments say why each value is what it is
// (config_test compares the two field by field).
KioskConfig defaultConfig() {
    KioskConfig c;
    c.presets = {
        {"CT soft tissue", 40.0, 60.0, 0.2, 40.0, 400.0, "soft"},
        {"CT bone", 900.0, 600.0, 0.5, 400.0, 1800.0, "bone"},
        {"MR tumour", 180.0, 50.0, 0.3, 128.0, 256.0, "mr"},
    };
    const model::StructureCode anatomy{"123037004", "SCT", "Anatomical Structure"};
    const model::StructureCode abnormal{"49755003", "SCT", "Morphologically Abnormal Structure"};
    c.structures = {
        {"Tumour", abnormal, {"108369006", "SCT", "Neoplasm"}, {0.847, 0.396, 0.310}, true},
        {"Liver", anatomy, {"10200004", "SCT", "Liver"}, {0.867, 0.510, 0.396}, true},
        {"Spleen", anatomy, {"78961009", "SCT", "Spleen"}, {0.616, 0.424, 0.635}, true},
        {"Right kidney", anatomy, {"9846003", "SCT", "Right kidney"}, {0.725, 0.400, 0.341}, true},
        {"Left kidney", anatomy, {"18639004", "SCT", "Left kidney"}, {0.725, 0.400, 0.341}, true},
        {"Lung", anatomy, {"39607008", "SCT", "Lung"}, {0.769, 0.475, 0.376}, true},
    };
    c.bindings.keys = {
        {"space", {"toggle_run", 1.0, ""}},
        {"enter", {"proceed", 1.0, ""}},
        {"backspace", {"back", 1.0, ""}},
        {"escape", {"dismiss", 1.0, ""}},
        {"z", {"undo", 1.0, ""}},
        {"y", {"redo", 1.0, ""}},
        {"ctrl+z", {"undo", 1.0, ""}},
        {"ctrl+y", {"redo", 1.0, ""}},
        {"tab", {"cycle_param", 1.0, ""}},
        {"shift+tab", {"cycle_param", -1.0, ""}},
        {"plus", {"nudge_selected", 1.0, ""}},
        {"minus", {"nudge_selected", -1.0, ""}},
        {"up", {"nudge_selected", 1.0, ""}},
        {"down", {"nudge_selected", -1.0, ""}},
        {"shift+up", {"nudge_selected", 10.0, ""}},
        {"shift+down", {"nudge_selected", -10.0, ""}},
        {"pageup", {"page:axial", 1.0, ""}},
        {"pagedown", {"page:axial", -1.0, ""}},
        {"left", {"rotate_yaw", -1.0, ""}},
        {"right", {"rotate_yaw", 1.0, ""}},
    };
    c.bindings.knobs = {
        {"knob1", {"nudge_selected", 1.0, ""}},
        {"knob2", {"page:axial", 1.0, ""}},
        {"shuttle_jog", {"nudge_selected", 1.0, ""}},
        {"shuttle_ring", {"nudge_selected", 10.0, ""}},
        {"shuttlepro_jog", {"nudge_selected", 1.0, ""}},
        {"shuttlepro_ring", {"nudge_selected", 10.0, ""}},
        {"powermate_turn", {"nudge:radius", 1.0, ""}},
        {"dial_turn", {"nudge_selected", 1.0, ""}},
    };
    c.bindings.buttons = {
        {"button1", {"proceed", 1.0, ""}},
        {"button2", {"back", 1.0, ""}},
        {"button3", {"undo", 1.0, ""}},
        {"pedal", {"run", 1.0, "pause"}},
        {"powermate_press", {"toggle_run", 1.0, ""}},
        {"dial_press", {"toggle_run", 1.0, ""}},
    };
    // A shuttle's buttons as the device numbers them: the ShuttleXpress's five left to right,
    // the ShuttlePRO v2's first five (its top row of four and the next row's first).
    const auto shuttleButtons = [&c](const std::string& device, int first) {
        const std::vector<std::string_view> actions{"cycle_param", "undo", "redo", "proceed",
                                                    "export"};
        for (std::size_t i = 0; i < actions.size(); ++i) {
            c.bindings.buttons[device + "_button" + std::to_string(first + static_cast<int>(i))] = {
                std::string(actions[i]), 1.0, ""};
        }
    };
    shuttleButtons("shuttle", 1);
    shuttleButtons("shuttlepro", 1);
    using K = InputDeviceKind;
    // 0x01/0x0E: Generic Desktop, System Multi-Axis Controller (the Surface Dial's class).
    c.input.devices = {
        {"shuttle", K::Shuttle, 0x0b33, 0x0020, 0, 0, "", "", "", false, 20.0},
        {"shuttlepro", K::Shuttle, 0x0b33, 0x0030, 0, 0, "", "", "", false, 20.0},
        {"powermate", K::PowerMate, 0x077d, 0x0410, 0, 0, "", "", "", false, 20.0},
        {"dial", K::Radial, 0, 0, 0x01, 0x0e, "", "", "", false, 20.0},
        {"pedal", K::GpioInput, 0, 0, 0, 0, "", "gpiochip0", "PEDAL", true, 20.0},
        {"led", K::GpioLed, 0, 0, 0, 0, "", "gpiochip0", "LED", false, 20.0},
    };
    return c;
}

} // namespace steerseg::config
