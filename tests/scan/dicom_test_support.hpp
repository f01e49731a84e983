#pragma once

// Helpers shared by the DICOM reader tests: expecting a ScanError, and editing DICOM files
// through GDCM to build hostile cases.
#include "scan/readers.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <gdcmReader.h>
#include <gdcmWriter.h>
#include <gtest/gtest.h>

namespace steerseg::test {

namespace fs = std::filesystem;
using scan::readDicom;
using scan::ScanError;

// The message of the ScanError `fn` throws; fails the test if it throws nothing or else.
inline std::string scanErrorOf(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const ScanError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected ScanError, got: " << e.what();
        return {};
    }
    ADD_FAILURE() << "expected ScanError, nothing thrown";
    return {};
}

inline std::vector<fs::path> filesIn(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir)) {
        files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// Rewrites a DICOM file after `edit` changed its data set.
inline void rewrite(const fs::path& in, const fs::path& out,
                    const std::function<void(gdcm::DataSet&)>& edit) {
    gdcm::Reader reader;
    reader.SetFileName(in.string().c_str());
    ASSERT_TRUE(reader.Read()) << in;
    edit(reader.GetFile().GetDataSet());
    gdcm::Writer writer;
    writer.SetFileName(out.string().c_str());
    writer.SetFile(reader.GetFile());
    ASSERT_TRUE(writer.Write()) << out;
}

inline void setText(gdcm::DataSet& ds, gdcm::Tag tag, gdcm::VR vr, std::string text) {
    if (text.size() % 2 != 0) {
        text += vr == gdcm::VR::UI ? '\0' : ' ';
    }
    gdcm::DataElement de(tag);
    de.SetVR(vr);
    de.SetByteValue(text.data(), gdcm::VL(static_cast<std::uint32_t>(text.size())));
    ds.Replace(de);
}

inline std::string positionText(const glm::dvec3& p) {
    char text[96];
    std::snprintf(text, sizeof text, "%.4f\\%.4f\\%.4f", p.x, p.y, p.z);
    return text;
}

} // namespace steerseg::test
