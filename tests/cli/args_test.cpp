#include "cli/args.hpp"

#include <gtest/gtest.h>

namespace steerseg::cli {
namespace {

TEST(Args, ParsesValuesFlagsAndPositionals) {
    const std::vector<std::string> w{"scan.nii", "--seed", "1,2,3,4", "--seed=5,6,7,8",
                                     "--dense",  "--T",    "40"};
    const Args a(w, {"seed", "T"}, {"dense"});
    EXPECT_EQ(a.positional(), std::vector<std::string>{"scan.nii"});
    EXPECT_EQ(a.values("seed").size(), 2U);
    EXPECT_TRUE(a.flag("dense"));
    EXPECT_DOUBLE_EQ(*a.number("T"), 40.0);
}

TEST(Args, RejectsUnknownMissingAndMalformed) {
    EXPECT_THROW(Args(std::vector<std::string>{"--nope"}, {}, {}), UsageError);
    EXPECT_THROW(Args(std::vector<std::string>{"--T"}, {"T"}, {}), UsageError);
    const Args a(std::vector<std::string>{"--T", "nan"}, {"T"}, {});
    EXPECT_THROW((void)a.number("T"), UsageError);
    EXPECT_THROW(parseNumberList("1,2", 4, "--seed"), UsageError);
    EXPECT_THROW(parseInteger("12x", "--iterations"), UsageError);
}

} // namespace
} // namespace steerseg::cli
