#pragma once

// Byte streams the readers pull scan data from: a file, bytes in memory (fuzz targets) or a
// gzip/zlib stream over either. Data is pulled in pieces, so a hostile header that claims
// gigabytes makes us allocate only as much as the file actually delivers.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace steerseg::scan {

class ByteSource {
  public:
    virtual ~ByteSource() = default;
    // Fills as much of `out` as it can; returns 0 only at the end of the data.
    virtual std::size_t read(std::span<std::byte> out) = 0;
    // Bytes left before the end, where known without reading (not for compressed streams).
    [[nodiscard]] virtual std::optional<std::uint64_t> remaining() const = 0;
    // For a decompressing stream, the compressed bytes not yet decoded, where known: what
    // bounds how much it can still deliver (checkDataFits). nullopt for plain data.
    [[nodiscard]] virtual std::optional<std::uint64_t> compressedRemaining() const {
        return std::nullopt;
    }
};

// A source that can jump: files and memory.
class SeekableSource : public ByteSource {
  public:
    [[nodiscard]] virtual std::uint64_t size() const = 0;
    [[nodiscard]] virtual std::uint64_t position() const = 0;
    // Jumps to `offset`, at most size().
    virtual void seek(std::uint64_t offset) = 0;
    [[nodiscard]] std::optional<std::uint64_t> remaining() const override {
        return size() - position();
    }
};

// A regular file. Throws ScanError when it is missing, not a regular file or unreadable.
class FileSource final : public SeekableSource {
  public:
    explicit FileSource(const std::filesystem::path& path);
    std::size_t read(std::span<std::byte> out) override;
    [[nodiscard]] std::uint64_t size() const override { return size_; }
    [[nodiscard]] std::uint64_t position() const override { return position_; }
    void seek(std::uint64_t offset) override;

  private:
    std::filesystem::path path_;
    std::ifstream in_;
    std::uint64_t size_ = 0;
    std::uint64_t position_ = 0;
};

class MemorySource final : public SeekableSource {
  public:
    explicit MemorySource(std::span<const std::byte> bytes) : bytes_(bytes) {}
    std::size_t read(std::span<std::byte> out) override;
    [[nodiscard]] std::uint64_t size() const override { return bytes_.size(); }
    [[nodiscard]] std::uint64_t position() const override { return position_; }
    void seek(std::uint64_t offset) override;

  private:
    std::span<const std::byte> bytes_;
    std::uint64_t position_ = 0;
};

// Decompresses a gzip or zlib stream (concatenated gzip members too), or a raw deflate stream
// (RFC 1951: DICOM's deflated transfer syntax), read from `inner`. Corrupt data throws ScanError
// naming `path`; compressed data that stops early reads as an early end.
class GzipSource final : public ByteSource {
  public:
    enum class Format { GzipOrZlib, RawDeflate };
    GzipSource(std::filesystem::path path, ByteSource& inner, Format format = Format::GzipOrZlib);
    ~GzipSource() override;
    GzipSource(const GzipSource&) = delete;
    GzipSource& operator=(const GzipSource&) = delete;
    std::size_t read(std::span<std::byte> out) override;
    [[nodiscard]] std::optional<std::uint64_t> remaining() const override { return std::nullopt; }
    [[nodiscard]] std::optional<std::uint64_t> compressedRemaining() const override;
    // Output inflate may still owe for input it already consumed, beyond what
    // compressedRemaining() bounds: its bit buffer (up to 8 bytes, 8 x 1032 bytes of output)
    // and a match in progress (258 bytes); with room to spare.
    static constexpr std::uint64_t kPendingBytes = 16 * 1024;

  private:
    struct State;
    std::filesystem::path path_;
    ByteSource& inner_;
    Format format_;
    std::unique_ptr<State> state_;
};

// True if the source starts with the gzip magic bytes; the position is left unchanged.
bool startsWithGzipMagic(SeekableSource& source);

// Reads until `count` bytes or the end of the data, growing the buffer only as bytes arrive.
std::vector<std::byte> readUpTo(ByteSource& source, std::uint64_t count);

// Reads exactly `count` bytes. Otherwise throws ScanError: "<what> but the data ends after
// <n>" (`what` says what was expected, e.g. "header says 512x512x300 int16 (150 MiB)").
std::vector<std::byte> readExactly(const std::filesystem::path& path, ByteSource& source,
                                   std::uint64_t count, const std::string& what);

// Skips `count` bytes; returns how many there were before the end.
std::uint64_t skipBytes(ByteSource& source, std::uint64_t count);

// Skips `lines` newline-terminated lines; returns false if the data ended first.
bool skipLines(ByteSource& source, std::uint64_t lines);

// "150 MiB", "12.3 KiB", "17 bytes": sizes in error messages.
std::string sizeText(std::uint64_t bytes);

} // namespace steerseg::scan
