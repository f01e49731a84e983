#include "bench/bench_scan.hpp"
#include "core/sample_phantom.hpp"

#include <stdexcept>

namespace steerseg::bench {

Volume loadScan(const std::string& path) {
    if (path != "builtin:sample") {
        throw std::runtime_error(path + ": this benchmark was built without the scan readers "
                                        "(STEERSEG_BENCH_IO=OFF); only builtin:sample is read");
    }
    return makeSamplePhantom();
}

void saveImage(const std::filesystem::path& path, const RgbaImage&) {
    throw std::runtime_error(path.string() + ": this benchmark was built without the image "
                                             "writer (STEERSEG_BENCH_IO=OFF)");
}

} // namespace steerseg::bench
