#include "kiosk/operator_pacing.hpp"

#include <algorithm>

namespace steerseg::kiosk {

bool OperatorPacing::quiet(double now) const {
    return now - lastInput_ >= settings_.quietAfter;
}

double OperatorPacing::solverSlice(double now) const {
    return quiet(now) ? settings_.solverSlice : 0.0;
}

double OperatorPacing::refineSeconds(double now, double interactive, bool awaited) const {
    return quiet(now) || awaited ? std::max(interactive, settings_.refineSlice) : interactive;
}

bool OperatorPacing::screenDue(double now, bool changed) {
    if (!changed && now - lastScreen_ < settings_.screenInterval) {
        return false;
    }
    lastScreen_ = now;
    return true;
}

} // namespace steerseg::kiosk
