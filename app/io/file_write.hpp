#pragma once

// Output helpers for writers: gzip compression and crash-safe replacement of a file.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace steerseg::io {

// Compresses pieces appended one after another into one gzip member.
class GzipWriter {
  public:
    explicit GzipWriter(int level = 6);
    ~GzipWriter();
    GzipWriter(const GzipWriter&) = delete;
    GzipWriter& operator=(const GzipWriter&) = delete;
    void append(std::span<const std::byte> bytes);
    // Ends the stream and hands back the compressed bytes.
    std::vector<std::byte> finish();

  private:
    struct State;
    std::unique_ptr<State> state_;
};

std::vector<std::byte> gzipBytes(std::span<const std::byte> bytes, int level = 6);

// Writes the pieces to a temporary file beside `path`, then renames it over `path`, so readers
// never see a half-written file. Throws WriteError naming `path`.
void writeFileAtomically(const std::filesystem::path& path,
                         std::initializer_list<std::span<const std::byte>> pieces);

} // namespace steerseg::io
