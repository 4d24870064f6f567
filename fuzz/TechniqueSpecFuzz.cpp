// libFuzzer target: the `-t technique:key=value...` text (techniques/PropertySet.h), parsed, applied to
// the technique it names (every entry of the registry: their knobs, types and ranges), and the small
// option parsers beside it (--size WxH, --shard i/N). Bad input must end in sb::Error. The promises of
// PropertySet.h are checked too, since a CSV row is re-run from what it recorded:
//   - TechniqueSpec::toString() parses back to the same spec;
//   - a technique's PropertySet::toString() (canonical, every knob) applied to a fresh technique gives
//     the same canonical string.
// The reach outcome is the spec's: "parsed" when the spec parses and applies to its technique.
// Seeds: fuzz/corpus/technique_spec/ (specs of the tests and sweeps, one per file).
#include <cstddef>
#include <cstdint>
#include <string>

#include "bench/lib/options/RunOptions.h"
#include "bench/lib/sweep/SweepPlan.h"
#include "core/Error.h"
#include "fuzz/FuzzReach.h"
#include "registry/TechniqueRegistry.h"
#include "techniques/PropertySet.h"

namespace {

/// The option parsers that take the same kind of text: their errors are fine, any other end is not.
void parseOptionValues(const std::string& text) {
    try {
        sb::RunOptions::parseSize(text);
    } catch (const sb::Error&) {
    }
    try {
        sb::parseShard(text);
    } catch (const sb::Error&) {
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text = sb::fuzz::text(data, size);
    parseOptionValues(text);
    try {
        const sb::TechniqueSpec spec = sb::TechniqueSpec::parse(text);
        const std::string printed = spec.toString();
        const sb::TechniqueSpec again = sb::TechniqueSpec::parse(printed);
        sb::fuzz::require(again.name == spec.name && again.properties == spec.properties,
                          "TechniqueSpec '" + text + "' prints as '" + printed +
                              "', which parses differently");

        const auto technique = sb::TechniqueRegistry::describe(spec);
        const std::string canonical = technique->properties().toString();
        const auto copy = sb::TechniqueRegistry::describe(
            sb::TechniqueSpec::parse(canonical.empty() ? spec.name : spec.name + ":" + canonical));
        sb::fuzz::require(copy->properties().toString() == canonical,
                          "properties of '" + text + "' print as '" + canonical + "', which applies as '" +
                              copy->properties().toString() + "'");
        sb::fuzz::reached(sb::fuzz::Outcome::Parsed, spec.name + ":" + canonical);
    } catch (const sb::Error& e) {
        sb::fuzz::reached(sb::fuzz::Outcome::Rejected, e.what());
    }
    return 0;
}
