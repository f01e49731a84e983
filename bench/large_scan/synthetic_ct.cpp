#include "bench/large_scan/synthetic_ct.hpp"

#include <cstdint>
#include <gdcmAttribute.h>
#include <gdcmImageWriter.h>
#include <gdcmUIDGenerator.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::bench {

namespace {

// Deterministic noise in [-15, 15] HU per voxel.
int noise(std::uint32_t n) {
    n ^= n >> 16;
    n *= 0x7feb352dU;
    n ^= n >> 15;
    n *= 0x846ca68bU;
    n ^= n >> 16;
    return static_cast<int>(n % 31U) - 15;
}

} // namespace

void writeSyntheticCt(SyntheticCt& ct, const std::filesystem::path& dir) {
    const glm::ivec3 d = ct.dims;
    ct.lesionCentre = glm::dvec3(0.6 * d.x, 0.45 * d.y, 0.5 * d.z);
    ct.lesionRadius = 0.06 * d.x;
    // The lesion is a ball in millimetres: its radius along k in slices follows the spacing.
    const double rk = ct.lesionRadius * ct.spacing.x / ct.spacing.z;
    gdcm::UIDGenerator uid;
    const std::string study = uid.Generate();
    const std::string series = uid.Generate();
    const std::string frame = uid.Generate();
    std::vector<std::int16_t> slice(static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y));
    ct.lesionVoxels = 0;
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                const double ex = (i - 0.5 * d.x) / (0.42 * d.x);
                const double ey = (j - 0.5 * d.y) / (0.32 * d.y);
                const glm::dvec3 q = (glm::dvec3(i, j, k) - ct.lesionCentre) /
                                     glm::dvec3(ct.lesionRadius, ct.lesionRadius, rk);
                int hu = -1000;
                if (glm::dot(q, q) <= 1.0) {
                    hu = 120;
                    ++ct.lesionVoxels;
                } else if (ex * ex + ey * ey <= 1.0) {
                    hu = 40;
                }
                const auto n = static_cast<std::uint32_t>(i + d.x * (j + d.y * k));
                slice[static_cast<std::size_t>(i) +
                      static_cast<std::size_t>(d.x) * static_cast<std::size_t>(j)] =
                    static_cast<std::int16_t>(hu + noise(n) + 1024);
            }
        }
        gdcm::ImageWriter writer;
        gdcm::Image& image = writer.GetImage();
        image.SetNumberOfDimensions(2);
        image.SetDimension(0, static_cast<unsigned int>(d.x));
        image.SetDimension(1, static_cast<unsigned int>(d.y));
        image.SetPixelFormat(gdcm::PixelFormat::INT16);
        image.SetPhotometricInterpretation(gdcm::PhotometricInterpretation::MONOCHROME2);
        image.SetSpacing(0, ct.spacing.x);
        image.SetSpacing(1, ct.spacing.y);
        image.SetSpacing(2, ct.spacing.z);
        const double origin[3] = {-0.5 * d.x * ct.spacing.x, -0.5 * d.y * ct.spacing.y,
                                  k * ct.spacing.z};
        image.SetOrigin(origin);
        image.SetOrigin(2, origin[2]); // a 2D image's origin keeps only x and y otherwise
        const double cosines[6] = {1, 0, 0, 0, 1, 0};
        image.SetDirectionCosines(cosines);
        image.SetIntercept(-1024.0);
        image.SetSlope(1.0);
        gdcm::DataElement pixels(gdcm::Tag(0x7fe0, 0x0010));
        pixels.SetByteValue(reinterpret_cast<const char*>(slice.data()),
                            gdcm::VL(static_cast<std::uint32_t>(slice.size() * 2)));
        image.SetDataElement(pixels);
        gdcm::DataSet& ds = writer.GetFile().GetDataSet();
        const auto text = [&ds](std::uint16_t g, std::uint16_t e, const std::string& value,
                                gdcm::VR vr) {
            gdcm::DataElement de(gdcm::Tag(g, e));
            de.SetVR(vr);
            std::string v = value;
            if (v.size() % 2 != 0) {
                v.push_back(vr == gdcm::VR::UI ? '\0' : ' ');
            }
            de.SetByteValue(v.data(), gdcm::VL(static_cast<std::uint32_t>(v.size())));
            ds.Replace(de);
        };
        text(0x0008, 0x0016, "1.2.840.10008.5.1.4.1.1.2", gdcm::VR::UI); // CT Image Storage
        text(0x0008, 0x0018, uid.Generate(), gdcm::VR::UI);
        text(0x0008, 0x0060, "CT", gdcm::VR::CS);
        text(0x0010, 0x0010, "Synthetic^Large", gdcm::VR::PN);
        text(0x0020, 0x000d, study, gdcm::VR::UI);
        text(0x0020, 0x000e, series, gdcm::VR::UI);
        text(0x0020, 0x0052, frame, gdcm::VR::UI);
        text(0x0020, 0x0013, std::to_string(k + 1), gdcm::VR::IS);
        // The geometry and rescale as text too: gdcm's writer leaves them out of a dataset it
        // did not read.
        char buf[128];
        std::snprintf(buf, sizeof buf, "%.4f\\%.4f\\%.4f", origin[0], origin[1], origin[2]);
        text(0x0020, 0x0032, buf, gdcm::VR::DS);
        text(0x0020, 0x0037, "1\\0\\0\\0\\1\\0", gdcm::VR::DS);
        std::snprintf(buf, sizeof buf, "%.4f\\%.4f", ct.spacing.y, ct.spacing.x);
        text(0x0028, 0x0030, buf, gdcm::VR::DS);
        std::snprintf(buf, sizeof buf, "%.4f", ct.spacing.z);
        text(0x0018, 0x0050, buf, gdcm::VR::DS);
        text(0x0028, 0x0004, "MONOCHROME2", gdcm::VR::CS);
        text(0x0028, 0x1052, "-1024", gdcm::VR::DS);
        text(0x0028, 0x1053, "1", gdcm::VR::DS);
        char name[32];
        std::snprintf(name, sizeof name, "slice%04d.dcm", k);
        writer.SetFileName((dir / name).string().c_str());
        if (!writer.Write()) {
            throw std::runtime_error("cannot write " + (dir / name).string());
        }
    }
}

} // namespace steerseg::bench
