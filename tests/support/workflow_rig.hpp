#pragma once

// A workflow over a FakeEngine, and the shortest operator path to each state.
#include "support/fake_engine.hpp"
#include "workflow/workflow.hpp"

#include <chrono>
#include <filesystem>
#include <gtest/gtest.h>
#include <memory>

namespace steerseg::test {

// 2026-11-23 13:01:40 UTC, so export names and audit times are known.
inline std::chrono::system_clock::time_point fixedTime() {
    return std::chrono::system_clock::time_point(std::chrono::seconds(1795438900));
}

inline workflow::Settings testSettings() {
    workflow::Settings s;
    s.presets = {{"CT soft tissue", 40.0, 80.0, 0.7, 40.0, 400.0, "ct_soft"},
                 {"CT bone", 700.0, 300.0, 0.9, 500.0, 2000.0, ""}};
    s.epsFloor = 25.0;
    s.maxUndo = 8;
    s.clock = fixedTime;
    s.exportFolder = std::filesystem::path(testing::TempDir()) / "steerseg-workflow-exports";
    return s;
}

struct Rig {
    explicit Rig(workflow::Settings s = testSettings(), workflow::AuditLog* audit = nullptr)
        : wf(std::make_unique<workflow::Workflow>(engine, std::move(s), audit)) {}

    workflow::Workflow::Outcome act(const model::Action& a) { return wf->handle(a); }
    model::State state() const { return wf->state(); }
    const workflow::Status& status() const { return wf->status(); }

    // Loads the fake scan through the polls a real load takes.
    void load() {
        ASSERT_TRUE(act(model::LoadScan{"fake.nii.gz"}).accepted);
        for (int i = 0; i < 10 && state() == model::State::Loading; ++i) {
            wf->update();
        }
        ASSERT_EQ(state(), model::State::Inspect);
    }
    void seed(const glm::dvec3& at = {8.0, 6.0, 4.0}, double radius = 2.0) {
        ASSERT_TRUE(act(model::AddSeed{at, radius}).accepted);
    }
    // Drives a fresh rig to `s` along the operator's path (Exporting is transient: not here).
    void driveTo(model::State s) {
        using model::State;
        if (s == State::NoScan) {
            return;
        }
        if (s == State::Loading) {
            ASSERT_TRUE(act(model::LoadScan{"fake.nii.gz"}).accepted);
            return;
        }
        load();
        if (s == State::Inspect) {
            return;
        }
        seed();
        if (s == State::Seeding) {
            return;
        }
        ASSERT_TRUE(act(model::Run{}).accepted);
        if (s == State::Evolving) {
            return;
        }
        if (s == State::Error) {
            engine.stepError = "GPU lost";
            wf->evolve(1);
            engine.stepError.clear();
            ASSERT_EQ(state(), State::Error);
            return;
        }
        ASSERT_TRUE(act(model::Pause{}).accepted);
        if (s == State::Paused) {
            return;
        }
        ASSERT_TRUE(act(model::Finish{}).accepted);
        if (s == State::Review) {
            return;
        }
        ASSERT_TRUE(act(model::Export{"out.nii.gz"}).accepted);
        ASSERT_EQ(state(), State::Done);
    }

    FakeEngine engine;
    std::unique_ptr<workflow::Workflow> wf;
};

} // namespace steerseg::test
