#pragma once

// The kiosk as a systemd service: READY=1 after the first frame is on the screen, a STATUS=
// line whenever the workflow's state or message changes, watchdog keep-alives from the frame
// loop (a hung loop gets the unit restarted), STOPPING=1 on the way out. Without systemd it
// does nothing.
#include "platform/systemd/service_notifier.hpp"
#include "workflow/status.hpp"

#include <string>

namespace steerseg::kiosk {

class ServiceStatus {
  public:
    // After each present.
    void framePresented(const workflow::Status& status);
    void stopping();

  private:
    platform::ServiceNotifier notifier_;
    bool ready_ = false;
    std::string shown_;
};

} // namespace steerseg::kiosk
