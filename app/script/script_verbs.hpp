#pragma once

// The script's verbs, one handler each, in tables by level: the device level (touch, tap,
// keys, wheel, and raw device records below the input path), the operator's actions (the
// PACS's in a table of their own), and the waits and checks. parseScript looks a line's first word
// up in their union.
#include "script/script.hpp"
#include "script/script_tokens.hpp"

#include <functional>
#include <map>
#include <string>

namespace steerseg::script::detail {

using Handler = std::function<StepKind(Words&)>;
using VerbTable = std::map<std::string, Handler, std::less<>>;

void addDeviceVerbs(VerbTable& table);   // script_verbs_device.cpp
void addOperatorVerbs(VerbTable& table); // script_verbs_operator.cpp
void addPacsVerbs(VerbTable& table);     // script_verbs_pacs.cpp
void addCheckVerbs(VerbTable& table);    // script_verbs_checks.cpp

} // namespace steerseg::script::detail
