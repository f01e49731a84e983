#include "fuzz_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return steerseg::fuzz::runReader(data, size, [](auto& source, const auto& limits) {
        return steerseg::scan::readMetaImageFrom("fuzz.mha", source, limits);
    });
}
