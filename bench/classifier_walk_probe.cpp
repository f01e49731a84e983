// Which way of writing the classifier forest's walk a GPU computes right: the shipped
// speed/classifier_walk.comp and the formulations it could have taken (a node copied as a
// struct or read field by field or as raw words, the features in a vector or an array, the
// bounds as uniforms or constants), each run on the same feature rows and compared with the CPU
// forest's walk, tree by tree and depth by depth. Written for issue 47's NVIDIA failure, where
// the walk agreed with the CPU nowhere while the features it walks matched; kept so that the
// next GPU that disagrees tells in one run where (docs/speed.md, "Right answers on every GPU").
//
//   classifier_walk_probe [--rows N] [--trees N] [--depth N]
//
// Prints one line per formulation: rows apart from the CPU (beyond 1e-6) and the largest
// difference; exits 1 when the shipped walk is apart.
#include "common/bindings.h"
#include "gpu/buffer_io.hpp"
#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/gl_handle.hpp"
#include "gpu/gpu_info.hpp"
#include "gpu/program.hpp"
#include "platform/egl/offscreen_context.hpp"
#include "speed/classifier_features.hpp"
#include "speed/random_forest.hpp"
#include "speed/split_mix.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

namespace {

using namespace steerseg;

constexpr int kFeatures = speed::kClassifierFeatureCount;

int argOr(int argc, char** argv, const char* name, int fallback) {
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::string(argv[i]) == name) {
            return std::atoi(argv[i + 1]);
        }
    }
    return fallback;
}

// The CPU's walk of trees [first, first + count), at most `maxDepth` steps each.
float cpuLook(const speed::RandomForest& forest, const float* row, int first, int count,
              int maxDepth) {
    const auto& nodes = forest.nodes();
    float sum = 0.0F;
    for (int t = first; t < first + count; ++t) {
        std::int32_t n = forest.roots()[static_cast<std::size_t>(t)];
        for (int d = 0; d < maxDepth && nodes[static_cast<std::size_t>(n)].feature >= 0; ++d) {
            const speed::ForestNode& node = nodes[static_cast<std::size_t>(n)];
            n = node.left + (row[node.feature] < node.threshold ? 0 : 1);
        }
        sum += nodes[static_cast<std::size_t>(n)].value;
    }
    return sum / static_cast<float>(count);
}

const char* kHead = R"(#version 310 es
precision highp float;
precision highp int;
layout(local_size_x = 64) in;
layout(std430, binding = 13) readonly buffer Rows { float rowFeatures[]; };
layout(std430, binding = 12) writeonly buffer Looks { float looks[]; };
layout(std430, binding = 15) readonly buffer Roots { int roots[]; };
uniform int rowCount;
uniform int firstTree;
uniform int treeCount;
uniform int maxDepth;
float feature(int r, int i) { return rowFeatures[r * 8 + i]; }
)";

const char* kStruct = R"(
struct ForestNode { int feature; float threshold; int left; float value; };
layout(std430, binding = 14) readonly buffer Nodes { ForestNode nodes[]; };
)";

const char* kRaw = R"(
layout(std430, binding = 14) readonly buffer Nodes { ivec4 nodes[]; };
)";

// Each formulation's body: `float look(int r)`, then main.
const char* kMain = R"(
void main() {
    int r = int(gl_GlobalInvocationID.x);
    if (r < rowCount) {
        looks[r] = look(r);
    }
}
)";

struct Formulation {
    const char* name;
    const char* nodes;
    const char* body;
    bool constants = false; // TREE_COUNT / MAX_DEPTH as #defines, not uniforms
};

