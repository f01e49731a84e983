#include "render/slice_view.hpp"

#include "common/bindings.h"
#include "gpu/gl_error.hpp"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <string_view>

namespace steerseg::render {

int glyphIndex(char side) {
    constexpr std::string_view kFont = "AILPRS";
    const auto at = kFont.find(side);
    return at == std::string_view::npos ? -1 : static_cast<int>(at);
}

SliceFrame SliceView::draw(const RenderInputs& in, const ViewParams& params) {
    const SliceFrame frame = sliceFrame(in.geometry, params);
    const GLuint program = program_.get(in.pool);
    glUseProgram(program);
    bindCommon(program, in, params);
    const glm::vec3 origin(frame.origin);
    const glm::vec3 right(frame.stepRight);
    const glm::vec3 down(frame.stepDown);
    glUniform3fv(uniform(program, "sliceOrigin"), 1, glm::value_ptr(origin));
    glUniform3fv(uniform(program, "sliceAxisU"), 1, glm::value_ptr(right));
    glUniform3fv(uniform(program, "sliceAxisV"), 1, glm::value_ptr(down));
    const bool showSpeed = params.content == SliceContent::Speed;
    glUniform1i(uniform(program, "showSpeed"), showSpeed ? 1 : 0);
    if (showSpeed) {
        speed::bindSpeedTextures(in.speed, in.scan.exact(), VIEW_SPEED_INTENSITY_UNIT,
                                 VIEW_SPEED_FACTOR_UNIT);
        glUniform1i(uniform(program, "speedKind"), static_cast<int>(in.speed.kind));
        glUniform1i(uniform(program, "classifyWithinWindow"), in.speed.withinWindow ? 1 : 0);
        glUniform1f(uniform(program, "T"), static_cast<float>(params.speed.T));
        glUniform1f(uniform(program, "eps"), static_cast<float>(params.speed.eps));
        // Full colour at |D| = eps for the speeds in the scan's units, at 1 for classify's.
        const bool unitless = in.speed.kind == model::SpeedKind::Classify;
        glUniform1f(uniform(program, "speedScale"),
                    unitless ? 1.0F : static_cast<float>(std::max(params.speed.eps, 1e-6)));
    }
    glUniform1i(uniform(program, "showContour"), params.contour ? 1 : 0);
    if (params.labels) {
        glUniform4i(uniform(program, "labelGlyphs"), glyphIndex(frame.labels[0]),
                    glyphIndex(frame.labels[1]), glyphIndex(frame.labels[2]),
                    glyphIndex(frame.labels[3]));
    } else {
        glUniform4i(uniform(program, "labelGlyphs"), -1, -1, -1, -1);
    }
    glUniform1i(uniform(program, "labelScale"),
                std::max(1, std::min(params.size.x, params.size.y) / 160));
    dispatchRegion(program, params);
    gpu::checkGl("drawing a slice view");
    return frame;
}

} // namespace steerseg::render
