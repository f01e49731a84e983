#include "bench/bench_scan.hpp"
#include "core/sample_phantom.hpp"
#include "scan/readers.hpp"

#include <fstream>
#include <stdexcept>

namespace steerseg::bench {

// The built-in sample and NIfTI (nifticlib and zlib are small enough to carry to the GPU
// machine, unlike the image-stack and DICOM readers' libraries).
Volume loadScan(const std::string& path) {
    if (path == "builtin:sample") {
        return makeSamplePhantom();
    }
    if (path.ends_with(".nii") || path.ends_with(".nii.gz")) {
        std::string format;
        return scan::readNifti(path, scan::ReadLimits{}, format);
    }
    throw std::runtime_error(path + ": this benchmark was built with the light reader set "
                                    "(STEERSEG_BENCH_IO=OFF): builtin:sample and NIfTI only");
}

// Without OpenImageIO the pictures go out as binary PPM (RGB; alpha dropped), a format small
// enough to write here, so pictures drawn on the GPU machine can be compared with the
// development machine's (idiff reads both).
void saveImage(const std::filesystem::path& path, const RgbaImage& image) {
    std::filesystem::path ppm = path;
    ppm.replace_extension(".ppm");
    std::ofstream out(ppm, std::ios::binary);
    out << "P6\n" << image.width << " " << image.height << "\n255\n";
    for (std::size_t n = 0; n + 3 < image.pixels.size(); n += 4) {
        out.write(reinterpret_cast<const char*>(image.pixels.data() + n), 3);
    }
    if (!out) {
        throw std::runtime_error(ppm.string() + ": cannot write");
    }
}

} // namespace steerseg::bench
