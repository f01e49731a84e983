// PLACEHOLDER: replaced by the real writer in this change.
#include "io/mask_writer.hpp"

#include "io/scan_reader.hpp"

namespace steerseg::io {

void writeMask(const std::filesystem::path& path, const Geometry&, std::span<const std::uint8_t>) {
    throw ScanError(path, "writer not built yet");
}

} // namespace steerseg::io
