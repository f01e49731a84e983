#include "exports/export_writer.hpp"

#include "exports/structure_export.hpp"

namespace steerseg::exports {

// One structure is the case of several with one: the same code writes both (docs/exports.md).
ExportSummary writeExport(const std::filesystem::path& path, model::ExportFormat format,
                          const ExportData& data) {
    StructureLayer structure;
    structure.segment = data.segment;
    structure.mask = data.mask;
    structure.phi = data.phi;
    return writeStructures(path, format, {data.geometry, {structure}, data.dicom, data.scan});
}

} // namespace steerseg::exports
