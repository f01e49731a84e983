#include "bench/bench_scan.hpp"
#include "exports/image_file.hpp"
#include "scan/scan_reader.hpp"

namespace steerseg::bench {

Volume loadScan(const std::string& path) {
    return scan::readScan(path).volume;
}

void saveImage(const std::filesystem::path& path, const RgbaImage& image) {
    exports::writeImage(path, image);
}

} // namespace steerseg::bench
