#include "shading/CompileLog.h"

namespace sb {

std::string leadWithFirstError(std::string log) {
    log.erase(log.find_last_not_of(" \n\r\t") + 1);
    size_t start = 0;
    while (start < log.size()) {
        const size_t end = log.find('\n', start);
        const std::string line =
            log.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (line.find("error") != std::string::npos || line.find("ERROR") != std::string::npos)
            return line + (log == line ? "" : "\nfull log:\n" + log);
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return log;
}

} // namespace sb
