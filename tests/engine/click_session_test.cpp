// engine::ClickSession: corrections through the kiosk's workflow on the real solver.
#include "engine/click_session.hpp"
#include "support/gpu_fixture.hpp"
#include "support/io_test_files.hpp"

#include <filesystem>
#include <gtest/gtest.h>
#include <string>

namespace steerseg::test {
namespace {

// Two balls of intensity 100 joined by a narrow neck along i, in a background of 0: a front
// seeded in the first leaks through the neck into the second.
std::filesystem::path dumbbell() {
    const glm::ivec3 d{48, 32, 32};
    std::vector<double> v(static_cast<std::size_t>(d.x * d.y * d.z), 0.0);
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                const glm::dvec3 p(i, j, k);
                const bool a = glm::length(p - glm::dvec3(12, 16, 16)) <= 8.0;
                const bool b = glm::length(p - glm::dvec3(36, 16, 16)) <= 8.0;
                const bool neck =
                    i >= 18 && i <= 30 && glm::length(glm::dvec2(j - 16, k - 16)) <= 2.5;
                v[static_cast<std::size_t>(i + d.x * (j + d.y * k))] = a || b || neck ? 100.0 : 0.0;
            }
        }
    }
    Geometry g;
    g.dims = d;
    // One file per test: CTest runs the tests of this binary side by side.
    const auto path = std::filesystem::temp_directory_path() /
                      (std::string("steerseg_dumbbell_") +
                       testing::UnitTest::GetInstance()->current_test_info()->name() + ".nii");
    NiftiOptions o;
    o.datatype = 16; // float32
    writeFile(path, niftiFile(g, encodeSamples(v, "float32"), o));
    return path;
}

workflow::Settings settings() {
    workflow::Settings s;
    s.epsFloor = 30.0; // the phantom has no noise: the floor sets eps
    return s;
}

bool inside(engine::ClickSession& s, glm::ivec3 v) {
    const glm::ivec3 d = s.scan().dims();
    return s.mask()[static_cast<std::size_t>(v.x + d.x * (v.y + d.y * v.z))] != 0;
}

class ClickSessionTest : public GpuTest {};

TEST_F(ClickSessionTest, ANegativeClickOnALeaksNeckKeepsItClosed) {
    const auto scan = dumbbell();
    const glm::ivec3 neck{24, 16, 16};
    const glm::ivec3 far{38, 16, 16};
    for (const bool sticky : {true, false}) {
        SCOPED_TRACE(sticky ? "a correction" : "a bare erase, for comparison");
        engine::ClickSession s(scan.string(), settings());
        const engine::ClickOutcome first =
            s.apply(model::Correct{{12.0, 16.0, 16.0}, true, 3.0}, 3000);
        EXPECT_NE(first.stopReason, "iteration_limit") << "the front should stop by itself";
        ASSERT_TRUE(inside(s, far)) << "the front leaked through the neck into the second ball";
        ASSERT_TRUE(inside(s, neck));
        const model::Sphere cut{glm::vec3(neck), 4.0F};
        if (sticky) {
            // The first click's keeping sphere and this blocking one.
            EXPECT_EQ(s.apply(model::Correct{glm::dvec3(neck), false, 4.0}, 100).barriers, 2);
        } else {
            s.engine().session()->erase(cut);
        }
        s.engine().session()->step(2000);
        EXPECT_EQ(inside(s, neck), !sticky) << "2000 iterations after the cut";
    }
    std::filesystem::remove(scan);
}

// The challenge's first prompt: a box around the first ball. Its centre is probed and seeded,
// and the run stops by itself at the box's face, short of the neck it leaked through above.
TEST_F(ClickSessionTest, ABoxRunsFromItsCentreAndHoldsTheLeak) {
    const auto scan = dumbbell();
    engine::ClickSession s(scan.string(), settings());
    const engine::ClickOutcome r =
        s.apply(model::SetBox{model::Box{{4, 8, 8}, {21, 24, 24}}}, 3000);
    EXPECT_EQ(r.stopReason, "converged");
    EXPECT_TRUE(inside(s, {12, 16, 16}));
    EXPECT_FALSE(inside(s, {24, 16, 16})) << "the neck lies beyond the box";
    EXPECT_FALSE(inside(s, {38, 16, 16}));
    EXPECT_THROW(s.apply(model::SetBox{model::Box{{4, 8, 8}, {21, 24, 99}}}, 10),
                 std::runtime_error);
    std::filesystem::remove(scan);
}

// A negative click over the whole structure leaves nothing inside: reported as "vanished", as
// `segment` reports a run that shrank away, and never as converged.
TEST_F(ClickSessionTest, AnEraseOfTheWholeSurfaceIsReportedAsVanished) {
    const auto scan = dumbbell();
    engine::ClickSession s(scan.string(), settings());
    ASSERT_EQ(s.apply(model::SetBox{model::Box{{4, 8, 8}, {21, 24, 24}}}, 3000).stopReason,
              "converged");
    const engine::ClickOutcome r = s.apply(model::Correct{{12.0, 16.0, 16.0}, false, 10.0}, 3000);
    EXPECT_EQ(r.stopReason, "vanished");
    EXPECT_FALSE(inside(s, {12, 16, 16}));
    EXPECT_NE(s.workflow().status().message.find("the level set is empty"), std::string::npos)
        << "message: " << s.workflow().status().message;
    std::filesystem::remove(scan);
}

TEST_F(ClickSessionTest, AFirstNegativeClickIsRefusedWithTheWorkflowsReason) {
    const auto scan = dumbbell();
    engine::ClickSession s(scan.string(), settings());
    try {
        s.apply(model::Correct{{12.0, 16.0, 16.0}, false, 3.0}, 10);
        FAIL() << "a negative first click was accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("first correction adds"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(engine::ClickSession("/nonexistent/scan.nii", settings()), std::runtime_error);
    std::filesystem::remove(scan);
}

} // namespace
} // namespace steerseg::test
