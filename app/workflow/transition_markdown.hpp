#pragma once

// The transition table as the Markdown rows docs/workflow.md shows, so the docs can be checked
// against (and regenerated from) the table the workflow runs.
#include <string>

namespace steerseg::workflow {

// The header, its separator and one line per rule, then one per state default; each line ends
// with '\n'.
std::string transitionTableMarkdown();

} // namespace steerseg::workflow
