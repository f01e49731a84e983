#include "platform/input/hid/hid_library.hpp"

#include <hidapi/hidapi.h>

namespace steerseg::platform::input {
namespace {

struct HidLibrary {
    HidLibrary() : ok(hid_init() == 0) {}
    ~HidLibrary() {
        if (ok) {
            hid_exit();
        }
    }
    HidLibrary(const HidLibrary&) = delete;
    HidLibrary& operator=(const HidLibrary&) = delete;
    bool ok;
};

} // namespace

bool ensureHidLibrary(std::string& problem) {
    static const HidLibrary library;
    if (!library.ok) {
        problem = "hidapi: hid_init failed";
    }
    return library.ok;
}

} // namespace steerseg::platform::input
