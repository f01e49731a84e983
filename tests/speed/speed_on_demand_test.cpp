// The classifier speed evaluated where the front goes (docs/speed.md): the solver's run with the
// speed computed brick by brick on demand is the run with the speed computed everywhere first,
// it evaluates only part of the scan, and filling ahead completes the same texture.
#include "gpu/scan_texture.hpp"
#include "gpu/texture_readback.hpp"
#include "solver/level_set_solver.hpp"
#include "speed/classifier_speed.hpp"
#include "speed/volume_texture.hpp"
#include "support/gpu_fixture.hpp"
#include "support/two_textures.hpp"

#include <algorithm>
#include <cstdint>
#include <gtest/gtest.h>
#include <utility>
#include <vector>

namespace steerseg::test {
namespace {

using model::LevelSetParams;
using model::Sphere;
using solver::LevelSetSolver;
using speed::ClassifierEvaluation;
using speed::ClassifierParams;
using speed::ClassifierSpeed;

class SpeedOnDemandTest : public GpuTest {};

// Calm noise (amplitude 8) for i < 24, rough (40) beyond, one mean: the classifier's two
// textures, the rough side three times the calm one, where the front stops.
constexpr glm::ivec3 kDims{96, 32, 32};
constexpr int kBorderX = 24;

std::vector<float> twoTextures() {
    return twoTextureIntensities(kDims, kBorderX, 777U);
}

constexpr int kIterations = 300;
const std::vector<speed::Example> kInside{{{10.0F, 16.0F, 16.0F}, 6.0F}};
const std::vector<speed::Example> kOutside{{{40.0F, 16.0F, 16.0F}, 6.0F}};

ClassifierSpeed classifier(const gpu::ScanTexture& scan, ClassifierEvaluation evaluation) {
    ClassifierParams params;
    params.evaluation = evaluation;
    return {scan.exact(), kDims, kInside, kOutside, params};
}

// kIterations from a seed in the calm texture, with the classifier's texture and forest.
std::vector<float> run(LevelSetSolver& solver, const ClassifierSpeed& c) {
    solver.setSpeedInputs({model::SpeedKind::Classify, 0, c.texture(), c.onDemandForest()});
    solver.setParams(LevelSetParams{100.0F, 30.0F, 0.5F});
    solver.addSphere(Sphere{{10.0F, 16.0F, 16.0F}, 3.0F});
    solver.step(kIterations);
    return solver.readPhi();
}

TEST_F(SpeedOnDemandTest, TheFrontMovesAsWithTheSpeedComputedEverywhere) {
    const std::vector<float> scan = twoTextures();
    const gpu::ScanTexture texture(scan, kDims);
    const ClassifierSpeed everywhere = classifier(texture, ClassifierEvaluation::Everywhere);
    const ClassifierSpeed onDemand = classifier(texture, ClassifierEvaluation::OnDemand);
    EXPECT_EQ(everywhere.onDemandForest().nodes, 0U);
    EXPECT_NE(onDemand.onDemandForest().nodes, 0U);

    LevelSetSolver a(texture);
    const std::vector<float> expected = run(a, everywhere);
    LevelSetSolver b(texture);
    const std::vector<float> phi = run(b, onDemand);
    ASSERT_EQ(phi.size(), expected.size());
    std::size_t inside = 0;
    std::size_t differ = 0;
    for (std::size_t n = 0; n < phi.size(); ++n) {
        inside += phi[n] < 0.0F ? 1 : 0;
        differ += phi[n] != expected[n] ? 1 : 0;
    }
    EXPECT_EQ(differ, 0U) << "of " << phi.size() << " voxels";
    EXPECT_GT(inside, 15000U); // most of the calm side's 24576 voxels, from the seed's 123

    // Only the bricks the front reached hold the speed; the rest of the texture is still 0.
    const model::SolverStats stats = b.stats();
    EXPECT_EQ(a.speedBricksEvaluated(), 0U);
    EXPECT_GT(b.speedBricksEvaluated(), 0U);
    EXPECT_LT(b.speedBricksEvaluated(), stats.totalBricks / 2);
    const std::vector<float> full = gpu::readVolumeTexture(everywhere.texture(), kDims);
    std::vector<float> partial = gpu::readVolumeTexture(onDemand.texture(), kDims);
    std::size_t evaluated = 0;
    for (std::size_t n = 0; n < partial.size(); ++n) {
        if (partial[n] != 0.0F) {
            ++evaluated;
            ASSERT_EQ(partial[n], full[n]) << "voxel " << n;
        }
    }
    EXPECT_GT(evaluated, 0U);
    EXPECT_LT(evaluated, partial.size() / 2);

    // Ahead of the front, in a few calls, the rest: the texture computed everywhere.
    std::uint32_t left = b.evaluateSpeedAhead(16);
    EXPECT_GT(left, 0U);
    while (left > 0) {
        left = b.evaluateSpeedAhead(64);
    }
    EXPECT_EQ(b.speedBricksEvaluated(), stats.totalBricks);
    partial = gpu::readVolumeTexture(onDemand.texture(), kDims);
    EXPECT_EQ(partial, full);
    EXPECT_EQ(a.evaluateSpeedAhead(16), 0U); // complete from the start
}

// A new speed forgets what the last one evaluated: its bricks are evaluated again.
TEST_F(SpeedOnDemandTest, ANewSpeedIsEvaluatedAfresh) {
    const std::vector<float> scan = twoTextures();
    const gpu::ScanTexture texture(scan, kDims);
    const ClassifierSpeed first = classifier(texture, ClassifierEvaluation::OnDemand);
    LevelSetSolver solver(texture);
    run(solver, first);
    const std::uint32_t once = solver.speedBricksEvaluated();
    ASSERT_GT(once, 0U);
    const ClassifierSpeed second = classifier(texture, ClassifierEvaluation::OnDemand);
    solver.setSpeedInputs(
        {model::SpeedKind::Classify, 0, second.texture(), second.onDemandForest()});
    EXPECT_EQ(solver.speedBricksEvaluated(), 0U);
    solver.step(1);
    EXPECT_GT(solver.speedBricksEvaluated(), 0U);
    solver.setSpeedInputs({});
    EXPECT_EQ(solver.speedBricksEvaluated(), 0U);
    EXPECT_THROW(solver.setSpeedInputs(
                     {model::SpeedKind::Edge, 0, second.texture(), second.onDemandForest()}),
                 std::invalid_argument);
}

// A retrained speed writes over its predecessor's texture (Session::setSpeed after a correction):
// the same texture, none of the old values left where the new forest has not been evaluated,
// and what it evaluates is a fresh speed's. Only a texture of the scan's grid is taken.
TEST_F(SpeedOnDemandTest, ARetrainedSpeedWritesOverItsPredecessorsTexture) {
    const std::vector<float> scan = twoTextures();
    const gpu::ScanTexture texture(scan, kDims);
    ClassifierSpeed first = classifier(texture, ClassifierEvaluation::OnDemand);
    LevelSetSolver solver(texture);
    run(solver, first);
    solver.setSpeedInputs({});
    const GLuint id = first.texture();
    std::vector<float> values = gpu::readVolumeTexture(id, kDims);
    ASSERT_GT(std::count_if(values.begin(), values.end(), [](float v) { return v != 0.0F; }), 0);

    ClassifierParams params;
    params.evaluation = ClassifierEvaluation::OnDemand;
    ClassifierSpeed second(texture.exact(), kDims, kInside, kOutside, params, first.takeTexture());
    EXPECT_EQ(first.texture(), 0U);
    EXPECT_EQ(second.texture(), id);
    values = gpu::readVolumeTexture(second.texture(), kDims);
    EXPECT_EQ(std::count_if(values.begin(), values.end(), [](float v) { return v != 0.0F; }), 0);
    LevelSetSolver fresh(texture);
    const ClassifierSpeed everywhere = classifier(texture, ClassifierEvaluation::Everywhere);
    const std::vector<float> expected = run(fresh, everywhere);
    LevelSetSolver again(texture);
    EXPECT_EQ(run(again, second), expected);

    // Everywhere fills a recycled texture whole; a texture of another grid is not taken.
    params.evaluation = ClassifierEvaluation::Everywhere;
    const ClassifierSpeed filled(texture.exact(), kDims, kInside, kOutside, params,
                                 second.takeTexture());
    EXPECT_EQ(filled.texture(), id);
    const std::vector<float> whole = gpu::readVolumeTexture(everywhere.texture(), kDims);
    EXPECT_EQ(gpu::readVolumeTexture(filled.texture(), kDims), whole);
    gpu::Texture other = speed::createVolumeTexture(glm::ivec3(8, 8, 8), "another grid");
    const GLuint otherId = other.id();
    const ClassifierSpeed own(texture.exact(), kDims, kInside, kOutside, params, std::move(other));
    EXPECT_NE(own.texture(), otherId);
    EXPECT_EQ(gpu::readVolumeTexture(own.texture(), kDims), whole);
}

} // namespace
} // namespace steerseg::test
