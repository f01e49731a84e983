#include "bench/bench_scan.hpp"
#include "io/scan_reader.hpp"

namespace steerseg::bench {

Volume loadScan(const std::string& path) {
    return io::readScan(path).volume;
}

void saveImage(const std::filesystem::path& path, const render::RgbaImage& image) {
    render::writeImage(path, image);
}

} // namespace steerseg::bench
