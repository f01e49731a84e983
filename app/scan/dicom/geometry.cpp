#include "scan/dicom/geometry.hpp"

#include "scan/load_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace steerseg::scan {

namespace {

std::string mm(double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

std::string sliceNames(const SliceStackInput& in, const std::vector<std::size_t>& order,
                       std::size_t k) {
    return "slices " + std::to_string(k + 1) + " and " + std::to_string(k + 2) + ": " +
           in.names[order[k]] + ", " + in.names[order[k + 1]];
}

glm::dvec3 unit(const std::filesystem::path& where, const glm::dvec3& v, const char* what) {
    const double len = glm::length(v);
    if (!std::isfinite(len) || std::abs(len - 1.0) > 1e-2) {
        throw ScanError(where, std::string("ImageOrientationPatient ") + what +
                                   " direction is not a unit vector (length " + mm(len) + ")");
    }
    return v / len;
}

} // namespace

SliceStack stackSlices(const std::filesystem::path& where, const SliceStackInput& in) {
    const std::size_t n = in.positions.size();
    if (n == 0 || in.names.size() != n) {
        throw ScanError(where, "no slices to stack");
    }
    const glm::dvec3 row = unit(where, in.rowDirection, "row");
    const glm::dvec3 col = unit(where, in.columnDirection, "column");
    if (std::abs(glm::dot(row, col)) > 1e-2) {
        throw ScanError(where, "ImageOrientationPatient row and column directions are not "
                               "perpendicular");
    }
    const glm::dvec3 normal = glm::normalize(glm::cross(row, col));

    std::vector<double> along(n);
    for (std::size_t s = 0; s < n; ++s) {
        along[s] = glm::dot(in.positions[s], normal);
    }
    SliceStack out;
    out.order.resize(n);
    std::iota(out.order.begin(), out.order.end(), std::size_t{0});
    std::stable_sort(out.order.begin(), out.order.end(),
                     [&](std::size_t a, std::size_t b) { return along[a] < along[b]; });

    double spacing = in.singleSliceSpacing;
    if (n > 1) {
        std::vector<double> steps(n - 1);
        for (std::size_t k = 0; k + 1 < n; ++k) {
            steps[k] = along[out.order[k + 1]] - along[out.order[k]];
            if (steps[k] < kDuplicateSliceMm) {
                throw ScanError(where, "two slices at the same position (" +
                                           mm(along[out.order[k]]) + " mm along the normal, " +
                                           sliceNames(in, out.order, k) + ")");
            }
        }
        spacing = (along[out.order[n - 1]] - along[out.order[0]]) / static_cast<double>(n - 1);
        const double slack = kSpacingSlackRelative * spacing + kPositionSlackMm;
        std::size_t worst = 0;
        for (std::size_t k = 0; k + 1 < n; ++k) {
            if (std::abs(steps[k] - spacing) > std::abs(steps[worst] - spacing)) {
                worst = k;
            }
        }
        if (std::abs(steps[worst] - spacing) > slack) {
            const auto [lo, hi] = std::minmax_element(steps.begin(), steps.end());
            throw ScanError(where, "uneven slice spacing: " + mm(*lo) + " to " + mm(*hi) + " mm (" +
                                       mm(steps[worst]) + " mm between " +
                                       sliceNames(in, out.order, worst) +
                                       "; missing or extra slices?)");
        }

        // Slices must lie on the line through the first one along the normal; a gantry tilt
        // (or a shifted slice) moves them sideways and a rectilinear grid would misplace them.
        const glm::dvec3 first = in.positions[out.order[0]];
        const auto sideways = [&](std::size_t k) {
            const glm::dvec3 d = in.positions[out.order[k]] - first;
            return d - glm::dot(d, normal) * normal;
        };
        double drift = 0.0;
        double worstAngle = 0.0;
        std::size_t worstStep = 0;
        for (std::size_t k = 0; k + 1 < n; ++k) {
            drift = std::max(drift, glm::length(sideways(k + 1)));
            const double step = glm::length(sideways(k + 1) - sideways(k));
            const double angle = std::atan2(step, steps[k]) * 180.0 / 3.14159265358979323846;
            if (angle > worstAngle) {
                worstAngle = angle;
                worstStep = k;
            }
        }
        const double allowed =
            kSidewaysDriftPixels * std::min(in.pixelSpacing.x, in.pixelSpacing.y);
        if (drift > allowed) {
            const double step = glm::length(sideways(worstStep + 1) - sideways(worstStep));
            throw ScanError(
                where, "gantry tilt of " + mm(worstAngle) + " degrees: slice positions step " +
                           mm(step) + " mm sideways of the slice normal between " +
                           sliceNames(in, out.order, worstStep) + " (drift up to " + mm(drift) +
                           " mm); a regular grid would misplace them, resample the "
                           "series to remove the tilt first");
        }
    }

    Geometry& g = out.geometry;
    g.dims = glm::ivec3(in.size.x, in.size.y, static_cast<int>(n));
    g.spacing = glm::dvec3(in.pixelSpacing.x, in.pixelSpacing.y, spacing);
    g.origin = in.positions[out.order[0]];
    g.direction = glm::dmat3(row, col, normal);
    checkGeometry(where, g);
    return out;
}

} // namespace steerseg::scan
