#pragma once
// A shader permutation's defines, the same on both APIs: the key logged in every row (the permutation
// column), the cache key of compiled programs and modules, and a folder of the shader dump.
#include <cstddef>
#include <map>
#include <string>

namespace sb {

/// Sorted NAME -> VALUE list; the key of a permutation. VALUE "" means "#define NAME 1".
using Defines = std::map<std::string, std::string>;
/// 64-bit FNV-1a of `text`'s bytes as 16 hex digits (core/Fnv1a.h): the short name of a long key.
std::string hash64(const std::string& text);
/// Values longer than this are written into definesKey as '#' and their 64-bit FNV-1a hash.
constexpr size_t kLongDefineValue = 24;
/// "PCF_SIZE=3,SB_INSTANCED" style key: sorted, comma separated, VALUE 1 and "" omitted, a value longer
/// than kLongDefineValue as "#<16 hex digits>" (the scene's light constants: a shader dump's folder name
/// stays within a file name's limit, and the dumped source spells the value out).
std::string definesKey(const Defines& d);
/// Every define with its value spelled out ("A=1;B=3;"): a cache key that tells "" from "1" apart
/// where a source could (it cannot today, but a cache must not rely on it).
std::string fullDefinesKey(const Defines& d);

} // namespace sb
