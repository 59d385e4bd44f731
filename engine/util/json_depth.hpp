#pragma once
// JSON nesting guard. nlohmann::json (and tinygltf's copy of it) parse recursively, so a file holding
// 100 000 nested brackets exhausts the stack and kills the process before any check runs. Callers
// scan the text first (iteratively, skipping strings) and refuse deeper nesting with a clear message.
#include <cstddef>
#include <string_view>

namespace ppr::util {

constexpr size_t kMaxJsonNesting = 256;  // far beyond any reflector file or glTF (glTF needs ~10)

// Byte offset of the first '[' or '{' that opens level maxDepth + 1, or npos when the text stays
// within maxDepth (unbalanced or malformed text is left to the parser).
size_t jsonNestingExceeded(std::string_view text, size_t maxDepth = kMaxJsonNesting);

}  // namespace ppr::util
