#pragma once

// GDCM 3.0.21 as Debian builds it keeps its assertions: a malformed compressed frame can make a
// codec assert and abort the whole process (fuzz_dicom keeps finding new ones in the JPEG,
// JPEG-LS and JPEG 2000 codecs). A crash on a bad file is not acceptable on the console, so
// compressed pixel data is decoded in a forked child: the child writes into a shared mapping and
// exits; if it dies instead, the parent reports the file as malformed and carries on. (An
// AddressSanitizer build with other threads running decodes in-process: its allocator is not
// fork-safe; isolated_decode.cpp says why.)
#include <cstddef>
#include <filesystem>
#include <functional>
#include <span>

namespace steerseg::scan {

// Runs decode(buffer) in a child process on a shared buffer of out.size() bytes and copies the
// result into `out`. Returns decode's result. Throws ScanError naming `file` if the child dies
// (a signal, an assertion) or runs past `timeoutSeconds`, or if no child can be started.
bool decodeIsolated(const std::filesystem::path& file, std::span<char> out,
                    const std::function<bool(char*)>& decode, int timeoutSeconds = 300);

} // namespace steerseg::scan
