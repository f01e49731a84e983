#include "exports/label_description.hpp"

#include "files/file_error.hpp"
#include "files/file_write.hpp"
#include "model/file_name.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

namespace steerseg::exports {

namespace {

// ITK-SNAP's own header, so that its reader and the tools that copy its format recognise it.
constexpr const char* kHeader = "################################################\n"
                                "# ITK-SnAP Label Description File\n"
                                "# File format: \n"
                                "# IDX   -R-  -G-  -B-  -A--  VIS MSH  LABEL\n"
                                "# Fields: \n"
                                "#    IDX:   Zero-based index \n"
                                "#    -R-:   Red color component (0..255)\n"
                                "#    -G-:   Green color component (0..255)\n"
                                "#    -B-:   Blue color component (0..255)\n"
                                "#    -A-:   Label transparency (0.00 .. 1.00)\n"
                                "#    VIS:   Label visibility (0 or 1)\n"
                                "#    IDX:   Label mesh visibility (0 or 1)\n"
                                "#  LABEL:   Label description \n"
                                "################################################\n";

std::string row(int index, const glm::ivec3& rgb, int alpha, int visible, const std::string& name) {
    std::array<char, 96> text{};
    std::snprintf(text.data(), text.size(), "%5d %5d %4d %4d %8d %2d %2d    \"", index, rgb.r,
                  rgb.g, rgb.b, alpha, visible, visible);
    std::string quoted = name;
    std::replace(quoted.begin(), quoted.end(), '"', '\''); // the format has no escape
    return text.data() + quoted + "\"\n";
}

int byteOf(double component) {
    return static_cast<int>(std::lround(std::clamp(component, 0.0, 1.0) * 255.0));
}

} // namespace

std::filesystem::path labelDescriptionPathFor(const std::filesystem::path& labelMapPath) {
    const std::string lower = model::lowerFileName(labelMapPath);
    std::string name = labelMapPath.string();
    for (const char* suffix : {".nii.gz", ".nii", ".nrrd"}) {
        if (model::hasSuffix(lower, suffix)) {
            name.resize(name.size() - std::string(suffix).size());
            break;
        }
    }
    return name + ".label.txt";
}

void writeLabelDescription(const std::filesystem::path& path, std::span<const SegmentInfo> labels) {
    std::string text = kHeader;
    text += row(0, glm::ivec3(0), 0, 0, "Clear Label");
    for (const SegmentInfo& s : labels) {
        text +=
            row(s.label, {byteOf(s.color.r), byteOf(s.color.g), byteOf(s.color.b)}, 1, 1, s.name);
    }
    files::writeFileAtomically(path, {std::as_bytes(std::span(text))});
}

std::vector<DescribedLabel> readLabelDescription(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) {
        throw std::runtime_error(path.string() + ": cannot be read");
    }
    std::vector<DescribedLabel> labels;
    std::set<int> seen;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const auto fail = [&](const std::string& why) {
            throw std::runtime_error(path.string() + " line " + std::to_string(number) + ": " +
                                     why);
        };
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') {
            continue;
        }
        std::istringstream row(line);
        long long value = 0;
        std::array<double, 6> fields{}; // R G B A VIS MSH
        row >> value;
        for (double& f : fields) {
            row >> f;
        }
        const std::size_t open = line.find('"');
        const std::size_t close = line.rfind('"');
        if (!row || open == std::string::npos || close == open) {
            fail("not a label row (seven numbers, then the name in double quotes)");
        }
        if (value < 0 || value > 65535) {
            fail("label " + std::to_string(value) + " is outside 0..65535");
        }
        if (!seen.insert(static_cast<int>(value)).second) {
            fail("label " + std::to_string(value) + " is named twice");
        }
        if (value != 0) {
            labels.push_back({static_cast<int>(value), line.substr(open + 1, close - open - 1)});
        }
    }
    return labels;
}

} // namespace steerseg::exports
