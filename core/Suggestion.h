#pragma once
// "Did you mean": the nearest valid name to a mistyped one, by edit distance. The one helper behind every
// site that rejects a name (bench's options and subcommands, techniques, their properties, scenes), so
// they all suggest alike.
#include <string>
#include <string_view>
#include <vector>

namespace sb {

class Suggestion {
public:
    /// Optimal string alignment distance: insertions, deletions, substitutions and transpositions of
    /// two adjacent characters each count one ("resolutoin" is one from "resolution").
    static size_t distance(std::string_view a, std::string_view b);
    /// The candidate nearest to `word`, or "" when none is near enough to be a likely typo: at most
    /// max(1, (|word| + 2) / 4) edits, or `word` a prefix (3 characters or more) of exactly one
    /// candidate. Ties go to the earlier candidate.
    static std::string nearest(const std::string& word, const std::vector<std::string>& candidates);
    /// " (did you mean NAME?)" for nearest(), or "" when there is none: appended to an error message.
    static std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);
};

} // namespace sb
