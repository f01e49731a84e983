// The autosave reader on arbitrary bytes (a file a crash or a bad disk left behind): it decodes
// or throws AutosaveFormatError, and what it decodes encodes back to the same snapshot.
#include "autosave/autosave_snapshot.hpp"

#include <cstdint>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace steerseg::autosave;
    AutosaveSnapshot s;
    try {
        s = decodeSnapshot(std::as_bytes(std::span<const std::uint8_t>(data, size)));
    } catch (const AutosaveFormatError&) {
        return 0;
    }
    const AutosaveSnapshot again = decodeSnapshot(encodeSnapshot(s));
    if (again.mask.runs != s.mask.runs || again.mask.voxels != s.mask.voxels ||
        again.dims != s.dims || again.state != s.state || again.params != s.params ||
        again.scan != s.scan || again.barriers != s.barriers) {
        __builtin_trap();
    }
    return 0;
}
