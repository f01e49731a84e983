#pragma once

// Shared body of the format fuzzers: run one reader over the input bytes in memory. A ScanError
// is the expected outcome for bad input; anything else (a crash, a sanitizer report, another
// exception) is a finding.
#include "scan/byte_source.hpp"
#include "scan/readers.hpp"

#include <cstddef>
#include <cstdint>

namespace steerseg::fuzz {

// Small caps keep each run fast and its memory low; the checks are the same at any size.
inline scan::ReadLimits fuzzLimits() {
    scan::ReadLimits limits;
    limits.maxVoxels = std::size_t{1} << 22;
    limits.maxDimension = 4096;
    limits.maxDataBytes = std::uint64_t{32} << 20;
    return limits;
}

template <typename Read> int runReader(const std::uint8_t* data, std::size_t size, Read read) {
    scan::MemorySource source({reinterpret_cast<const std::byte*>(data), size});
    try {
        const Volume v = read(source, fuzzLimits());
        (void)v.stats();
    } catch (const scan::ScanError&) {
    }
    return 0;
}

} // namespace steerseg::fuzz
