#include "kiosk/service_status.hpp"

#include "model/action.hpp"

namespace steerseg::kiosk {

void ServiceStatus::framePresented(const workflow::Status& status) {
    std::string line(model::stateName(status.state));
    if (!status.message.empty()) {
        line += ": " + status.message;
    }
    if (!ready_) {
        ready_ = true;
        shown_ = line;
        notifier_.ready(line);
    } else if (line != shown_) {
        shown_ = line;
        notifier_.status(line);
    }
    notifier_.keepAlive(platform::ServiceNotifier::Clock::now());
}

void ServiceStatus::stopping() {
    notifier_.stopping();
}

} // namespace steerseg::kiosk
