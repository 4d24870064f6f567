// The edit distance behind every "did you mean" (core/Suggestion.h), against distances counted by hand,
// and which names it offers and withholds.
#include <gtest/gtest.h>

#include "core/Suggestion.h"

using sb::Suggestion;

TEST(DidYouMeanTest, DistanceCountsEachEditOnce) {
    EXPECT_EQ(Suggestion::distance("", ""), 0u);
    EXPECT_EQ(Suggestion::distance("abc", ""), 3u);    // three deletions
    EXPECT_EQ(Suggestion::distance("", "golden"), 6u); // six insertions
    EXPECT_EQ(Suggestion::distance("golde", "golden"), 1u);
    EXPECT_EQ(Suggestion::distance("kitten", "sitting"), 3u); // k->s, e->i, +g
    EXPECT_EQ(Suggestion::distance("--instanses", "--instances"), 1u);
    EXPECT_EQ(Suggestion::distance("flaw", "lawn"), 2u);
}

TEST(DidYouMeanTest, AdjacentTranspositionIsOneEdit) {
    EXPECT_EQ(Suggestion::distance("resolutoin", "resolution"), 1u);
    EXPECT_EQ(Suggestion::distance("ab", "ba"), 1u);
    // Optimal string alignment: a transposed pair is not edited again ("ca" -> "abc" is 3, not 2).
    EXPECT_EQ(Suggestion::distance("ca", "abc"), 3u);
    EXPECT_EQ(Suggestion::distance("aircarft", "aircraft"), 1u);
}

TEST(DidYouMeanTest, NearestIsTheClosestLikelyTypo) {
    const std::vector<std::string> modes = {"accuracy", "sweep", "bottleneck", "figures", "golden", "ci"};
    EXPECT_EQ(Suggestion::nearest("golde", modes), "golden");
    EXPECT_EQ(Suggestion::nearest("swep", modes), "sweep");
    EXPECT_EQ(Suggestion::nearest("bottelneck", modes), "bottleneck");
    // An abbreviation of one name only.
    EXPECT_EQ(Suggestion::nearest("gol", modes), "golden");
    // Ties go to the earlier candidate: "bc" is one from both.
    EXPECT_EQ(Suggestion::nearest("bc", {"ac", "bd"}), "ac");
}

TEST(DidYouMeanTest, FarWordsGetNoSuggestion) {
    const std::vector<std::string> properties = {"resolution", "bias", "hw", "mode", "offset"};
    EXPECT_EQ(Suggestion::nearest("x", properties), ""); // two edits from "hw": a guess, not a typo
    EXPECT_EQ(Suggestion::nearest("teleport", properties), "");
    EXPECT_EQ(Suggestion::nearest("mo", {"mode", "model"}), "");   // too short to abbreviate
    EXPECT_EQ(Suggestion::nearest("mod", {"model", "modes"}), ""); // a prefix of two: ambiguous
    EXPECT_EQ(Suggestion::nearest("anything", {}), "");
}

TEST(DidYouMeanTest, DidYouMeanIsTheMessageTail) {
    EXPECT_EQ(Suggestion::didYouMean("--instanses", {"--instances", "--scene"}),
              " (did you mean --instances?)");
    EXPECT_EQ(Suggestion::didYouMean("zzzz", {"--instances"}), "");
    EXPECT_EQ(Suggestion::didYouMean("golden", {"golden"}), ""); // an exact name is no typo
}
