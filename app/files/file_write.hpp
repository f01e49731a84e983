#pragma once

// Output helpers for writers: gzip compression and the one durable way a file is written.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace steerseg::files {

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

// The single path every writer takes, so that neither a crash nor a power cut leaves a
// half-written file under `path`: a new temporary file beside it (O_EXCL, a unique hidden
// name), every byte written, fsync, rename over `path`, fsync of the folder. On any failure the
// temporary file is removed, an existing `path` is left as it was, and files::WriteError says why
// in one line: the disk is full, the folder is read-only or not writable, the folder does not
// exist, or the system's own words for anything else.
void writeFileAtomically(const std::filesystem::path& path,
                         std::initializer_list<std::span<const std::byte>> pieces);

// writeFileAtomically's write loop on an open descriptor (short writes and EINTR retried): the
// seam where a test hands it /dev/full to see the full-disk message come from the real errno.
// Throws files::WriteError naming `path`, with the bytes that could not be written.
void writeAllTo(int fd, const std::filesystem::path& path,
                std::initializer_list<std::span<const std::byte>> pieces);

// Throws the files::WriteError for `error` (an errno) writing `path`, in the one-line words above.
[[noreturn]] void failWrite(const std::filesystem::path& path, int error, std::size_t unwritten);

} // namespace steerseg::files
