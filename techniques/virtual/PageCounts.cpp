#include "techniques/virtual/PageCounts.h"

namespace sb {

Counters PageCounts::toCounters() const {
    return {{"pages_needed", double(needed)},           {"pages_allocated", double(allocated)},
            {"pages_rendered", double(rendered)},       {"pages_reused", double(reused)},
            {"pages_invalidated", double(invalidated)}, {"pages_evicted", double(evicted)},
            {"pages_dropped", double(dropped)},         {"pages_resident", double(resident)}};
}

} // namespace sb
