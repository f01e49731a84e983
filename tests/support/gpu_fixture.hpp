#pragma once

#include "platform/egl/offscreen_context.hpp"

#include <gtest/gtest.h>
#include <memory>

namespace steerseg::test {

// One offscreen GLES context per test binary (creating one per test costs ~100 ms on
// llvmpipe). Tests derive from GpuTest and find the context current.
class GpuTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite();
    void SetUp() override;
    static platform::GpuContext& context();

  private:
    static std::unique_ptr<platform::GpuContext> context_;
};

} // namespace steerseg::test
