// The HID source through hidapi's hidraw backend: the device matched by vendor/product (and
// usage where the spec names one), opened by path, read without blocking. The first record
// is the report descriptor, so a descriptor-parsing decoder sees it before any report; hidapi
// 0.13 (Debian 12) cannot fetch it, so it comes from sysfs or the HIDIOCGRDESC ioctl.
#include "platform/input/hid/hid_library.hpp"
#include "platform/input/node_access.hpp"
#include "platform/input/sources.hpp"

#include <array>
#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <hidapi/hidapi.h>
#include <linux/hidraw.h>
#include <sys/ioctl.h>
#include <unistd.h>

namespace steerseg::platform::input {
namespace {

// hidraw's largest report (HID_MAX_BUFFER_SIZE).
constexpr std::size_t kMaxReport = 4096;

std::string narrow(const wchar_t* text) {
    std::string out;
    for (; text != nullptr && *text != L'\0'; ++text) {
        out.push_back(*text < 0x80 ? static_cast<char>(*text) : '?');
    }
    return out;
}

std::string hex4(std::uint16_t v) {
    std::array<char, 8> text{};
    std::snprintf(text.data(), text.size(), "%04x", v);
    return text.data();
}

std::string baseName(const std::string& path) {
    const auto slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// sysfs first (readable by anyone), then the ioctl on the node.
bool readReportDescriptor(const std::string& node, std::vector<std::uint8_t>& out,
                          std::string& problem) {
    const std::string sysfs = "/sys/class/hidraw/" + baseName(node) + "/device/report_descriptor";
    const int sysfd = ::open(sysfs.c_str(), O_RDONLY | O_CLOEXEC);
    if (sysfd >= 0) {
        std::array<std::uint8_t, HID_MAX_DESCRIPTOR_SIZE> bytes{};
        const ssize_t got = ::read(sysfd, bytes.data(), bytes.size());
        ::close(sysfd);
        if (got > 0) {
            out.assign(bytes.begin(), bytes.begin() + got);
            return true;
        }
    }
    const int fd = ::open(node.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        problem = nodeOpenProblem(node, "opening to read the report descriptor", errno);
        return false;
    }
    int size = 0;
    hidraw_report_descriptor descriptor{};
    const bool ok = ioctl(fd, HIDIOCGRDESCSIZE, &size) >= 0 && size > 0 &&
                    size <= HID_MAX_DESCRIPTOR_SIZE &&
                    (descriptor.size = static_cast<std::uint32_t>(size),
                     ioctl(fd, HIDIOCGRDESC, &descriptor) >= 0);
    const int err = errno;
    ::close(fd);
    if (!ok) {
        problem = nodeOpenProblem(node, "HIDIOCGRDESC", err);
        return false;
    }
    out.assign(descriptor.value, descriptor.value + descriptor.size);
    return true;
}

class HidSource final : public RawSource {
  public:
    HidSource(std::string name, std::string node, hid_device* device,
              std::vector<std::uint8_t> descriptor)
        : name_(std::move(name)), node_(std::move(node)), device_(device),
          descriptor_(std::move(descriptor)) {}
    ~HidSource() override { hid_close(device_); }
    HidSource(const HidSource&) = delete;
    HidSource& operator=(const HidSource&) = delete;

    [[nodiscard]] const std::string& name() const override { return name_; }
    // hidapi keeps its file descriptor to itself: the owner reads each frame.
    [[nodiscard]] int fd() const override { return -1; }

    ReadStatus read(double now, std::size_t maxRecords, std::vector<RawRecord>& out,
                    std::string& problem) override {
        std::size_t produced = 0;
        if (!descriptorSent_ && maxRecords > 0) {
            RawRecord record;
            record.kind = RawRecord::Kind::HidDescriptor;
            record.time = now;
            record.device = name_;
            record.bytes = descriptor_;
            out.push_back(std::move(record));
            descriptorSent_ = true;
            ++produced;
        }
        std::array<std::uint8_t, kMaxReport> buffer{};
        while (produced < maxRecords) {
            const int got = hid_read(device_, buffer.data(), buffer.size());
            if (got == 0) {
                return ReadStatus::Ok;
            }
            if (got < 0) {
                const std::string why = narrow(hid_error(device_));
                // hidapi reports an unplug as a poll error or ENODEV; the node's absence says so
                // for certain.
                if (::access(node_.c_str(), F_OK) != 0 ||
                    why.find("disconnected") != std::string::npos ||
                    why.find("No such device") != std::string::npos) {
                    problem = node_ + ": device removed";
                    return ReadStatus::Gone;
                }
                problem = node_ + ": hid_read failed: " + (why.empty() ? "unknown error" : why);
                return ReadStatus::Failed;
            }
            RawRecord record;
            record.kind = RawRecord::Kind::HidReport;
            record.time = now;
            record.device = name_;
            record.bytes.assign(buffer.begin(), buffer.begin() + got);
            out.push_back(std::move(record));
            ++produced;
        }
        return ReadStatus::Ok;
    }

  private:
    std::string name_;
    std::string node_;
    hid_device* device_;
    std::vector<std::uint8_t> descriptor_;
    bool descriptorSent_ = false;
};

bool matches(const hid_device_info& info, const DeviceSpec& spec) {
    return (spec.usagePage == 0 || info.usage_page == spec.usagePage) &&
           (spec.usage == 0 || info.usage == spec.usage);
}

} // namespace

std::unique_ptr<RawSource> openHidSource(const DeviceSpec& spec, std::string& problem) {
    problem.clear();
    if (!ensureHidLibrary(problem)) {
        problem = spec.name + ": " + problem;
        return nullptr;
    }
    // A kind of controller made by many vendors (radial dials) is found by its usage alone;
    // hid_enumerate(0, 0) lists every device.
    const bool byId = spec.vendorId != 0 || spec.productId != 0;
    if (!byId && spec.usagePage == 0 && spec.usage == 0) {
        problem = spec.name + ": neither a vendor/product id nor a usage to find the HID device by";
        return nullptr;
    }
    std::string node;
    hid_device_info* list = hid_enumerate(spec.vendorId, spec.productId);
    for (const hid_device_info* info = list; info != nullptr; info = info->next) {
        if (info->path != nullptr && matches(*info, spec)) {
            node = info->path;
            break;
        }
    }
    hid_free_enumeration(list);
    const std::string id = byId ? hex4(spec.vendorId) + ":" + hex4(spec.productId) : "";
    if (node.empty()) {
        problem = spec.name + ": no HID device" + (byId ? " " + id : "");
        if (spec.usagePage != 0 || spec.usage != 0) {
            problem += " with usage " + hex4(spec.usagePage) + ":" + hex4(spec.usage);
        }
        problem += " (hidraw)";
        return nullptr;
    }
    // hidapi folds errno into a wide string; asking the node directly names a permission error.
    if (::access(node.c_str(), R_OK | W_OK) != 0) {
        problem = spec.name + ": " + nodeOpenProblem(node, "open", errno);
        return nullptr;
    }
    hid_device* device = hid_open_path(node.c_str());
    if (device == nullptr) {
        problem = spec.name + ": " + node + ": hid_open_path failed: " + narrow(hid_error(nullptr));
        return nullptr;
    }
    if (hid_set_nonblocking(device, 1) != 0) {
        problem =
            spec.name + ": " + node + ": hid_set_nonblocking failed: " + narrow(hid_error(device));
        hid_close(device);
        return nullptr;
    }
    std::vector<std::uint8_t> descriptor;
    std::string why;
    if (!readReportDescriptor(node, descriptor, why)) {
        problem = spec.name + ": " + why;
        hid_close(device);
        return nullptr;
    }
    return std::make_unique<HidSource>(spec.name, node, device, std::move(descriptor));
}

std::vector<AttachedDevice> listHidDevices() {
    std::vector<AttachedDevice> devices;
    std::string problem;
    if (!ensureHidLibrary(problem)) {
        return devices;
    }
    hid_device_info* list = hid_enumerate(0, 0);
    for (const hid_device_info* info = list; info != nullptr; info = info->next) {
        AttachedDevice device;
        device.kind = "hid";
        device.node = info->path != nullptr ? info->path : "";
        device.vendorId = info->vendor_id;
        device.productId = info->product_id;
        device.usagePage = info->usage_page;
        device.usage = info->usage;
        device.description = narrow(info->product_string);
        devices.push_back(std::move(device));
    }
    hid_free_enumeration(list);
    return devices;
}

} // namespace steerseg::platform::input
