#include "core/sample_phantom.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

TEST(SamplePhantom, IsDeterministicAndHasItsStructures) {
    const Volume a = makeSamplePhantom();
    const Volume b = makeSamplePhantom();
    ASSERT_EQ(a.bytes().size(), b.bytes().size());
    EXPECT_TRUE(std::equal(a.bytes().begin(), a.bytes().end(), b.bytes().begin()));
    EXPECT_EQ(a.dims(), glm::ivec3(128, 128, 96));
    const PhantomLesion l = kPhantomLesion;
    EXPECT_NEAR(a.valueAt(l.i, l.j, l.k), l.intensity, 80.0);
    EXPECT_NEAR(a.valueAt(2, 2, 2), 20.0, 80.0);
    EXPECT_NEAR(a.valueAt(64, 64, 20), 420.0, 80.0); // brain, away from lesion and ventricles
    EXPECT_GT(a.stats().max, 700.0);
}

} // namespace
} // namespace steerseg::test
