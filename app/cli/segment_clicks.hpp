#pragma once

// `segment --click` and `--box`: prompts replayed through the kiosk's workflow
// (cmd_segment_clicks.cpp).
#include "cli/args.hpp"
#include "model/action.hpp"

#include <string>

namespace steerseg::cli {

// "i,j,k,+" or "i,j,k,-", optionally ",radius" (voxels); UsageError naming the problem.
model::Correct parseClick(const std::string& text);

// "i0,j0,k0,i1,j1,k1": two opposite corners, voxel indices; UsageError naming the problem
// (whether it fits the scan is checked once the scan is read).
model::Box parseBox(const std::string& text);

// The command when --click or --box is given; refuses the options the prompts replace.
int runSegmentClicks(const Args& args);

// A report (JSON text and a newline) written whole or not at all; files::WriteError.
void writeReport(const std::string& path, const std::string& text);

} // namespace steerseg::cli
