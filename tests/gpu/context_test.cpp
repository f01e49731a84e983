#include "gpu/gl_error.hpp"
#include "gpu/gl_handle.hpp"
#include "gpu/gpu_info.hpp"
#include "gpu/program.hpp"
#include "gpu/shader_library.hpp"
#include "platform/null/null_context.hpp"
#include "support/gpu_fixture.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::test {
namespace {

class ContextTest : public GpuTest {};

// The tests' own shader: validated by glslang at build time (tests/gpu/CMakeLists.txt) but not
// embedded in the product.
std::string testShader() {
    std::ifstream in(STEERSEG_TEST_SHADER_DIR "/square.comp");
    std::stringstream text;
    text << in.rdbuf();
    if (!in || text.str().empty()) {
        throw std::runtime_error(STEERSEG_TEST_SHADER_DIR "/square.comp: cannot read");
    }
    return text.str();
}

TEST_F(ContextTest, ReportsEs31OrNewerWithComputeLimits) {
    const gpu::GpuInfo info = gpu::queryGpuInfo();
    EXPECT_NE(info.renderer, "");
    EXPECT_EQ(info.version.rfind("OpenGL ES 3.", 0), 0U) << info.version;
    EXPECT_GE(info.maxComputeWorkGroupInvocations, 128);
    EXPECT_GE(info.maxComputeShaderStorageBlocks, 4);
    EXPECT_GE(info.max3dTextureSize, 256);
}

TEST(CpuRasterizerLanes, ReadsLlvmpipesVectorWidthAndNothingElsesRenderer) {
    EXPECT_EQ(gpu::cpuRasterizerLanes("llvmpipe (LLVM 15.0.6, 256 bits)"), 8);
    EXPECT_EQ(gpu::cpuRasterizerLanes("llvmpipe (LLVM 12.0.0, 128 bits)"), 4);
    EXPECT_EQ(gpu::cpuRasterizerLanes("llvmpipe (LLVM 17.0.6, 512 bits)"), 16);
    EXPECT_EQ(gpu::cpuRasterizerLanes("llvmpipe"), 0);
    EXPECT_EQ(gpu::cpuRasterizerLanes("llvmpipe (LLVM 15.0.6,  bits)"), 0);
    EXPECT_EQ(gpu::cpuRasterizerLanes("llvmpipe (LLVM 15.0.6, 99999999999 bits)"), 0);
    EXPECT_EQ(gpu::cpuRasterizerLanes("NVIDIA H200/PCIe/SSE2"), 0);
    EXPECT_EQ(gpu::cpuRasterizerLanes("Mali-G52 (256 bits)"), 0);
    EXPECT_EQ(gpu::cpuRasterizerLanes(""), 0);
}

TEST_F(ContextTest, RunsComputeShaderAndReadsResultBack) {
    constexpr GLuint kCount = 1000; // not a multiple of the work-group size on purpose
    std::vector<float> input(kCount);
    for (GLuint n = 0; n < kCount; ++n) {
        input[n] = static_cast<float>(n) * 0.5F;
    }
    gpu::Program program = gpu::buildComputeProgramFromSource("square.comp", testShader());
    gpu::Buffer in = gpu::createBuffer(GL_SHADER_STORAGE_BUFFER, kCount * sizeof(float),
                                       input.data(), GL_STATIC_DRAW);
    gpu::Buffer out = gpu::createBuffer(GL_SHADER_STORAGE_BUFFER, (kCount + 64) * sizeof(float),
                                        nullptr, GL_DYNAMIC_READ);
    // Sentinel past the end: the shader must not write beyond `count`.
    std::vector<float> sentinel(kCount + 64, -1.0F);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, out.id());
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0,
                    static_cast<GLsizeiptr>(sentinel.size() * sizeof(float)), sentinel.data());
    glUseProgram(program.id());
    glUniform1f(glGetUniformLocation(program.id(), "offset"), 3.0F);
    glUniform1ui(glGetUniformLocation(program.id(), "count"), kCount);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glDispatchCompute((kCount + 63) / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gpu::checkGl("dispatch");
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, out.id());
    const auto* mapped = static_cast<const float*>(
        glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0,
                         static_cast<GLsizeiptr>((kCount + 64) * sizeof(float)), GL_MAP_READ_BIT));
    ASSERT_NE(mapped, nullptr);
    for (GLuint n = 0; n < kCount; ++n) {
        ASSERT_FLOAT_EQ(mapped[n], input[n] * input[n] + 3.0F) << "at " << n;
    }
    for (GLuint n = kCount; n < kCount + 64; ++n) {
        ASSERT_FLOAT_EQ(mapped[n], -1.0F) << "wrote past the end at " << n;
    }
    glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
}

TEST_F(ContextTest, ShaderLibraryHasTheProductsShadersOnly) {
    EXPECT_TRUE(gpu::findShaderSource("solver/update_phi.comp").has_value());
    EXPECT_TRUE(gpu::findShaderSource("render/raycast.comp").has_value());
    EXPECT_TRUE(gpu::findShaderSource("kiosk/present.frag").has_value());
    for (const std::string_view name : gpu::shaderNames()) {
        // The kiosk's screen compositor (app/kiosk/screen_compositor.cpp) has its own pair;
        // gpu/ holds the texture read-back (app/gpu/texture_readback.cpp).
        EXPECT_TRUE(name.rfind("solver/", 0) == 0 || name.rfind("render/", 0) == 0 ||
                    name.rfind("kiosk/", 0) == 0 || name.rfind("speed/", 0) == 0 ||
                    name.rfind("gpu/", 0) == 0)
            << name;
    }
    EXPECT_THROW(gpu::buildComputeProgram("no/such.comp"), gpu::GlError);
}

TEST_F(ContextTest, DefinesGoAfterTheVersionLine) {
    const std::string s =
        gpu::withDefines("#version 310 es\nvoid main() {}\n", {{"BRICK_SIZE", "8"}});
    EXPECT_EQ(s, "#version 310 es\n#define BRICK_SIZE 8\nvoid main() {}\n");
}

TEST(NullPlatform, ProvidesNoGlAndNeedsNone) {
    const auto context = platform::createNullContext();
    EXPECT_EQ(context->backendName(), "null");
    EXPECT_FALSE(context->providesGl());
    context->makeCurrent();
}

TEST_F(ContextTest, OffscreenContextProvidesGl) {
    EXPECT_TRUE(context().providesGl());
}

TEST(OffscreenPlatform, RejectsUnknownPlatformName) {
    EXPECT_THROW(platform::parseOffscreenPlatform("x11"), platform::GpuContextError);
    EXPECT_EQ(platform::parseOffscreenPlatform("surfaceless"),
              platform::OffscreenPlatform::Surfaceless);
}

} // namespace
} // namespace steerseg::test
