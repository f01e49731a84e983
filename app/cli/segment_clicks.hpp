#pragma once

// `segment --click`: corrections replayed through the kiosk's workflow (cmd_segment_clicks.cpp).
#include "cli/args.hpp"
#include "model/action.hpp"

#include <string>

namespace steerseg::cli {

// "i,j,k,+" or "i,j,k,-", optionally ",radius" (voxels); UsageError naming the problem.
model::Correct parseClick(const std::string& text);

// The command when --click is given; refuses the options the clicks replace.
int runSegmentClicks(const Args& args);

// A report (JSON text and a newline) written whole or not at all; files::WriteError.
void writeReport(const std::string& path, const std::string& text);

} // namespace steerseg::cli