const Formulation kFormulations[] = {
    {"struct copied, vec4 pair, selects (the walk before)", kStruct, R"(
struct Fv { vec4 lo; vec4 hi; };
float pick(Fv fv, int i) {
    vec4 q = i < 4 ? fv.lo : fv.hi;
    int c = i & 3;
    return c == 0 ? q.x : (c == 1 ? q.y : (c == 2 ? q.z : q.w));
}
float look(int r) {
    Fv f;
    f.lo = vec4(feature(r, 0), feature(r, 1), feature(r, 2), feature(r, 3));
    f.hi = vec4(feature(r, 4), feature(r, 5), feature(r, 6), feature(r, 7));
    float sum = 0.0;
    for (int t = firstTree; t < firstTree + treeCount; ++t) {
        ForestNode node = nodes[roots[t]];
        for (int depth = 0; depth < maxDepth && node.feature >= 0; ++depth) {
            node = nodes[node.left + (pick(f, node.feature) < node.threshold ? 0 : 1)];
        }
        sum += node.value;
    }
    return sum / float(treeCount);
}
)"},
    {"struct copied, features from the buffer", kStruct, R"(
float look(int r) {
    float sum = 0.0;
    for (int t = firstTree; t < firstTree + treeCount; ++t) {
        ForestNode node = nodes[roots[t]];
        for (int depth = 0; depth < maxDepth && node.feature >= 0; ++depth) {
            node = nodes[node.left + (feature(r, node.feature) < node.threshold ? 0 : 1)];
        }
        sum += node.value;
    }
    return sum / float(treeCount);
}
)"},
    {"struct read field by field, index walk, break", kStruct, R"(
float look(int r) {
    float sum = 0.0;
    for (int t = firstTree; t < firstTree + treeCount; ++t) {
        int n = roots[t];
        for (int depth = 0; depth < maxDepth; ++depth) {
            int k = nodes[n].feature;
            if (k < 0) {
                break;
            }
            n = nodes[n].left + (feature(r, k) < nodes[n].threshold ? 0 : 1);
        }
        sum += nodes[n].value;
    }
    return sum / float(treeCount);
}
)"},
    {"raw ivec4 words, index walk, break", kRaw, R"(
float look(int r) {
    float sum = 0.0;
    for (int t = firstTree; t < firstTree + treeCount; ++t) {
        int n = roots[t];
        for (int depth = 0; depth < maxDepth; ++depth) {
            ivec4 w = nodes[n];
            if (w.x < 0) {
                break;
            }
            n = w.z + (feature(r, w.x) < intBitsToFloat(w.y) ? 0 : 1);
        }
        sum += intBitsToFloat(nodes[n].w);
    }
    return sum / float(treeCount);
}
)"},
    {"struct copied, float[8] features", kStruct, R"(
float look(int r) {
    float f[8];
    for (int i = 0; i < 8; ++i) {
        f[i] = feature(r, i);
    }
    float sum = 0.0;
    for (int t = firstTree; t < firstTree + treeCount; ++t) {
        ForestNode node = nodes[roots[t]];
        for (int depth = 0; depth < maxDepth && node.feature >= 0; ++depth) {
            node = nodes[node.left + (f[node.feature] < node.threshold ? 0 : 1)];
        }
        sum += node.value;
    }
    return sum / float(treeCount);
}
)"},
    {"struct copied, bounds as constants", kStruct, R"(
float look(int r) {
    float sum = 0.0;
    for (int t = 0; t < TREE_COUNT; ++t) {
        ForestNode node = nodes[roots[firstTree + t]];
        for (int depth = 0; depth < MAX_DEPTH && node.feature >= 0; ++depth) {
            node = nodes[node.left + (feature(r, node.feature) < node.threshold ? 0 : 1)];
        }
        sum += node.value;
    }
    return sum / float(TREE_COUNT);
}
)",
     true},
};

struct Gap {
    std::size_t apart = 0;
    double largest = 0.0;
};

Gap compare(const std::vector<float>& gpu, const std::vector<float>& cpu) {
    Gap gap;
    for (std::size_t n = 0; n < cpu.size(); ++n) {
        const double d = std::abs(static_cast<double>(gpu[n]) - static_cast<double>(cpu[n]));
        gap.apart += !(d <= 1e-6) ? 1 : 0;
        gap.largest = std::max(gap.largest, std::isfinite(d) ? d : 1e30);
    }
    return gap;
}

struct Setup {
    const speed::RandomForest* forest;
    const gpu::Buffer* rows;
    const gpu::Buffer* nodes;
    const gpu::Buffer* roots;
    int rowCount;
};

// Runs `program` over the rows for trees [first, first + count), depth <= maxDepth.
std::vector<float> run(const gpu::Program& program, const Setup& s, int first, int count,
                       int maxDepth) {
    std::vector<float> looks(static_cast<std::size_t>(s.rowCount),
                             std::numeric_limits<float>::quiet_NaN());
    const gpu::Buffer out = gpu::createBuffer(GL_SHADER_STORAGE_BUFFER,
                                              static_cast<GLsizeiptr>(looks.size() * sizeof(float)),
                                              looks.data(), GL_STREAM_READ);
    glUseProgram(program.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CLASSIFIER_SAMPLES_BINDING, out.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CLASSIFIER_FEATURES_BINDING, s.rows->id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CLASSIFIER_NODES_BINDING, s.nodes->id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CLASSIFIER_ROOTS_BINDING, s.roots->id());
    const auto set = [&](const char* name, int value) {
        glUniform1i(glGetUniformLocation(program.id(), name), value);
    };
    set("rowCount", s.rowCount);
    set("firstTree", first);
    set("treeCount", count);
    set("maxDepth", maxDepth);
    gpu::dispatchCompute(static_cast<GLuint>((s.rowCount + 63) / 64), 1, 1);
    gpu::readBufferBytes(out, 0, looks.data(), looks.size() * sizeof(float), "the probe's looks");
    gpu::checkGl("the walk probe");
    return looks;
}

std::vector<float> cpuRun(const Setup& s, const std::vector<float>& rows, int first, int count,
                          int maxDepth) {
    std::vector<float> looks(static_cast<std::size_t>(s.rowCount));
    for (int r = 0; r < s.rowCount; ++r) {
        looks[static_cast<std::size_t>(r)] =
            cpuLook(*s.forest, rows.data() + static_cast<std::ptrdiff_t>(r) * kFeatures, first,
                    count, maxDepth);
    }
    return looks;
}

} // namespace

