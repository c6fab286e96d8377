// C source text of the values an exported reproducer embeds: arrays of
// words and bytes, floats that read back to the same bits, string literals.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rayspec {

// "static const uint32_t NAME[] = {...};" (eight words a line, hex); an
// empty list holds one zero word, since C has no empty array.
std::string cWordArray(const std::string& name, const std::vector<uint32_t>& words);
// "static const uint8_t NAME[] = {...};" (sixteen bytes a line); the same
// for an empty list.
std::string cByteArray(const std::string& name, const std::vector<uint8_t>& bytes);
// A float literal that reads back to f exactly (C99 hex float), "NAN" or
// "INFINITY" where needed.
std::string cFloat(float f);
// A C string literal of text ("..." with \\, \" and control bytes escaped).
std::string cString(const std::string& text);
// text as // comment lines.
std::string cComment(const std::string& text);

}  // namespace rayspec
