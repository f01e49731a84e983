// PLACEHOLDER: replaced by the real reader in this change.
#include "io/readers.hpp"

namespace steerseg::io {

Volume readNifti(const std::filesystem::path& path, const ReadLimits&, std::string&) {
    throw ScanError(path, "reader not built yet");
}

} // namespace steerseg::io
