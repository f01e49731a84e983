#include "bench/bench_scan.hpp"
#include "io/image_file.hpp"
#include "io/scan_reader.hpp"

namespace steerseg::bench {

Volume loadScan(const std::string& path) {
    return io::readScan(path).volume;
}

void saveImage(const std::filesystem::path& path, const RgbaImage& image) {
    io::writeImage(path, image);
}

} // namespace steerseg::bench
