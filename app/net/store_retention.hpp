#pragma once

// How long received series stay in the incoming store ([dicom] keep_days).
#include <chrono>
#include <filesystem>

namespace steerseg::net {

// Removes each <store>/<study>/<series> folder whose newest file is older than `now - keep`
// (a series still arriving has a new file and stays), then study folders left empty. Returns
// the series removed; a folder that cannot be read or removed is left, never thrown for.
int pruneStore(const std::filesystem::path& store, std::chrono::hours keep,
               std::filesystem::file_time_type now = std::filesystem::file_time_type::clock::now());

} // namespace steerseg::net
