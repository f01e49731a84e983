#pragma once

// Waits' and checks' conditions evaluated against the workflow's Status.
#include "script/script.hpp"
#include "workflow/status.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace steerseg::script {

// A numeric Status field by its script name ("volume_ml", "T", "converged" as 0/1, ...).
std::optional<double> statusField(const workflow::Status& status, std::string_view field);

bool compare(double lhs, Condition::Op op, double rhs);
std::string_view opText(Condition::Op op);

// Whether `status` satisfies `condition` (Seconds and wait-Iterations are the player's: they
// need the clock and the count at the wait's start; here Iterations is "at least count").
bool holds(const Condition& condition, const workflow::Status& status);

// What the status shows for the condition, for a failure message: "state is paused",
// "volume_ml is 1.2", "message is \"...\"".
std::string observed(const Condition& condition, const workflow::Status& status);

} // namespace steerseg::script
