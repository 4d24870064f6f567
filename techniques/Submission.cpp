#include "techniques/Submission.h"

namespace sb {

namespace {

// The one table of submission modes, in kAllSubmitModes's order.
constexpr Named<SubmitMode> kSubmitModes[] = {
    {SubmitMode::Immediate, "immediate"},
    {SubmitMode::DisplayList, "displaylist"},
    {SubmitMode::Retained, "retained"},
    {SubmitMode::Instanced, "instanced"},
};
constexpr NameTable kSubmitModeTable{kSubmitModes};

} // namespace

const NameTable<Named<SubmitMode>>& submitModes() {
    return kSubmitModeTable;
}

const char* submitModeName(SubmitMode m) {
    return kSubmitModeTable.name(m);
}

std::optional<SubmitMode> parseSubmitMode(const std::string& name) {
    return kSubmitModeTable.parse(name);
}

} // namespace sb
