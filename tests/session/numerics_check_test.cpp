// The appliance's check of its GPU's numbers (session/numerics_check, issue 47): on a GPU that
// computes right (llvmpipe) every speed passes, well within its tolerances and within the time
// a start-up can spend; with the classifier's gather broken through its test seam, classify
// fails naming the gathered features and the other speeds still pass.
#include "session/numerics_check.hpp"
#include "speed/classifier_gather_fault.hpp"
#include "support/gpu_fixture.hpp"

#include <gtest/gtest.h>
#include <string>

namespace steerseg::test {
namespace {

class NumericsCheckTest : public GpuTest {};

TEST_F(NumericsCheckTest, EverySpeedMatchesItsCpuTwinOnAGpuThatComputesRight) {
    const session::NumericsReport r = session::checkGpuNumerics();
    ASSERT_EQ(r.speeds.size(), model::kSpeedKinds.size());
    for (std::size_t n = 0; n < r.speeds.size(); ++n) {
        const session::SpeedNumerics& s = r.speeds[n];
        SCOPED_TRACE(model::speedKindName(s.kind));
        EXPECT_EQ(s.kind, model::kSpeedKinds[n]);
        EXPECT_TRUE(s.passed) << s.detail;
        EXPECT_TRUE(s.failure.empty()) << s.failure;
        // Well within the check's tolerances: a GPU's linear filtering of the marks' vote
        // weighs with fixed-point fractions (the H200's differed by 0.0016, the check allows 0.02).
        EXPECT_LT(s.largestDifference, 5e-3) << s.detail;
        EXPECT_NE(s.detail.find("12 solver iterations: 0 voxels apart off the surface"),
                  std::string::npos)
            << s.detail;
    }
    EXPECT_NE(r.speeds[2].detail.find("gathered features within"), std::string::npos);
    EXPECT_TRUE(r.allPassed());
    EXPECT_GT(r.seconds, 0.0);
}

TEST_F(NumericsCheckTest, AGatherThatHandsOutOtherRowsFailsClassifyAlone) {
    speed::fault::reverseGatheredRows(true);
    const session::NumericsReport r = session::checkGpuNumerics();
    speed::fault::reverseGatheredRows(false);
    EXPECT_FALSE(r.allPassed());
    EXPECT_TRUE(r.passed(model::SpeedKind::Threshold)) << r.speeds[0].detail;
    EXPECT_TRUE(r.passed(model::SpeedKind::Edge)) << r.speeds[1].detail;
    ASSERT_FALSE(r.passed(model::SpeedKind::Classify));
    EXPECT_EQ(r.speeds[2].failure.rfind("gathered features within ", 0), 0U) << r.speeds[2].failure;
    EXPECT_NE(r.speeds[2].failure.find("beyond tolerance"), std::string::npos);
    EXPECT_GT(r.speeds[2].largestDifference, 1.0);
}

} // namespace
} // namespace steerseg::test
