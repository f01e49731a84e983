#include "files/file_write.hpp"

#include "files/file_error.hpp"
#include "files/io_faults.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <unistd.h>
#include <zlib.h>

namespace steerseg::files {

struct GzipWriter::State {
    z_stream zs{};
    std::vector<std::byte> out;
};

GzipWriter::GzipWriter(int level) : state_(std::make_unique<State>()) {
    // 15 + 16: the largest window with a gzip (not zlib) wrapper.
    if (deflateInit2(&state_->zs, level, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
        throw std::runtime_error("cannot start the zlib compressor");
    }
}

GzipWriter::~GzipWriter() {
    deflateEnd(&state_->zs);
}

namespace {

void pump(z_stream& zs, std::vector<std::byte>& out, int flush) {
    constexpr std::size_t kChunk = 256 * 1024;
    int rc = Z_OK;
    do {
        const std::size_t old = out.size();
        out.resize(old + kChunk);
        zs.next_out = reinterpret_cast<Bytef*>(out.data() + old);
        zs.avail_out = static_cast<uInt>(kChunk);
        rc = deflate(&zs, flush);
        out.resize(old + kChunk - zs.avail_out);
        if (rc == Z_STREAM_ERROR) {
            throw std::runtime_error("zlib compression failed");
        }
    } while (zs.avail_out == 0 || (flush == Z_FINISH && rc != Z_STREAM_END));
}

} // namespace

void GzipWriter::append(std::span<const std::byte> bytes) {
    z_stream& zs = state_->zs;
    constexpr std::size_t kMaxIn = std::size_t{1} << 30;
    while (!bytes.empty()) {
        const std::size_t n = std::min(bytes.size(), kMaxIn);
        // zlib's API takes non-const input it never writes.
        zs.next_in = const_cast<Bytef*>(reinterpret_cast<const Bytef*>(bytes.data()));
        zs.avail_in = static_cast<uInt>(n);
        pump(zs, state_->out, Z_NO_FLUSH);
        bytes = bytes.subspan(n);
    }
}

std::vector<std::byte> GzipWriter::finish() {
    state_->zs.avail_in = 0;
    pump(state_->zs, state_->out, Z_FINISH);
    return std::move(state_->out);
}

std::vector<std::byte> gzipBytes(std::span<const std::byte> bytes, int level) {
    GzipWriter writer(level);
    writer.append(bytes);
    return writer.finish();
}

namespace {

std::filesystem::path folderOf(const std::filesystem::path& path) {
    const std::filesystem::path folder = path.parent_path();
    return folder.empty() ? std::filesystem::path(".") : folder;
}

// One line per cause the operator can act on; the system's words for the rest.
std::string causeText(int error, const std::filesystem::path& folder, std::size_t unwritten) {
    const std::string where = folder.string();
    switch (error) {
    case ENOSPC:
    case EDQUOT:
        return "the disk is full: " + std::to_string(unwritten) +
               " bytes could not be written to " + where;
    case EFBIG:
        return "the file is larger than this system lets the program write: " +
               std::to_string(unwritten) + " bytes could not be written to " + where;
    case EROFS:
        return "the folder " + where + " is on a read-only file system";
    case EACCES:
    case EPERM:
        return "the folder " + where + " is not writable (permission denied)";
    case ENOENT: {
        // /proc and the like: the folder is there but takes no new files.
        std::error_code ec;
        if (std::filesystem::is_directory(folder, ec)) {
            return "the folder " + where + " does not accept new files";
        }
        return "the folder " + where + " does not exist";
    }
    case ENOTDIR:
        return where + " is not a folder";
    case EISDIR:
        return "a folder of that name is in the way";
    default:
        return "cannot write to " + where + ": " + std::strerror(error);
    }
}

[[noreturn]] void fail(const std::filesystem::path& path, int error, std::size_t unwritten) {
    failWrite(path, error, unwritten);
}

std::size_t totalSize(std::initializer_list<std::span<const std::byte>> pieces) {
    std::size_t total = 0;
    for (const auto& piece : pieces) {
        total += piece.size();
    }
    return total;
}

// A new file beside `path` no other writer (another process, a second export within the same
// second) can have: O_EXCL, the process id and a counter, retried on a name already taken.
// Hidden, so a half-written file never looks like an export in a file browser.
int createTemporary(const std::filesystem::path& path, std::size_t bytes,
                    std::filesystem::path& temp) {
    static std::atomic<unsigned> counter{0};
    const std::filesystem::path folder = folderOf(path);
    for (int attempt = 0; attempt < 100; ++attempt) {
        temp = folder / ("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()) +
                         "-" + std::to_string(counter++));
        const int fd = unlessInjected(IoCall::Open, [&] {
            return ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
        });
        if (fd >= 0) {
            return fd;
        }
        if (errno != EEXIST) {
            fail(path, errno, bytes); // ENOSPC here: no room for even an empty file
        }
    }
    throw WriteError(path, "cannot find a free temporary name in " + folder.string());
}

// Makes the rename itself durable: the folder's entry, not only the file's bytes.
void syncFolder(const std::filesystem::path& path) {
    const int fd = ::open(folderOf(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) {
        fail(path, errno, 0);
    }
    // EINVAL: a file system that cannot sync a folder (some FUSE ones); nothing more to do.
    const int rc = unlessInjected(IoCall::SyncFolder, [&] { return ::fsync(fd); });
    const int error = errno;
    ::close(fd);
    if (rc != 0 && error != EINVAL) {
        fail(path, error, 0);
    }
}

} // namespace

void failWrite(const std::filesystem::path& path, int error, std::size_t unwritten) {
    throw WriteError(path, causeText(error, folderOf(path), unwritten));
}

void writeAllTo(int fd, const std::filesystem::path& path,
                std::initializer_list<std::span<const std::byte>> pieces) {
    std::size_t unwritten = totalSize(pieces);
    for (const auto& piece : pieces) {
        std::span<const std::byte> rest = piece;
        while (!rest.empty()) {
            const ssize_t n = unlessInjected(IoCall::Write,
                                             [&] { return ::write(fd, rest.data(), rest.size()); });
            if (n < 0) {
                if (errno == EINTR) {
                    continue;
                }
                fail(path, errno, unwritten);
            }
            if (n == 0) {
                fail(path, ENOSPC, unwritten);
            }
            rest = rest.subspan(static_cast<std::size_t>(n));
            unwritten -= static_cast<std::size_t>(n);
        }
    }
}

void writeFileAtomically(const std::filesystem::path& path,
                         std::initializer_list<std::span<const std::byte>> pieces) {
    std::filesystem::path temp;
    int fd = createTemporary(path, totalSize(pieces), temp);
    const auto discard = [&] {
        if (fd >= 0) {
            ::close(fd);
            fd = -1;
        }
        ::unlink(temp.c_str());
    };
    try {
        writeAllTo(fd, path, pieces);
        // Delayed allocation can report a full disk only here, at fsync or close.
        if (unlessInjected(IoCall::Sync, [&] { return ::fsync(fd); }) != 0) {
            fail(path, errno, totalSize(pieces));
        }
        const int rc = ::close(fd);
        fd = -1;
        if (rc != 0) {
            fail(path, errno, totalSize(pieces));
        }
        if (unlessInjected(IoCall::Rename, [&] { return ::rename(temp.c_str(), path.c_str()); }) !=
            0) {
            fail(path, errno, 0);
        }
    } catch (...) {
        discard();
        throw;
    }
    syncFolder(path);
}

} // namespace steerseg::files
