#include "kiosk/frame_stats.hpp"

#include "files/file_write.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <span>
#include <sstream>
#include <stdexcept>

namespace steerseg::kiosk {

Percentiles percentiles(std::vector<double> samples) {
    Percentiles p;
    p.count = samples.size();
    if (samples.empty()) {
        return p;
    }
    std::sort(samples.begin(), samples.end());
    for (const double x : samples) {
        p.total += x;
    }
    const auto at = [&](double q) {
        const auto index =
            static_cast<std::size_t>(std::ceil(q * static_cast<double>(samples.size()))) - 1;
        return samples[std::min(index, samples.size() - 1)];
    };
    p.p50 = at(0.50);
    p.p90 = at(0.90);
    p.p99 = at(0.99);
    p.max = samples.back();
    return p;
}

namespace {

nlohmann::json toJson(const Percentiles& p) {
    return {{"count", p.count},      {"p50_ms", p.p50 * 1e3}, {"p90_ms", p.p90 * 1e3},
            {"p99_ms", p.p99 * 1e3}, {"max_ms", p.max * 1e3}, {"total_s", p.total}};
}

std::string line(const char* what, const Percentiles& p) {
    std::ostringstream o;
    o.precision(3);
    o << what << " p50 " << p.p50 * 1e3 << " ms, p90 " << p.p90 * 1e3 << " ms, p99 " << p.p99 * 1e3
      << " ms, max " << p.max * 1e3 << " ms (" << p.count << ")";
    return o.str();
}

} // namespace

void FrameStats::write(const std::filesystem::path& path, const std::string& description) const {
    nlohmann::json j;
    j["display"] = description;
    const Percentiles evolving = percentiles(evolvingFrames_);
    j["frames_evolving"] = toJson(evolving);
    j["frames_idle"] = toJson(percentiles(idleFrames_));
    j["latency"] = toJson(percentiles(latencies_));
    j["iterations"] = iterations_;
    j["iterations_per_second"] =
        evolving.total > 0.0 ? static_cast<double>(iterations_) / evolving.total : 0.0;
    j["solver_seconds"] = solverSeconds_;
    j["draw_seconds"] = drawSeconds_;
    j["pixels_per_second"] = drawSeconds_ > 0.0 ? pixels_ / drawSeconds_ : 0.0;
    j["frame_waits_s"] = frameWaits_;
    j["view_sizes"] = nlohmann::json::array();
    for (const auto& [w, h] : viewSizes_) {
        j["view_sizes"].push_back({w, h});
    }
    const std::string text = j.dump(2) + '\n';
    files::writeFileAtomically(path, {std::as_bytes(std::span(text))});
}

std::string FrameStats::summary() const {
    return line("frames while evolving:", percentiles(evolvingFrames_)) + "\n" +
           line("frames otherwise:", percentiles(idleFrames_)) + "\n" +
           line("input to screen:", percentiles(latencies_));
}

} // namespace steerseg::kiosk
