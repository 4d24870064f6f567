#include "scenes/SceneDocumentCost.h"

#include <vector>

#include <nlohmann/json.hpp>

namespace sb {
namespace {

/// glibc malloc's chunk for a request: the request plus 8 B of header, rounded up to 16, at least 32.
uint64_t chunk(uint64_t request) {
    const uint64_t rounded = (request + 8 + 15) / 16 * 16;
    return rounded < 32 ? 32 : rounded;
}

/// A std::string's heap buffer (none for the 15 characters kept inside the object).
uint64_t stringHeap(uint64_t length) {
    return length > 15 ? chunk(length + 1) : 0;
}

constexpr uint64_t kValueBytes = 16;        ///< sizeof(nlohmann::json)
constexpr uint64_t kMapBytes = 64;          ///< chunk(sizeof(std::map)), an object's members
constexpr uint64_t kMapNodeBytes = 96;      ///< chunk(rb-tree header 32 + key 32 + value 16)
constexpr uint64_t kVectorBytes = 32;       ///< chunk(sizeof(std::vector)), an array's elements
constexpr uint64_t kStringObjectBytes = 48; ///< chunk(sizeof(std::string)), a string value

/// The SAX events of nlohmann::json, summed into a SceneDocumentCost. Arrays are charged per element
/// (two slots each); objects per member (a map node and the key's heap).
class Counter : public nlohmann::json_sax<nlohmann::json> {
public:
    explicit Counter(SceneDocumentCost& cost) : mCost(cost) {}

    bool null() override { return value(0); }
    bool boolean(bool) override { return value(0); }
    bool number_integer(number_integer_t) override { return value(0); }
    bool number_unsigned(number_unsigned_t) override { return value(0); }
    bool number_float(number_float_t, const string_t&) override { return value(0); }
    bool string(string_t& s) override { return value(kStringObjectBytes + stringHeap(s.size())); }
    bool binary(binary_t&) override { return value(0); }
    bool start_object(std::size_t) override {
        value(kMapBytes);
        mStack.push_back(Frame{true, false});
        return true;
    }
    bool key(string_t& k) override {
        mCost.documentBytes += kMapNodeBytes + stringHeap(k.size());
        // The root object's "instances" array is the one whose elements are counted.
        mPendingInstances = mStack.size() == 1 && k == "instances";
        return true;
    }
    bool end_object() override {
        mStack.pop_back();
        return true;
    }
    bool start_array(std::size_t) override {
        const bool instances = mPendingInstances;
        value(kVectorBytes);
        mStack.push_back(Frame{false, instances});
        return true;
    }
    bool end_array() override {
        mStack.pop_back();
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
        return false; // JsonReader::parse reports it, with the line and column
    }

private:
    struct Frame {
        bool object = false;
        bool instances = false; ///< the top-level "instances" array
    };

    /// One value of `heap` bytes beyond its 16: in an array it takes two slots (growth), in an object
    /// its 16 B are part of the member's node, already charged by key().
    bool value(uint64_t heap) {
        ++mCost.values;
        mCost.documentBytes += heap;
        if (mStack.empty()) {
            mCost.documentBytes += kValueBytes;
        } else if (!mStack.back().object) {
            mCost.documentBytes += 2 * kValueBytes;
            if (mStack.back().instances) ++mCost.instances;
        }
        mPendingInstances = false;
        return true;
    }

    SceneDocumentCost& mCost;
    std::vector<Frame> mStack;
    bool mPendingInstances = false;
};

} // namespace

SceneDocumentCost SceneDocumentCost::measure(const std::string& text) {
    SceneDocumentCost cost;
    Counter counter(cost);
    try {
        nlohmann::json::sax_parse(text, &counter, nlohmann::json::input_format_t::json, true,
                                  /*ignore_comments=*/true);
    } catch (const std::exception&) {
        // Counted as far as it parsed; JsonReader::parse reports the error.
    }
    return cost;
}

} // namespace sb
