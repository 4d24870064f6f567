#include "techniques/MatrixVariant.h"

namespace sb {

const char* accuracyRuleName(AccuracyRule rule) {
    switch (rule) {
    case AccuracyRule::Exact:
        return "exact";
    case AccuracyRule::Map:
        return "map";
    case AccuracyRule::NoShadow:
        return "no_shadow";
    case AccuracyRule::Approximate:
        return "approximate";
    case AccuracyRule::SoftApproximate:
        return "soft_approximate";
    case AccuracyRule::NotJudged:
        return "not_judged";
    }
    return "?";
}

} // namespace sb
