#pragma once

// Where a benchmark gets its scan and where it puts its pictures. Two builds: with every scan
// reader and the image writer (bench_scan_io.cpp, the default), or with the light set
// (bench_scan_light.cpp, STEERSEG_BENCH_IO=OFF) for the lent GPU machine, which has no package
// registry and so no OpenImageIO or GDCM: there the built-in sample and NIfTI are read, and
// pictures are written as PPM.
#include "core/rgba_image.hpp"
#include "core/volume.hpp"

#include <filesystem>
#include <string>

namespace steerseg::bench {

// The scan at `path` (a file, a folder or "builtin:sample"). Throws std::runtime_error.
Volume loadScan(const std::string& path);

// Writes a PNG, or without the image writer (STEERSEG_BENCH_IO=OFF) a PPM beside the name.
// Throws std::runtime_error.
void saveImage(const std::filesystem::path& path, const RgbaImage& image);

// The volume resampled by `factor` on each axis (trilinear, same world extent), so the
// renderer and solver can be timed at scan sizes no file at hand has. factor 1 returns a copy.
Volume resampled(const Volume& scan, double factor);

} // namespace steerseg::bench
