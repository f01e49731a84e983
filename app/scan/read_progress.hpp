#pragma once

// How far a scan read has come, for a loader's progress bar: the bytes of scan files read on
// the calling thread (compressed bytes for .gz files; DICOM series, read by GDCM, do not count).
// A loader thread points it at its counter before reading; other threads read the counter.
#include <atomic>
#include <cstdint>

namespace steerseg::scan {

// Counts into `counter` the bytes this thread's file reads deliver, until set to null.
void countReadsInto(std::atomic<std::uint64_t>* counter);
void noteBytesRead(std::uint64_t bytes);

} // namespace steerseg::scan
