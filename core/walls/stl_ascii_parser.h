#pragma once
// The ASCII STL grammar, used by ReadStl/ParseStl (core/walls/mesh_io.h); not meant to be called
// directly. Accepts one or more "solid ... endsolid" blocks, keywords in any letter case, numbers
// in any C locale form (including a leading '+'), CR/LF line ends. A missing final "endsolid" is an error (kTruncated):
// a file cut after a whole facet is otherwise indistinguishable from a complete one. Coordinates come back in file units, unscaled and unfiltered.
//
// Thread-safety: free functions, no shared state.
#include <string>
#include <string_view>
#include <vector>

#include "core/walls/mesh_io.h"

namespace demcal::core {

// True if the text starts (after whitespace and an optional UTF-8 byte-order mark) with the word
// "solid", any case, followed by whitespace or the end.
bool StartsWithSolidKeyword(std::string_view text);

// Parses the whole text. On failure returns kMalformed (a syntax error), kTruncated (the text
// ends inside a facet) or kNonFinite (a NaN/infinite vertex coordinate) and sets *error to a
// message with the line number (without the file name).
MeshIoStatus ParseAsciiStl(std::string_view text, std::vector<StlTriangle>* triangles,
                           std::string* name, std::vector<std::string>* warnings,
                           std::string* error);

}  // namespace demcal::core
