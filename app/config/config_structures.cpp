// [[structures]]: the site's list of structures (docs/structures.md), each a name, its coded
// category and type ([value, scheme, meaning]) and an optional colour; [segmentation]'s
// structures_overlap. A file that has the list replaces it whole, as [[input.devices]] does:
// a site's list is one thing, not a patch on the shipped one.
#include "config/config_sections.hpp"

#include <algorithm>

namespace steerseg::config::detail {

namespace {

constexpr std::size_t kMaxKinds = 64; // a panel's list, as model::kMaxStructures

// [value, scheme, meaning], three non-empty strings; nullopt after reporting what is wrong.
std::optional<model::StructureCode> readCode(TableReader& t, std::string_view key) {
    if (!t.has(key)) {
        t.sink().add(t.source().source(), t.path(key),
                     "is missing: give [\"code value\", \"scheme\", \"meaning\"], e.g. "
                     "[\"10200004\", \"SCT\", \"Liver\"]");
        return std::nullopt;
    }
    const toml::array* a = t.array(key);
    if (a == nullptr) {
        return std::nullopt;
    }
    std::vector<std::string> parts;
    for (const toml::node& n : *a) {
        if (const auto* s = n.as_string()) {
            parts.push_back(s->get());
        }
    }
    model::StructureCode code;
    if (parts.size() == 3 && a->size() == 3) {
        code = {parts[0], parts[1], parts[2]};
    }
    const std::string problem =
        parts.size() == 3 && a->size() == 3
            ? model::structureCodeProblem(code)
            : std::string("must be three strings: [value, scheme, meaning]");
    if (!problem.empty()) {
        t.problem(key, problem);
        return std::nullopt;
    }
    return code;
}

std::optional<glm::dvec3> readColour(TableReader& t) {
    const toml::array* a = t.array("colour");
    if (a == nullptr) {
        return std::nullopt;
    }
    if (a->size() != 3) {
        t.problem("colour", "must be [r, g, b], each within 0..1");
        return std::nullopt;
    }
    glm::dvec3 c(0.0);
    for (std::size_t i = 0; i < 3; ++i) {
        const auto v = readNumber(*a->get(i), t.path("colour") + "[" + std::to_string(i + 1) + "]",
                                  {0.0, 1.0}, t.sink());
        if (!v) {
            return std::nullopt;
        }
        c[static_cast<int>(i)] = *v;
    }
    return c;
}

} // namespace

void readStructures(const toml::array& entries, std::vector<model::StructureInfo>& kinds,
                    ProblemSink& sink) {
    std::vector<model::StructureInfo> next;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const toml::node& node = *entries.get(i);
        const std::string prefix = "structures[" + std::to_string(i + 1) + "]";
        const toml::table* table = node.as_table();
        if (table == nullptr) {
            sink.add(node.source(), prefix,
                     "expected a table ([[structures]]), got something else");
            continue;
        }
        TableReader t(*table, prefix, sink);
        model::StructureInfo kind;
        const auto name = t.text("name", [](std::string_view s) {
            const std::string problem = model::structureNameProblem(s);
            return problem.empty() ? problem : "is no structure name: " + problem;
        });
        if (!t.has("name")) {
            sink.add(table->source(), prefix, "has no name");
        }
        const auto category = readCode(t, "category");
        const auto type = readCode(t, "type");
        const auto colour = readColour(t);
        t.reportUnknownKeys();
        if (!name || !category || !type || (t.has("colour") && !colour)) {
            continue;
        }
        if (std::any_of(next.begin(), next.end(),
                        [&](const model::StructureInfo& k) { return k.name == *name; })) {
            t.problem("name", "\"" + *name + "\" is given twice");
            continue;
        }
        if (next.size() >= kMaxKinds) {
            sink.add(table->source(), prefix, "more than 64 structures");
            continue;
        }
        kind.name = *name;
        kind.category = *category;
        kind.type = *type;
        kind.colour = colour.value_or(model::paletteColour(next.size()));
        next.push_back(std::move(kind));
    }
    kinds = std::move(next);
}

void readSegmentation(TableReader& table, SegmentationConfig& segmentation) {
    if (auto v = table.boolean("structures_overlap")) {
        segmentation.structuresOverlap = *v;
    }
}

} // namespace steerseg::config::detail
