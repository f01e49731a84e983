#include "render/volume_view.hpp"

#include "common/bindings.h"
#include "gpu/gl_error.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>

namespace steerseg::render {

namespace {

bool sameTransfer(const TransferFunction& a, const TransferFunction& b) {
    if (a.gradientScale != b.gradientScale || a.widgets.size() != b.widgets.size()) {
        return false;
    }
    for (std::size_t n = 0; n < a.widgets.size(); ++n) {
        const TfWidget& x = a.widgets[n];
        const TfWidget& y = b.widgets[n];
        if (x.centre != y.centre || x.halfWidth != y.halfWidth || x.minGradient != y.minGradient ||
            x.colour != y.colour || x.opacity != y.opacity) {
            return false;
        }
    }
    return true;
}

// The data term whose zero crossing places the surface between voxels (render/
// surface_smooth.glsl), the solver's own textures.
void bindSurfaceSpeed(GLuint program, const RenderInputs& in, const SpeedParams& speed) {
    glUniform1i(uniform(program, "surfaceFromData"), speed.placesSurface ? 1 : 0);
    if (!speed.placesSurface) {
        return;
    }
    speed::bindSpeedTextures(in.speed, in.scan.exact(), VIEW_SURFACE_INTENSITY_UNIT,
                             VIEW_SURFACE_FACTOR_UNIT);
    glUniform1i(uniform(program, "speedKind"), static_cast<int>(in.speed.kind));
    glUniform1i(uniform(program, "classifyWithinWindow"), in.speed.withinWindow ? 1 : 0);
    glUniform1f(uniform(program, "T"), static_cast<float>(speed.T));
    glUniform1f(uniform(program, "eps"), static_cast<float>(speed.eps));
}

} // namespace

VolumeView::VolumeView() {
    lut_ = gpu::createTexture();
    glActiveTexture(GL_TEXTURE0 + VIEW_TF_LUT_UNIT);
    glBindTexture(GL_TEXTURE_2D, lut_.id());
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, kTfIntensityBins, kTfGradientBins);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    occupancy_ = gpu::createTexture();
    glActiveTexture(GL_TEXTURE0 + VIEW_OCCUPANCY_UNIT);
    glBindTexture(GL_TEXTURE_2D, occupancy_.id());
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_R32F, kTfIntensityBins + 1, kTfGradientBins + 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gpu::checkGl("creating the transfer function textures");
}

void VolumeView::bakeTransfer(const gpu::ScanTexture& scan, const TransferFunction& tf) {
    if (haveBaked_ && sameTransfer(tf, baked_)) {
        return;
    }
    const std::vector<std::uint8_t> lut = bakeTransferLut(tf, scan.rangeMin(), scan.rangeMax());
    const std::vector<float> occupancy = occupancyTable(lut);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glActiveTexture(GL_TEXTURE0 + VIEW_TF_LUT_UNIT);
    glBindTexture(GL_TEXTURE_2D, lut_.id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kTfIntensityBins, kTfGradientBins, GL_RGBA,
                    GL_UNSIGNED_BYTE, lut.data());
    glActiveTexture(GL_TEXTURE0 + VIEW_OCCUPANCY_UNIT);
    glBindTexture(GL_TEXTURE_2D, occupancy_.id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kTfIntensityBins + 1, kTfGradientBins + 1, GL_RED,
                    GL_FLOAT, occupancy.data());
    gpu::checkGl("uploading the transfer function");
    baked_ = tf;
    haveBaked_ = true;
}

void VolumeView::draw(const RenderInputs& in, const ViewParams& params) {
    bakeTransfer(in.scan, params.transfer);
    if (in.pool != nullptr) {
        bandBounds_.update(*in.pool);
    }
    const GLuint program =
        programs_[in.pool != nullptr ? 1 : 0][in.gradient != 0 ? 1 : 0].get(in.pool);
    glUseProgram(program);
    bindCommon(program, in, params);
    if (in.gradient != 0) {
        glActiveTexture(GL_TEXTURE0 + VIEW_GRADIENT_UNIT);
        glBindTexture(GL_TEXTURE_3D, in.gradient);
    }
    if (in.pool != nullptr) {
        bindSurfaceSpeed(program, in, params.speed);
    }
    glActiveTexture(GL_TEXTURE0 + VIEW_TF_LUT_UNIT);
    glBindTexture(GL_TEXTURE_2D, lut_.id());
    glActiveTexture(GL_TEXTURE0 + VIEW_SKIP_GRID_UNIT);
    glBindTexture(GL_TEXTURE_3D, in.skip.texture());
    glActiveTexture(GL_TEXTURE0 + VIEW_OCCUPANCY_UNIT);
    glBindTexture(GL_TEXTURE_2D, occupancy_.id());

    const Geometry& g = in.geometry;
    const glm::dmat3 indexToWorld =
        g.direction * glm::dmat3(glm::dvec3(g.spacing.x, 0, 0), glm::dvec3(0, g.spacing.y, 0),
                                 glm::dvec3(0, 0, g.spacing.z));
    const glm::dmat3 worldToIndex = glm::inverse(indexToWorld);
    const Camera& cam = params.camera;
    const glm::vec3 eyeIndex(worldToIndex * (cam.eye() - g.origin));
    const double aspect = static_cast<double>(params.size.x) / params.size.y;
    const double t = std::tan(glm::radians(cam.fovYDegrees()) * 0.5);
    const glm::vec3 forward(cam.forward());
    const glm::vec3 right(cam.right() * (t * aspect));
    const glm::vec3 up(cam.up() * t);
    const glm::mat3 w2i(worldToIndex);
    glUniform3fv(uniform(program, "eyeIndex"), 1, glm::value_ptr(eyeIndex));
    glUniformMatrix3fv(uniform(program, "worldToIndex"), 1, GL_FALSE, glm::value_ptr(w2i));
    glUniform3fv(uniform(program, "camForward"), 1, glm::value_ptr(forward));
    glUniform3fv(uniform(program, "camRight"), 1, glm::value_ptr(right));
    glUniform3fv(uniform(program, "camUp"), 1, glm::value_ptr(up));
    const double minSpacing = std::min({g.spacing.x, g.spacing.y, g.spacing.z});
    glUniform1f(uniform(program, "stepMm"), static_cast<float>(0.5 * minSpacing));
    glUniform1f(uniform(program, "gradientScale"),
                static_cast<float>(std::max(params.transfer.gradientScale, 1e-6)));
    glUniform1i(uniform(program, "surfaceMode"), static_cast<int>(params.surface));
    glUniform1i(uniform(program, "roiMode"), static_cast<int>(params.roi));
    glUniform1f(uniform(program, "dimFactor"), params.dimFactor);
    glUniform1i(uniform(program, "clipEnabled"), params.clip.enabled ? 1 : 0);
    glUniform4f(uniform(program, "clipPlane"), static_cast<float>(params.clip.normal.x),
                static_cast<float>(params.clip.normal.y), static_cast<float>(params.clip.normal.z),
                static_cast<float>(params.clip.d));
    // About one pixel's footprint at the target, in voxels, but never thinner than a voxel's
    // worth of phi so the line stays closed.
    const double pixelMm = 2.0 * cam.distance() * t / params.size.y;
    const double lineVoxels = std::max(0.6, 0.9 * pixelMm / minSpacing);
    glUniform1f(uniform(program, "lineWidth"), static_cast<float>(lineVoxels));
    dispatchRegion(program, params);
    gpu::checkGl("drawing the 3D view");
}

} // namespace steerseg::render
