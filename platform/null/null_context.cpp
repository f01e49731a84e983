#include "platform/null/null_context.hpp"

namespace steerseg::platform {

namespace {

class NullContext final : public GpuContext {
  public:
    [[nodiscard]] std::string backendName() const override { return "null"; }
    [[nodiscard]] bool providesGl() const override { return false; }
    void makeCurrent() override {}
};

} // namespace

std::unique_ptr<GpuContext> createNullContext() {
    return std::make_unique<NullContext>();
}

} // namespace steerseg::platform
