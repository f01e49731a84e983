#include "model/ae_title.hpp"

#include <algorithm>

namespace steerseg::model {

std::string aeTitleProblem(std::string_view aet) {
    if (aet.empty() || aet.size() > 16) {
        return "an AE title has 1 to 16 characters";
    }
    if (std::any_of(aet.begin(), aet.end(),
                    [](char c) { return c < 0x20 || c > 0x7e || c == '\\'; })) {
        return "an AE title holds printable ASCII characters only, no backslash";
    }
    if (std::all_of(aet.begin(), aet.end(), [](char c) { return c == ' '; })) {
        return "an AE title cannot be only spaces";
    }
    return {};
}

} // namespace steerseg::model
