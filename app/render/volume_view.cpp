#include "render/volume_view.hpp"

#include "common/bindings.h"
#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"
#include "render/render_bindings.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/gtc/type_ptr.hpp>
#include <string>
#include <vector>

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

void VolumeView::bakeTransfer(const gpu::ScanTexture& scan, const SkipGrid& skip,
                              const TransferFunction& tf) {
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
    // Which blocks the march may skip depends on the transfer function: decided here, once,
    // so the march reads one texel per block.
    tfVisible_ = skip.visibleBlocks(occupancy, std::max(tf.gradientScale, 1e-6));
    skipStale_ = true;
    gpu::checkGl("uploading the transfer function");
    baked_ = tf;
    haveBaked_ = true;
}

void VolumeView::updateSkipTexture(const SkipGrid& skip, const StructureLabels& labels) {
    if (!skipStale_ && labelsMerged_ == labels.uploads()) {
        return;
    }
    const glm::ivec3 grid = skip.dims();
    glActiveTexture(GL_TEXTURE0 + VIEW_SKIP_GRID_UNIT);
    if (!visibleBlocks_) {
        visibleBlocks_ = gpu::createTexture();
        glBindTexture(GL_TEXTURE_3D, visibleBlocks_.id());
        glTexStorage3D(GL_TEXTURE_3D, 1, GL_RG8, grid.x, grid.y, grid.z);
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glBindTexture(GL_TEXTURE_3D, visibleBlocks_.id());
    // Red: the march's verdict; green: the blocks the search for other structures stops in
    // (render/raycast.comp's searchLabel).
    const std::vector<std::uint8_t>& labelled = labels.blocks();
    std::vector<std::uint8_t> bytes(2 * tfVisible_.size());
    for (std::size_t b = 0; b < tfVisible_.size(); ++b) {
        bytes[2 * b] = tfVisible_[b] != 0 ? 255 : 0;
        bytes[2 * b + 1] = !labelled.empty() && labelled[b] != 0 ? 255 : 0;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, grid.x, grid.y, grid.z, GL_RG, GL_UNSIGNED_BYTE,
                    bytes.data());
    gpu::checkGl("uploading the skipping blocks");
    skipStale_ = false;
    labelsMerged_ = labels.uploads();
}

PoolProgram VolumeView::variant(int surface, int gradient, int labels, int surfacePass) {
    return PoolProgram{"render/raycast.comp",
                       {{"HAS_SURFACE", std::to_string(surface)},
                        {"GRADIENT_TEXTURE", std::to_string(gradient)},
                        {"HAS_LABELS", std::to_string(labels)},
                        {"SURFACE_PASS", std::to_string(surfacePass)}}};
}

void VolumeView::use(GLuint program, const RenderInputs& in, const ViewParams& params,
                     const StructureLabels* labels) {
    glUseProgram(program);
    bindCommon(program, in, params);
    if (labels != nullptr) {
        glActiveTexture(GL_TEXTURE0 + VIEW_LABELS_UNIT);
        glBindTexture(GL_TEXTURE_3D, labels->texture());
        const std::vector<glm::vec3>& colours = labels->colours();
        glUniform3fv(uniform(program, "labelColours"), static_cast<GLsizei>(colours.size()),
                     glm::value_ptr(colours.front()));
        const glm::ivec3 lo = labels->blockBoxLo();
        const glm::ivec3 hi = labels->blockBoxHi();
        glUniform3i(uniform(program, "labelBlocksLo"), lo.x, lo.y, lo.z);
        glUniform3i(uniform(program, "labelBlocksHi"), hi.x, hi.y, hi.z);
    }
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
    glBindTexture(GL_TEXTURE_3D, visibleBlocks_.id());
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
    glUniform1f(uniform(program, "skipBlock"), static_cast<float>(in.skip.blockSize()));
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
}

void VolumeView::draw(const RenderInputs& in, const ViewParams& params,
                      const StructureLabels& labels) {
    bakeTransfer(in.scan, in.skip, params.transfer);
    updateSkipTexture(in.skip, labels);
    const int gradient = in.gradient != 0 ? 1 : 0;
    const int others = labels.empty() ? 0 : 1;
    const StructureLabels* shown = labels.empty() ? nullptr : &labels;
    if (in.pool == nullptr) {
        const GLuint program = programs_[0][gradient][others].get(in.pool);
        use(program, in, params, shown);
        dispatchRegion(program, params);
        gpu::checkGl("drawing the 3D view");
        return;
    }
    bandBounds_.update(*in.pool);
    // Room for every pixel's hit, reset to no hits and an empty second dispatch.
    const std::size_t pixels =
        static_cast<std::size_t>(params.size.x) * static_cast<std::size_t>(params.size.y);
    if (!hits_ || hitCapacity_ < pixels) {
        hits_ = gpu::createBuffer(GL_SHADER_STORAGE_BUFFER,
                                  static_cast<GLsizeiptr>(kHitsHeader + kHitBytes * pixels),
                                  nullptr, GL_DYNAMIC_DRAW);
        hitCapacity_ = pixels;
    }
    const GLuint reset[4] = {0, 1, 1, 0};
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, hits_.id());
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(reset), reset);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, VIEW_SURFACE_HITS_BINDING, hits_.id());
    const GLuint program = programs_[1][gradient][others].get(in.pool);
    use(program, in, params, shown);
    dispatchRegion(program, params);
    if (params.surface == SurfaceMode::Opaque && params.roi == RoiMode::Off) {
        // The rays that hit the surface, listed by the first pass: refined and composited by
        // the second, for them only.
        gpu::memoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
        const GLuint refine = surfacePass_[gradient].get(in.pool);
        use(refine, in, params, nullptr);
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, hits_.id());
        gpu::dispatchComputeIndirect(0);
        gpu::memoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                           GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    }
    gpu::checkGl("drawing the 3D view");
}

} // namespace steerseg::render
