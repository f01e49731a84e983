#pragma once

// Frame times and input-to-screen latencies of a kiosk run, for the benchmark and the log.
#include <filesystem>
#include <string>
#include <vector>

namespace steerseg::kiosk {

struct Percentiles {
    double p50 = 0.0;
    double p90 = 0.0;
    double p99 = 0.0;
    double max = 0.0;
    std::size_t count = 0;
};
Percentiles percentiles(std::vector<double> samples);

class FrameStats {
  public:
    void frame(double seconds, bool evolving) {
        (evolving ? evolvingFrames_ : idleFrames_).push_back(seconds);
    }
    void latency(double seconds) { latencies_.push_back(seconds); }
    void iterations(int n) { iterations_ += n; }
    void drawn(double pixels, double seconds) {
        pixels_ += pixels;
        drawSeconds_ += seconds;
    }
    // {"frames_evolving": {"p50_ms": ...}, "frames_idle": ..., "latency": ..., "iterations": N,
    //  "pixels_per_second": ...}; throws std::runtime_error naming the path on a write error.
    void write(const std::filesystem::path& path, const std::string& description) const;
    [[nodiscard]] std::string summary() const;

  private:
    std::vector<double> evolvingFrames_;
    std::vector<double> idleFrames_;
    std::vector<double> latencies_;
    long long iterations_ = 0;
    double pixels_ = 0.0;
    double drawSeconds_ = 0.0;
};

} // namespace steerseg::kiosk
