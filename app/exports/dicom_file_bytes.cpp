#include "exports/dicom_file_bytes.hpp"

#include "files/file_error.hpp"

#include <dcmtk/dcmdata/dcostrmb.h>

namespace steerseg::exports {

std::vector<std::byte> dicomFileBytes(DcmFileFormat& file, E_TransferSyntax xfer, std::size_t chunk,
                                      OFCondition& status) {
    std::vector<char> buffer(chunk);
    DcmOutputBufferStream stream(buffer.data(), static_cast<offile_off_t>(buffer.size()));
    std::vector<std::byte> out;
    file.transferInit();
    do {
        status = file.write(stream, xfer, EET_ExplicitLength, nullptr, EGL_recalcGL, EPD_noChange,
                            0, 0, 0, EWM_createNewMeta);
        void* data = nullptr;
        offile_off_t length = 0;
        stream.flushBuffer(data, length);
        const auto* bytes = static_cast<const std::byte*>(data);
        out.insert(out.end(), bytes, bytes + length);
    } while (status == EC_StreamNotifyClient);
    file.transferEnd();
    return out;
}

std::vector<std::byte> encodeExportFile(const std::filesystem::path& path, DcmFileFormat& file,
                                        const char* what) {
    const E_TransferSyntax xfer = EXS_LittleEndianExplicit;
    const std::size_t estimate =
        file.getDataset()->calcElementLength(xfer, EET_ExplicitLength) + 64 * 1024;
    OFCondition c;
    std::vector<std::byte> out = dicomFileBytes(file, xfer, estimate, c);
    if (c.bad()) {
        throw files::WriteError(path, std::string(what) + ": encoding failed: " + c.text());
    }
    return out;
}

} // namespace steerseg::exports
