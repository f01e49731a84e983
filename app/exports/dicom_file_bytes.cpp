#include "exports/dicom_file_bytes.hpp"

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

} // namespace steerseg::exports
