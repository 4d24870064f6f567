#include "bench/golden/MatrixVariants.h"

#include <algorithm>
#include <cctype>

#include "bench/lib/select/AutoResolver.h"
#include "core/Error.h"
#include "core/Strings.h"
#include "registry/TechniqueRegistry.h"

namespace sb {

namespace {

/// The variants `name` declares (its declaration at its defaults: TechniqueRegistry::describe, which
/// needs no API). An unknown name is the registry's error.
std::vector<MatrixVariant> declared(const std::string& name) {
    return TechniqueRegistry::describe(TechniqueSpec{name, {}})->info().matrixVariants;
}

bool keepsCharacter(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '=' || c == '-' || c == '_' ||
           c == ',';
}

} // namespace

std::vector<std::string> MatrixVariants::of(const std::string& name) {
    std::vector<std::string> out{name};
    for (const MatrixVariant& v : declared(name)) out.push_back(name + ":" + v.properties);
    return out;
}

std::vector<std::string> MatrixVariants::all() {
    std::vector<std::string> out;
    for (const std::string& name : TechniqueRegistry::names())
        for (std::string& form : of(name)) out.push_back(std::move(form));
    return out;
}

std::vector<std::string> MatrixVariants::select(const std::vector<std::string>& requested) {
    std::vector<std::string> out;
    auto add = [&](const std::string& form) {
        if (std::find(out.begin(), out.end(), form) == out.end()) out.push_back(form);
    };
    for (const std::string& asked : requested) {
        if (asked == AutoResolver::kName) {
            add(asked);
            continue;
        }
        const TechniqueSpec spec = TechniqueSpec::parse(asked); // a malformed spec says what is wrong
        const std::vector<std::string> forms = of(spec.name);   // an unknown name: the registry's error
        if (spec.properties.empty()) {
            for (const std::string& form : forms) add(form);
        } else if (std::find(forms.begin(), forms.end(), spec.toString()) != forms.end()) {
            add(spec.toString());
        } else {
            throw Error("--technique " + asked + ": not a form the matrix renders; " + spec.name + "'s are " +
                            join(forms, ", ") + " (its name alone selects them all)",
                        ExitCode::BadInput);
        }
    }
    return out;
}

std::optional<MatrixVariant> MatrixVariants::variantOf(const std::string& technique) {
    if (technique.find(':') == std::string::npos) return std::nullopt; // a default form: no properties
    const TechniqueSpec spec = TechniqueSpec::parse(technique);
    const std::string properties = technique.substr(spec.name.size() + 1);
    for (const MatrixVariant& v : declared(spec.name))
        if (v.properties == properties) return v;
    throw Error("'" + technique + "' is not a form the matrix renders (" + join(of(spec.name), ", ") + ")",
                ExitCode::BadInput);
}

std::string MatrixVariants::nameOf(const std::string& technique) {
    return technique.substr(0, technique.find(':'));
}

std::string MatrixVariants::key(const std::string& technique) {
    std::string out = technique;
    std::replace(out.begin(), out.end(), ':', '.');
    for (char& c : out)
        if (!keepsCharacter(c)) c = '_';
    return out;
}

} // namespace sb
