#pragma once

// A DICOM Application Entity title's rule, shared by the configuration that names peers and the
// network node that checks them.
#include <string>
#include <string_view>

namespace steerseg::model {

// "" when `aet` is a valid AE title (PS3.5 6.2: 1..16 characters of the default repertoire, no
// backslash or control character, not only spaces), else why not.
std::string aeTitleProblem(std::string_view aet);

} // namespace steerseg::model