int main(int argc, char** argv) {
    try {
        const int rowCount = std::max(64, argOr(argc, argv, "--rows", 20000));
        speed::ForestParams params;
        params.trees = std::max(1, argOr(argc, argv, "--trees", 12));
        params.maxDepth = std::max(1, argOr(argc, argv, "--depth", 10));
        auto context = platform::createOffscreenContext();
        std::printf("renderer: %s; %d rows, %d trees, depth <= %d\n",
                    gpu::queryGpuInfo().renderer.c_str(), rowCount, params.trees, params.maxDepth);

        // Rows whose label is a noisy nonlinear rule of several features: deep trees with
        // mixed leaves, so that a step taken wrongly anywhere shows in the look.
        speed::SplitMix rng(47);
        std::vector<float> rows(static_cast<std::size_t>(rowCount) * kFeatures);
        std::vector<std::uint8_t> labels(static_cast<std::size_t>(rowCount));
        for (int r = 0; r < rowCount; ++r) {
            float* f = rows.data() + static_cast<std::ptrdiff_t>(r) * kFeatures;
            for (int i = 0; i < kFeatures; ++i) {
                f[i] = static_cast<float>(rng.below(100000)) / 1000.0F - 20.0F * i;
            }
            const bool inside = (f[0] + f[3] * 0.5F > 40.0F) != (f[5] < -60.0F) ||
                                (f[7] > -110.0F && f[1] < 10.0F) || rng.below(10) == 0;
            labels[static_cast<std::size_t>(r)] = inside ? 1 : 0;
        }
        const speed::RandomForest forest =
            speed::RandomForest::train(rows, labels, kFeatures, params);
        const auto& nodes = forest.nodes();
        const auto& roots = forest.roots();
        const gpu::Buffer rowBuffer = gpu::createBuffer(
            GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(rows.size() * sizeof(float)),
            rows.data(), GL_STATIC_DRAW);
        const gpu::Buffer nodeBuffer =
            gpu::createBuffer(GL_SHADER_STORAGE_BUFFER,
                              static_cast<GLsizeiptr>(nodes.size() * sizeof(speed::ForestNode)),
                              nodes.data(), GL_STATIC_DRAW);
        const gpu::Buffer rootBuffer = gpu::createBuffer(
            GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(roots.size() * sizeof(std::int32_t)),
            roots.data(), GL_STATIC_DRAW);
        const Setup s{&forest, &rowBuffer, &nodeBuffer, &rootBuffer, rowCount};
        const int trees = static_cast<int>(roots.size());
        const std::vector<float> cpu = cpuRun(s, rows, 0, trees, params.maxDepth);
        std::size_t mixed = 0;
        for (float look : cpu) {
            mixed += std::abs(look) < 0.9F ? 1 : 0;
        }
        std::printf("%zu nodes; %zu of %d rows with a mixed look (|look| < 0.9)\n\n", nodes.size(),
                    mixed, rowCount);

        const auto line = [](const std::string& name, const Gap& g) {
            std::printf("%-58s %s: %zu rows apart, largest %.3g\n", name.c_str(),
                        g.apart == 0 ? "RIGHT" : "WRONG", g.apart, g.largest);
        };
        // The shipped walk, with the product's uniforms (its own names: no firstTree).
        const gpu::Program shipped = gpu::buildComputeProgram("speed/classifier_walk.comp");
        const Gap shippedGap = compare(run(shipped, s, 0, trees, params.maxDepth), cpu);
        line("shipped speed/classifier_walk.comp", shippedGap);
        for (const Formulation& f : kFormulations) {
            gpu::Defines defines;
            if (f.constants) {
                defines = {{"TREE_COUNT", std::to_string(trees)},
                           {"MAX_DEPTH", std::to_string(params.maxDepth)}};
            }
            const gpu::Program program = gpu::buildComputeProgramFromSource(
                f.name, std::string(kHead) + f.nodes + f.body + kMain, defines);
            line(f.name, compare(run(program, s, 0, trees, params.maxDepth), cpu));
            if (f.constants) {
                continue; // its bounds are fixed: the steps below need uniforms
            }
            // Where a wrong walk goes wrong: one tree, then the first steps alone.
            line("  tree 0 alone", compare(run(program, s, 0, 1, params.maxDepth),
                                           cpuRun(s, rows, 0, 1, params.maxDepth)));
            line("  tree 1 alone", compare(run(program, s, 1, 1, params.maxDepth),
                                           cpuRun(s, rows, 1, 1, params.maxDepth)));
            for (int depth : {0, 1, 2}) {
                line("  every tree, depth <= " + std::to_string(depth),
                     compare(run(program, s, 0, trees, depth), cpuRun(s, rows, 0, trees, depth)));
            }
        }
        return shippedGap.apart == 0 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "classifier_walk_probe: %s\n", e.what());
        return 2;
    }
}
