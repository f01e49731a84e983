// The evdev source: struct input_event records read without blocking from a node (or, for
// tests and replays, from a FIFO or regular file holding the same structs, where the ioctls
// fail with ENOTTY and only reading matters). The device is not grabbed: a desktop may share
// it. SYN_DROPPED is passed on like any event; the decoder resynchronises.
#include "platform/input/evdev/powermate_led.hpp"
#include "platform/input/node_access.hpp"
#include "platform/input/sources.hpp"

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <linux/input.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace steerseg::platform::input {
namespace {

constexpr const char* kInputDir = "/dev/input";

struct NodeIdentity {
    input_id id{};
    std::string name;
};

// EVIOCGID and EVIOCGNAME; false where the node is no evdev device (ENOTTY on a file).
bool identify(int fd, NodeIdentity& out) {
    if (ioctl(fd, EVIOCGID, &out.id) < 0) {
        return false;
    }
    std::array<char, 256> name{};
    if (ioctl(fd, EVIOCGNAME(name.size() - 1), name.data()) >= 0) {
        out.name = name.data();
    }
    return true;
}

class EvdevSource final : public RawSource {
  public:
    EvdevSource(std::string name, std::string node, int fd, bool writable)
        : name_(std::move(name)), node_(std::move(node)), fd_(fd), writable_(writable) {}
    ~EvdevSource() override { ::close(fd_); }
    EvdevSource(const EvdevSource&) = delete;
    EvdevSource& operator=(const EvdevSource&) = delete;

    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] int fd() const override { return fd_; }

    ReadStatus read(double now, std::size_t maxRecords, std::vector<RawRecord>& out,
                    std::string& problem) override {
        constexpr std::size_t kEvent = sizeof(input_event);
        std::size_t produced = 0;
        while (produced < maxRecords) {
            // At most what fits in maxRecords, so a flood stays queued in the kernel.
            const std::size_t want =
                std::min<std::size_t>(maxRecords - produced, kChunkEvents) * kEvent - pending_;
            const ssize_t got = ::read(fd_, buffer_.data() + pending_, want);
            if (got < 0) {
                if (errno == EINTR) {
                    continue;
                }
                if (errno == EAGAIN) {
                    return ReadStatus::Ok;
                }
                if (errno == ENODEV || errno == ENXIO) {
                    problem = node_ + ": device removed";
                    return ReadStatus::Gone;
                }
                problem = node_ + ": read failed: " + std::strerror(errno);
                return ReadStatus::Failed;
            }
            if (got == 0) {
                // End of a recorded file, or the writer of a FIFO went away.
                problem = node_ + ": end of input";
                return ReadStatus::Gone;
            }
            const std::size_t bytes = pending_ + static_cast<std::size_t>(got);
            const std::size_t whole = bytes / kEvent;
            for (std::size_t i = 0; i < whole; ++i) {
                input_event ev{};
                std::memcpy(&ev, buffer_.data() + i * kEvent, kEvent);
                RawRecord record;
                record.kind = RawRecord::Kind::Evdev;
                record.time = now;
                record.device = name_;
                record.type = ev.type;
                record.code = ev.code;
                record.value = ev.value;
                out.push_back(std::move(record));
            }
            produced += whole;
            // A FIFO may hand over part of a struct; keep it for the next read.
            pending_ = bytes - whole * kEvent;
            std::memmove(buffer_.data(), buffer_.data() + whole * kEvent, pending_);
        }
        return ReadStatus::Ok;
    }

    void setIndicator(Indicator indicator) override {
        if (!writable_ || (hasIndicator_ && indicator == indicator_)) {
            return;
        }
        input_event ev{};
        ev.type = EV_MSC;
        ev.code = MSC_PULSELED;
        ev.value = packPowerMateLed(powerMateLedFor(indicator));
        // A failed write (device gone) shows on the next read; the LED is cosmetic.
        if (::write(fd_, &ev, sizeof ev) == static_cast<ssize_t>(sizeof ev)) {
            indicator_ = indicator;
            hasIndicator_ = true;
        }
    }

  private:
    static constexpr std::size_t kChunkEvents = 64;
    std::string name_;
    std::string node_;
    int fd_;
    bool writable_;
    std::array<std::uint8_t, kChunkEvents * sizeof(input_event)> buffer_{};
    std::size_t pending_ = 0;
    Indicator indicator_ = Indicator::Off;
    bool hasIndicator_ = false;
};

std::string hex4(std::uint16_t v) {
    std::array<char, 8> text{};
    std::snprintf(text.data(), text.size(), "%04x", v);
    return text.data();
}

// Opens a device node for the LED where allowed, read-only otherwise (`problem` then says the
// LED stays off). Anything else (a recorded file, a FIFO) is only read: opening a FIFO for
// writing would make the source its own writer, and it would never see the end.
int openNode(const std::string& node, bool& writable, std::string& problem) {
    writable = false;
    struct stat st {};
    if (::stat(node.c_str(), &st) != 0) {
        problem = nodeOpenProblem(node, "open", errno);
        return -1;
    }
    if (S_ISDIR(st.st_mode)) {
        problem = node + " is a directory, not an evdev node";
        return -1;
    }
    int fd = -1;
    if (S_ISCHR(st.st_mode)) {
        fd = ::open(node.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
        writable = fd >= 0;
        if (fd < 0 && errno != EACCES && errno != EPERM && errno != EROFS) {
            problem = nodeOpenProblem(node, "open", errno);
            return -1;
        }
        if (fd < 0) {
            problem = nodeOpenProblem(node, "opening for writing", errno) +
                      "; reading only, the LED stays off";
        }
    }
    if (fd < 0) {
        fd = ::open(node.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) {
            problem = nodeOpenProblem(node, "open", errno);
        }
    }
    return fd;
}

} // namespace

std::unique_ptr<RawSource> openEvdevSource(const DeviceSpec& spec, std::string& problem) {
    problem.clear();
    std::string node = spec.path;
    if (node.empty()) {
        if (spec.vendorId == 0 && spec.productId == 0) {
            problem = spec.name + ": no evdev path and no vendor/product id to find it by";
            return nullptr;
        }
        std::string denied;
        for (const std::string& candidate : listNodes(kInputDir, "event")) {
            const int fd = ::open(candidate.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
            if (fd < 0) {
                if (denied.empty() && (errno == EACCES || errno == EPERM)) {
                    denied = nodeOpenProblem(candidate, "open", errno);
                }
                continue;
            }
            NodeIdentity identity;
            const bool known = identify(fd, identity);
            ::close(fd);
            if (known && identity.id.vendor == spec.vendorId &&
                identity.id.product == spec.productId) {
                node = candidate;
                break;
            }
        }
        if (node.empty()) {
            problem = spec.name + ": no evdev device " + hex4(spec.vendorId) + ":" +
                      hex4(spec.productId) + " in " + kInputDir;
            if (!denied.empty()) {
                problem += " (some nodes could not be read: " + denied + ")";
            }
            return nullptr;
        }
    }
    bool writable = false;
    std::string note;
    const int fd = openNode(node, writable, note);
    if (fd < 0) {
        problem = spec.name + ": " + note;
        return nullptr;
    }
    if (!note.empty()) {
        problem = spec.name + ": " + note;
    }
    return std::make_unique<EvdevSource>(spec.name, node, fd, writable);
}

std::vector<AttachedDevice> listEvdevDevices() {
    std::vector<AttachedDevice> devices;
    for (const std::string& node : listNodes(kInputDir, "event")) {
        AttachedDevice device;
        device.kind = "evdev";
        device.node = node;
        const int fd = ::open(node.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) {
            device.description = "(cannot open: " + std::string(std::strerror(errno)) + ")";
            devices.push_back(std::move(device));
            continue;
        }
        NodeIdentity identity;
        const bool known = identify(fd, identity);
        ::close(fd);
        if (!known) {
            continue;
        }
        device.vendorId = identity.id.vendor;
        device.productId = identity.id.product;
        device.description = identity.name;
        devices.push_back(std::move(device));
    }
    return devices;
}

} // namespace steerseg::platform::input
