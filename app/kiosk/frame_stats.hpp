#pragma once

// Frame times and input-to-screen latencies of a kiosk run, for the benchmark and the log.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace steerseg::kiosk {

struct Percentiles {
    double p50 = 0.0;
    double p90 = 0.0;
    double p99 = 0.0;
    double max = 0.0;
    double total = 0.0; // the samples' sum: rates over the time spent
    std::size_t count = 0;
};
Percentiles percentiles(std::vector<double> samples);

class FrameStats {
  public:
    void frame(double seconds, bool evolving) {
        (evolving ? evolvingFrames_ : idleFrames_).push_back(seconds);
    }
    void latency(double seconds) { latencies_.push_back(seconds); }
    // n solver iterations that took `seconds` (the solver's part of an evolving frame).
    void iterations(int n, double seconds) {
        iterations_ += n;
        solverSeconds_ += seconds;
    }
    void drawn(double pixels, double seconds) {
        pixels_ += pixels;
        drawSeconds_ += seconds;
    }
    // A script's `frame` written `seconds` after it was asked for (the pictures' refinement).
    void frameWait(double seconds) { frameWaits_.push_back(seconds); }
    // The views' sizes on screen (3D, first slice, second slice), for a comparison with the
    // renderer drawing the same pictures whole.
    void viewSizes(std::vector<std::pair<int, int>> sizes) { viewSizes_ = std::move(sizes); }
    // {"frames_evolving": {"p50_ms": ..., "total_s": ...}, "frames_idle": ..., "latency": ...,
    //  "iterations": N, "iterations_per_second": (per second evolving), "solver_seconds": ...,
    //  "draw_seconds": ..., "pixels_per_second": ..., "frame_waits_s": [...],
    //  "view_sizes": [[w, h], ...]}; throws std::runtime_error naming the path on a write error.
    void write(const std::filesystem::path& path, const std::string& description) const;
    [[nodiscard]] std::string summary() const;

  private:
    std::vector<double> evolvingFrames_;
    std::vector<double> idleFrames_;
    std::vector<double> latencies_;
    long long iterations_ = 0;
    double solverSeconds_ = 0.0;
    double pixels_ = 0.0;
    double drawSeconds_ = 0.0;
    std::vector<double> frameWaits_;
    std::vector<std::pair<int, int>> viewSizes_;
};

} // namespace steerseg::kiosk
