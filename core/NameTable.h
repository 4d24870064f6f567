#pragma once
// The one way an enum meets its names: a constexpr array of entries, each with a `value` and a `name`,
// and the lookups every such table needs (name of a value, value of a name, the list of names for help
// and error text). An entry may carry more fields (the backend table carries its factory); a value may
// have several names, the first being its canonical one and the others accepted aliases.
//
//   constexpr Named<LightType> kLightTypes[] = {{LightType::Directional, "directional"}, ...};
//   constexpr NameTable kLightTypeNames{kLightTypes};
//   kLightTypeNames.name(LightType::Point)  -> "point"
//   kLightTypeNames.parse("spot")           -> LightType::Spot
//   kLightTypeNames.choices()               -> "directional, point or spot"
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sb {

/// The plain entry: a value and one of its names.
template <typename E>
struct Named {
    E value;
    const char* name;
};

template <typename Entry>
class NameTable {
public:
    using Value = decltype(Entry::value);

    template <size_t N>
    constexpr NameTable(const Entry (&entries)[N]) : mEntries(entries, N) {}

    constexpr std::span<const Entry> entries() const { return mEntries; }

    /// The first entry with `value`, or nullptr.
    constexpr const Entry* find(Value value) const {
        for (const Entry& e : mEntries)
            if (e.value == value) return &e;
        return nullptr;
    }
    /// The entry named `name` (exact, case-sensitive), or nullptr.
    constexpr const Entry* find(std::string_view name) const {
        for (const Entry& e : mEntries)
            if (name == e.name) return &e;
        return nullptr;
    }
    /// The canonical name of `value`; `fallback` only for a value outside the table (an enum cast from
    /// an out-of-range integer).
    constexpr const char* name(Value value, const char* fallback = "?") const {
        const Entry* e = find(value);
        return e ? e->name : fallback;
    }
    std::optional<Value> parse(std::string_view name) const {
        const Entry* e = find(name);
        return e ? std::optional<Value>(e->value) : std::nullopt;
    }
    /// Every accepted name, aliases included, in table order: "console, csv, json, md, markdown".
    std::string list(std::string_view separator = ", ") const {
        std::string out;
        for (const Entry& e : mEntries) {
            if (!out.empty()) out += separator;
            out += e.name;
        }
        return out;
    }
    /// The canonical names for prose, the last joined by `last`: "immediate, displaylist, retained or
    /// instanced".
    std::string choices(std::string_view last = " or ") const {
        return labelledChoices([](const Entry& e) { return std::optional<std::string>(e.name); }, last);
    }
    /// The same prose list of labels `label(entry)` gives for the canonical entries, leaving out those
    /// it answers std::nullopt for: "console (tables), csv, json or md".
    template <typename Label>
    std::string labelledChoices(Label label, std::string_view last = " or ") const {
        std::vector<std::string> labels;
        for (const Entry& e : mEntries)
            if (find(e.value) == &e) // aliases stay unlisted
                if (std::optional<std::string> text = label(e)) labels.push_back(std::move(*text));
        std::string out;
        for (size_t i = 0; i < labels.size(); ++i)
            out += std::string(i == 0 ? "" : i + 1 == labels.size() ? last : ", ") + labels[i];
        return out;
    }

private:
    std::span<const Entry> mEntries;
};

} // namespace sb
