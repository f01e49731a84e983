// A CRC-valid autosave whose counts no session can have (seeds = -3, a negative evolved time)
// is refused by the decoder with one line naming the field, as a damaged one is, so the resume
// falls back to the autosave before it instead of showing the operator -3 seeds.
#include "autosave/autosave_snapshot.hpp"

#include <gtest/gtest.h>
#include <limits>

namespace steerseg::test {
namespace {

using autosave::AutosaveSnapshot;

AutosaveSnapshot plausible() {
    AutosaveSnapshot s;
    s.scan = {"builtin:sample", 0, 0};
    s.dims = {4, 3, 2};
    s.state = model::State::Paused;
    s.seeds = 2;
    s.erasures = 1;
    s.iterations = 40;
    s.evolvedTime = 3.5;
    return s;
}

std::string decodeError(const AutosaveSnapshot& s) {
    try {
        (void)autosave::decodeSnapshot(autosave::encodeSnapshot(s));
    } catch (const autosave::AutosaveFormatError& e) {
        return e.what();
    }
    return "(decoded)";
}

TEST(FaultsAutosaveCounts, APlausibleSnapshotDecodes) {
    EXPECT_EQ(decodeError(plausible()), "(decoded)");
}

TEST(FaultsAutosaveCounts, NegativeAndAbsurdCountsAreRefusedByName) {
    struct Case {
        const char* field;
        void (*spoil)(AutosaveSnapshot&);
    };
    const Case cases[] = {
        {"seeds", [](AutosaveSnapshot& s) { s.seeds = -3; }},
        {"erasures", [](AutosaveSnapshot& s) { s.erasures = -1; }},
        {"iterations", [](AutosaveSnapshot& s) { s.iterations = -7; }},
        {"evolved_time", [](AutosaveSnapshot& s) { s.evolvedTime = -0.5; }},
        {"seeds", [](AutosaveSnapshot& s) { s.seeds = std::numeric_limits<int>::max(); }},
    };
    for (const Case& c : cases) {
        AutosaveSnapshot s = plausible();
        c.spoil(s);
        const std::string m = decodeError(s);
        SCOPED_TRACE(m);
        EXPECT_NE(m.find(c.field), std::string::npos);
        EXPECT_EQ(m.find('\n'), std::string::npos);
    }
}

} // namespace
} // namespace steerseg::test
