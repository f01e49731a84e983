// The GL state policy (gpu/gl_state_guard.hpp): every solver and renderer entry point restores
// the state it found and binds everything it reads. Solver, renderer, solver, renderer on one
// context must give what each gives alone, also when the caller leaves unrelated objects bound
// between the calls (as a UI drawing in the same context does).
#include "gpu/gl_handle.hpp"
#include "render/render_scene.hpp"
#include "render/renderer.hpp"
#include "solver/level_set_solver.hpp"
#include "support/gpu_fixture.hpp"

#include <vector>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class GlStatePolicy : public GpuTest {};

// Binds junk to every binding point the solver and renderer use: a program, SSBOs, textures,
// the dispatch-indirect buffer and image unit 0.
struct Clutter {
    Clutter() {
        buffer = gpu::createBuffer(GL_SHADER_STORAGE_BUFFER, 4096, nullptr, GL_STATIC_DRAW);
        texture2d = gpu::createTexture();
        glBindTexture(GL_TEXTURE_2D, texture2d.id());
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 4, 4);
        texture3d = gpu::createTexture();
    }
    void apply() const {
        for (GLuint b = 0; b < 12; ++b) {
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, buffer.id());
        }
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, buffer.id());
        for (GLenum unit : {GL_TEXTURE0, GL_TEXTURE1, GL_TEXTURE2, GL_TEXTURE3}) {
            glActiveTexture(unit);
            glBindTexture(GL_TEXTURE_2D, texture2d.id());
            glBindTexture(GL_TEXTURE_3D, texture3d.id());
        }
        glActiveTexture(GL_TEXTURE1);
        glBindImageTexture(0, texture2d.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
    }
    void expectStillBound() const {
        GLint value = 0;
        for (GLuint b = 0; b < 12; ++b) {
            glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, b, &value);
            EXPECT_EQ(static_cast<GLuint>(value), buffer.id()) << "SSBO binding " << b;
        }
        glGetIntegerv(GL_DISPATCH_INDIRECT_BUFFER_BINDING, &value);
        EXPECT_EQ(static_cast<GLuint>(value), buffer.id());
        glGetIntegerv(GL_ACTIVE_TEXTURE, &value);
        EXPECT_EQ(value, GL_TEXTURE1);
        for (GLenum unit : {GL_TEXTURE0, GL_TEXTURE1, GL_TEXTURE2, GL_TEXTURE3}) {
            glActiveTexture(unit);
            glGetIntegerv(GL_TEXTURE_BINDING_3D, &value);
            EXPECT_EQ(static_cast<GLuint>(value), texture3d.id()) << "unit " << unit - GL_TEXTURE0;
        }
        glActiveTexture(GL_TEXTURE1);
        glGetIntegeri_v(GL_IMAGE_BINDING_NAME, 0, &value);
        EXPECT_EQ(static_cast<GLuint>(value), texture2d.id());
    }
    gpu::Buffer buffer;
    gpu::Texture texture2d;
    gpu::Texture texture3d;
};

struct Outputs {
    std::vector<float> phiAfterFirst;
    std::vector<float> phiAfterSecond;
    RgbaImage first3d;
    RgbaImage secondAxial;
};

void seed(LevelSetSolver& solver) {
    solver.addSphere({glm::vec3(kHeadLesionCentre), 3.0F});
    solver.setParams({800.0F, 150.0F, 0.7F});
}

render::ViewParams view(const render::Renderer& r, render::ViewKind kind) {
    render::ViewParams p = r.defaultParams(kind, {48, 40});
    p.slice = static_cast<int>(kHeadLesionCentre.z);
    p.surface = render::SurfaceMode::Opaque;
    return p;
}

TEST_F(GlStatePolicy, SolverAndRendererInterleavedMatchEachAlone) {
    const Volume scan = makeHeadScene();
    const gpu::ScanTexture texture(scan);

    // The solver alone.
    Outputs alone;
    {
        LevelSetSolver solver(texture);
        seed(solver);
        solver.step(12);
        alone.phiAfterFirst = solver.readPhi();
        solver.step(12);
        alone.phiAfterSecond = solver.readPhi();
    }
    // The renderer alone, on level sets made by a solver that finished before it was built.
    {
        LevelSetSolver solver(texture);
        seed(solver);
        solver.step(12);
        render::Renderer renderer(scan, texture);
        const BrickPoolView pool = solver.poolView();
        renderer.render(view(renderer, render::ViewKind::Volume3d), &pool);
        alone.first3d = renderer.readback();
    }
    // Interleaved on one context, with the caller's clutter bound before every call.
    const Clutter clutter;
    Outputs mixed;
    LevelSetSolver solver(texture);
    render::Renderer renderer(scan, texture);
    clutter.apply();
    seed(solver);
    clutter.expectStillBound();
    solver.step(12);
    clutter.expectStillBound();
    mixed.phiAfterFirst = solver.readPhi();
    const BrickPoolView pool = solver.poolView();
    renderer.render(view(renderer, render::ViewKind::Volume3d), &pool);
    clutter.expectStillBound();
    mixed.first3d = renderer.readback();
    solver.step(12);
    clutter.expectStillBound();
    mixed.phiAfterSecond = solver.readPhi();
    const BrickPoolView after = solver.poolView();
    renderer.render(view(renderer, render::ViewKind::Axial), &after);
    clutter.expectStillBound();
    mixed.secondAxial = renderer.readback();

    EXPECT_EQ(mixed.phiAfterFirst, alone.phiAfterFirst);
    EXPECT_EQ(mixed.phiAfterSecond, alone.phiAfterSecond);
    EXPECT_EQ(mixed.first3d.pixels, alone.first3d.pixels);
    // A renderer built now, on a clean state, draws the same axial picture.
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
    render::Renderer fresh(scan, texture);
    fresh.render(view(fresh, render::ViewKind::Axial), &after);
    EXPECT_EQ(fresh.readback().pixels, mixed.secondAxial.pixels);
}

} // namespace
} // namespace steerseg::test
