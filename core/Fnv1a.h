#pragma once
// FNV-1a, 64 bit: the content hashes recorded in result rows (scene_hash, sweep_id). Not
// cryptographic; it only has to tell two definitions apart and be the same on every machine.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace sb {

class Fnv1a {
public:
    void bytes(const void* data, size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) mHash = (mHash ^ p[i]) * 1099511628211ull;
    }
    template <typename T>
    void value(const T& v) {
        bytes(&v, sizeof(T));
    }
    template <typename T>
    void vector(const std::vector<T>& v) {
        value(uint64_t(v.size()));
        if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
    }
    void string(const std::string& s) {
        value(uint64_t(s.size()));
        bytes(s.data(), s.size());
    }
    uint64_t result() const { return mHash; }
    /// 16 lower-case hex digits.
    std::string hex() const {
        char out[17];
        std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(mHash));
        return out;
    }

private:
    uint64_t mHash = 14695981039346656037ull;
};

} // namespace sb
