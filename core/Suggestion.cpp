#include "core/Suggestion.h"

#include <algorithm>

namespace sb {

size_t Suggestion::distance(std::string_view a, std::string_view b) {
    // Three rows of the dynamic programme: a transposition looks two rows back.
    const size_t n = b.size();
    std::vector<size_t> before(n + 1), previous(n + 1), current(n + 1);
    for (size_t j = 0; j <= n; ++j) previous[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (size_t j = 1; j <= n; ++j) {
            const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                current[j] = std::min(current[j], before[j - 2] + 1);
        }
        std::swap(before, previous);
        std::swap(previous, current);
    }
    return previous[n];
}

std::string Suggestion::nearest(const std::string& word, const std::vector<std::string>& candidates) {
    // A quarter of the word's length: a long name survives a few slips, a short one only one, so that
    // "x" is not "corrected" to an unrelated two-letter name.
    const size_t limit = std::max<size_t>(1, (word.size() + 2) / 4);
    std::string best;
    size_t bestDistance = limit + 1;
    for (const std::string& c : candidates) {
        const size_t d = distance(word, c);
        if (d < bestDistance) best = c, bestDistance = d;
    }
    if (!best.empty() || word.size() < 3) return best;
    // An abbreviation: "gol" for golden, when nothing else begins the same way.
    std::vector<std::string> prefixed;
    for (const std::string& c : candidates)
        if (c.rfind(word, 0) == 0) prefixed.push_back(c);
    return prefixed.size() == 1 ? prefixed.front() : std::string();
}

std::string Suggestion::didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
    const std::string best = nearest(word, candidates);
    return best.empty() || best == word ? std::string() : " (did you mean " + best + "?)";
}

} // namespace sb
