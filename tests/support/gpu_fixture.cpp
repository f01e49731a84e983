#include "support/gpu_fixture.hpp"

namespace steerseg::test {

std::unique_ptr<platform::GpuContext> GpuTest::context_;

void GpuTest::SetUpTestSuite() {
    if (!context_) {
        context_ = platform::createOffscreenContext();
    }
}

void GpuTest::SetUp() {
    ASSERT_TRUE(context_) << "no offscreen GLES context";
    context_->makeCurrent();
}

platform::GpuContext& GpuTest::context() {
    return *context_;
}

} // namespace steerseg::test
