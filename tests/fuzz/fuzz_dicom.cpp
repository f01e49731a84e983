// libFuzzer target for the DICOM reader: bytes -> temporary file -> scan::readDicom. Anything but
// a result or a ScanError (a crash, hang, other exception or sanitizer report) is a bug.
#include "fuzz_reader.hpp"

#include <cstdint>
#include <fstream>
#include <unistd.h>

// GDCM's codecs leak small buffers on some corrupt streams (JPEGLSCodec::Decode): not ours.
extern "C" const char* __lsan_default_suppressions() {
    return "leak:libgdcmMSFF.so\nleak:libgdcmDSED.so\nleak:libgdcmjpeg\nleak:libCharLS.so\nleak:"
           "libopenjp2.so\n";
}

extern "C" const char* __lsan_default_options() {
    return "print_suppressions=0";
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path file =
        std::filesystem::temp_directory_path() /
        ("steerseg-fuzz-dicom-" + std::to_string(::getpid()) + ".dcm");
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    try {
        const steerseg::Volume v = steerseg::scan::readDicom(file, steerseg::fuzz::fuzzLimits());
        (void)v.stats();
    } catch (const steerseg::scan::ScanError&) {
    }
    return 0;
}
