#pragma once

// A DICOM file encoded in memory (preamble, a new meta header, the data set), for
// files::writeFileAtomically: the SEG and report exports and the network node's incoming store
// share it.
#include <cstddef>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcxfer.h>
#include <filesystem>
#include <vector>

namespace steerseg::exports {

// `file` in `xfer`, `chunk` bytes encoded a pass at a time (the whole object in one pass builds
// the meta header once; a smaller chunk bounds the extra memory). `status` is DCMTK's result.
std::vector<std::byte> dicomFileBytes(DcmFileFormat& file, E_TransferSyntax xfer, std::size_t chunk,
                                      OFCondition& status);

// An export's object whole in explicit little endian (room for it in one pass, so the meta
// header is built once); files::WriteError naming `path` and `what` ("DICOM SEG") otherwise.
std::vector<std::byte> encodeExportFile(const std::filesystem::path& path, DcmFileFormat& file,
                                        const char* what);

} // namespace steerseg::exports
