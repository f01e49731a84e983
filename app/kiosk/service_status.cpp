#include "kiosk/service_status.hpp"

#include "workflow/action.hpp"

namespace steerseg::kiosk {

void ServiceStatus::framePresented(const workflow::Status& status) {
    notifier_.keepAlive(platform::ServiceNotifier::Clock::now());
    std::string line(workflow::stateName(status.state));
    if (!status.message.empty()) {
        line += ": " + status.message;
    }
    if (!ready_) {
        ready_ = true;
        shown_ = line;
        notifier_.ready(line);
        return;
    }
    if (line != shown_) {
        shown_ = line;
        notifier_.status(line);
    }
}

void ServiceStatus::stopping() {
    notifier_.stopping();
}

} // namespace steerseg::kiosk
