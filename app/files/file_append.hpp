#pragma once

// The other way a file is written: one that grows by whole records (the audit log, an input
// recording), where a temporary file and a rename would rewrite it all each time.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string_view>

namespace steerseg::files {

// Opened for append (created 0644, its folder too), each append written whole and synced, or,
// on any failure, cut back to where it was so no partial record stays. Failures throw
// files::WriteError in the durable writer's words (file_write.hpp).
class AppendFile {
  public:
    explicit AppendFile(std::filesystem::path path);
    ~AppendFile();
    AppendFile(const AppendFile&) = delete;
    AppendFile& operator=(const AppendFile&) = delete;

    void append(std::span<const std::byte> bytes);
    void append(std::string_view text);
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
    int fd_ = -1;
};

} // namespace steerseg::files
