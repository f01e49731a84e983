#include "platform/input/libinput/touch_input.hpp"

#include "platform/input/node_access.hpp"

#include <array>
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <fcntl.h>
#include <libinput.h>
#include <libudev.h>
#include <unistd.h>

namespace steerseg::platform::input {

struct TouchInput::State {
    udev* udevContext = nullptr;
    libinput* context = nullptr;
    InputTranslator translator;
    std::optional<CalibrationMatrix> calibration;
    std::vector<std::string> problems;
    ~State() {
        if (context != nullptr) {
            libinput_unref(context);
        }
        if (udevContext != nullptr) {
            udev_unref(udevContext);
        }
    }
};

namespace {

int openRestricted(const char* path, int flags, void* userData) {
    const int fd = ::open(path, flags | O_CLOEXEC);
    if (fd < 0) {
        const int err = errno;
        static_cast<TouchInput::State*>(userData)->problems.push_back(
            "touch input: " + nodeOpenProblem(path, "open", err, "input"));
        return -err;
    }
    return fd;
}

void closeRestricted(int fd, void*) {
    ::close(fd);
}

const libinput_interface kInterface = {openRestricted, closeRestricted};

// libinput's own errors ("client bug: Invalid path ...") join the problems instead of stderr.
__attribute__((format(printf, 3, 0))) void
logHandler(libinput* context, libinput_log_priority priority, const char* format, va_list args) {
    if (priority < LIBINPUT_LOG_PRIORITY_ERROR) {
        return;
    }
    std::array<char, 512> text{};
    std::vsnprintf(text.data(), text.size(), format, args);
    std::string line = text.data();
    while (!line.empty() && line.back() == '\n') {
        line.pop_back();
    }
    static_cast<TouchInput::State*>(libinput_get_user_data(context))
        ->problems.push_back("touch input: libinput: " + line);
}

void deviceAdded(TouchInput::State& state, libinput_device* device) {
    if (state.calibration && libinput_device_config_calibration_has_matrix(device) != 0) {
        const std::string name = libinput_device_get_name(device);
        if (libinput_device_config_calibration_set_matrix(device, state.calibration->data()) !=
            LIBINPUT_CONFIG_STATUS_SUCCESS) {
            state.problems.push_back("touch input: " + name + ": calibration matrix refused");
        }
    }
}

void fill(TouchInput::State& state, libinput_event* event, double now,
          std::vector<InputEvent>& out) {
    DeviceEvent d;
    d.time = now;
    libinput_device* device = libinput_event_get_device(event);
    d.calibrateInSoftware =
        state.calibration && libinput_device_config_calibration_has_matrix(device) == 0;
    switch (libinput_event_get_type(event)) {
    case LIBINPUT_EVENT_DEVICE_ADDED:
        deviceAdded(state, device);
        return;
    case LIBINPUT_EVENT_TOUCH_DOWN:
    case LIBINPUT_EVENT_TOUCH_MOTION: {
        libinput_event_touch* t = libinput_event_get_touch_event(event);
        d.type = libinput_event_get_type(event) == LIBINPUT_EVENT_TOUCH_DOWN
                     ? DeviceEvent::Type::TouchDown
                     : DeviceEvent::Type::TouchMotion;
        d.slot = libinput_event_touch_get_seat_slot(t);
        // Normalised (width 1): the translator maps to the screen it is told about.
        d.x = libinput_event_touch_get_x_transformed(t, 1);
        d.y = libinput_event_touch_get_y_transformed(t, 1);
        break;
    }
    case LIBINPUT_EVENT_TOUCH_UP:
        d.type = DeviceEvent::Type::TouchUp;
        d.slot = libinput_event_touch_get_seat_slot(libinput_event_get_touch_event(event));
        break;
    case LIBINPUT_EVENT_TOUCH_CANCEL:
        d.type = DeviceEvent::Type::TouchCancel;
        break;
    case LIBINPUT_EVENT_POINTER_MOTION: {
        libinput_event_pointer* p = libinput_event_get_pointer_event(event);
        d.type = DeviceEvent::Type::PointerMotion;
        d.dx = libinput_event_pointer_get_dx(p);
        d.dy = libinput_event_pointer_get_dy(p);
        break;
    }
    case LIBINPUT_EVENT_POINTER_MOTION_ABSOLUTE: {
        libinput_event_pointer* p = libinput_event_get_pointer_event(event);
        d.type = DeviceEvent::Type::PointerMotionAbsolute;
        d.x = libinput_event_pointer_get_absolute_x_transformed(p, 1);
        d.y = libinput_event_pointer_get_absolute_y_transformed(p, 1);
        break;
    }
    case LIBINPUT_EVENT_POINTER_BUTTON: {
        libinput_event_pointer* p = libinput_event_get_pointer_event(event);
        d.type = DeviceEvent::Type::PointerButton;
        d.code = libinput_event_pointer_get_button(p);
        d.pressed = libinput_event_pointer_get_button_state(p) == LIBINPUT_BUTTON_STATE_PRESSED;
        break;
    }
    // The legacy LIBINPUT_EVENT_POINTER_AXIS repeats these; only the per-source events are used.
    case LIBINPUT_EVENT_POINTER_SCROLL_WHEEL:
    case LIBINPUT_EVENT_POINTER_SCROLL_FINGER: {
        libinput_event_pointer* p = libinput_event_get_pointer_event(event);
        if (libinput_event_pointer_has_axis(p, LIBINPUT_POINTER_AXIS_SCROLL_VERTICAL) == 0) {
            return;
        }
        const bool wheel = libinput_event_get_type(event) == LIBINPUT_EVENT_POINTER_SCROLL_WHEEL;
        d.type = wheel ? DeviceEvent::Type::ScrollWheel : DeviceEvent::Type::ScrollFinger;
        d.scroll =
            wheel
                ? libinput_event_pointer_get_scroll_value_v120(
                      p, LIBINPUT_POINTER_AXIS_SCROLL_VERTICAL)
                : libinput_event_pointer_get_scroll_value(p, LIBINPUT_POINTER_AXIS_SCROLL_VERTICAL);
        break;
    }
    case LIBINPUT_EVENT_KEYBOARD_KEY: {
        libinput_event_keyboard* k = libinput_event_get_keyboard_event(event);
        d.type = DeviceEvent::Type::Key;
        d.code = libinput_event_keyboard_get_key(k);
        d.pressed = libinput_event_keyboard_get_key_state(k) == LIBINPUT_KEY_STATE_PRESSED;
        break;
    }
    default:
        return;
    }
    state.translator.translate(d, out);
}

} // namespace

TouchInput::TouchInput(std::unique_ptr<State> state) : state_(std::move(state)) {}
TouchInput::~TouchInput() = default;

std::unique_ptr<TouchInput> TouchInput::open(const TouchInputOptions& options,
                                             std::string& problem) {
    problem.clear();
    auto state = std::make_unique<State>();
    state->calibration = options.calibration;
    state->translator.setScreen(options.screenWidth, options.screenHeight);
    state->translator.setCalibration(options.calibration);
    if (options.devices.empty()) {
        // Without udevd the seat enumerates devices that are never initialised, and libinput
        // takes none of them: say so instead of opening a seat that stays silent.
        if (::access("/run/udev/control", F_OK) != 0) {
            problem = "touch input: udev is not running (no /run/udev/control): the seat " +
                      options.seat + " would have no devices; name the nodes instead";
            return nullptr;
        }
        state->udevContext = udev_new();
        if (state->udevContext == nullptr) {
            problem = "touch input: udev_new failed";
            return nullptr;
        }
        state->context = libinput_udev_create_context(&kInterface, state.get(), state->udevContext);
        if (state->context == nullptr) {
            problem = "touch input: libinput_udev_create_context failed";
            return nullptr;
        }
        libinput_log_set_handler(state->context, logHandler);
        if (libinput_udev_assign_seat(state->context, options.seat.c_str()) != 0) {
            problem = "touch input: libinput_udev_assign_seat(" + options.seat +
                      ") failed (is udev running?)";
            return nullptr;
        }
    } else {
        state->context = libinput_path_create_context(&kInterface, state.get());
        if (state->context == nullptr) {
            problem = "touch input: libinput_path_create_context failed";
            return nullptr;
        }
        libinput_log_set_handler(state->context, logHandler);
        for (const std::string& node : options.devices) {
            if (libinput_path_add_device(state->context, node.c_str()) == nullptr) {
                problem = state->problems.empty()
                              ? "touch input: " + node + ": libinput_path_add_device failed " +
                                    "(not an input device?)"
                              : state->problems.back();
                return nullptr;
            }
        }
    }
    return std::unique_ptr<TouchInput>(new TouchInput(std::move(state)));
}

int TouchInput::fd() const {
    return libinput_get_fd(state_->context);
}

void TouchInput::setScreen(int width, int height) {
    state_->translator.setScreen(width, height);
}

void TouchInput::poll(double now, std::vector<InputEvent>& out) {
    if (libinput_dispatch(state_->context) != 0) {
        state_->problems.emplace_back("touch input: libinput_dispatch failed");
    }
    while (libinput_event* event = libinput_get_event(state_->context)) {
        fill(*state_, event, now, out);
        libinput_event_destroy(event);
    }
}

std::vector<std::string> TouchInput::takeProblems() {
    std::vector<std::string> problems;
    problems.swap(state_->problems);
    return problems;
}

} // namespace steerseg::platform::input
