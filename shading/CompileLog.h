#pragma once
// A compiler's log as a user reads it: the first line that reports an error leads (it is the one line an
// error message shows), the whole log follows. Mesa's GL compiler writes "error:", glslang "ERROR:".
#include <string>

namespace sb {

/// `log` trimmed, its first error line first ("...\nfull log:\n<log>"); the log itself when it has none.
std::string leadWithFirstError(std::string log);

} // namespace sb
