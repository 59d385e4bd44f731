// Deeply nested JSON is refused with one line before the recursive parsers run: a reflector file or a
// .gltf of 100 000 nested brackets used to kill the process (stack overflow, exit 139).
#include "scene/errors.hpp"
#include "scene/reflector.hpp"
#include "scene/scene.hpp"
#include "util/json_depth.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace ppr;

namespace {

std::string nested(size_t depth, char open = '[', char close = ']') { return std::string(depth, open) + std::string(depth, close); }

template <class F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST(JsonNesting, CountsBracketsOutsideStringsOnly) {
    EXPECT_EQ(util::jsonNestingExceeded(nested(256)), std::string_view::npos);
    EXPECT_EQ(util::jsonNestingExceeded(nested(257)), 256u);  // the bracket that opens level 257
    EXPECT_EQ(util::jsonNestingExceeded("{\"a\":" + nested(300, '{', '}').substr(0, 0) + "\"" + std::string(1000, '[') + "\"}"),
              std::string_view::npos)
        << "brackets inside a string are text";
    EXPECT_EQ(util::jsonNestingExceeded("[\"\\\"[[[\"]", 1), std::string_view::npos) << "an escaped quote does not end the string";
    EXPECT_EQ(util::jsonNestingExceeded("[[]][[]]", 2), std::string_view::npos) << "siblings do not add up";
    EXPECT_EQ(util::jsonNestingExceeded("]]]][[[", 2), 6u) << "stray closers do not buy depth";
}

TEST(JsonNesting, ReflectorFileIsRefusedWithOneLine) {
    const std::string text = "{\"version\":1,\"reflectors\":" + nested(100000) + "}";
    const std::string e = errorOf([&] { scene::parseReflectorFile(text, "deep.json"); });
    EXPECT_EQ(e, "deep.json: JSON nested deeper than 256 levels at byte 282");
}

TEST(JsonNesting, GltfIsRefusedWithOneLine) {
    const auto path = std::filesystem::temp_directory_path() / "ppr-deep-nesting.gltf";
    std::ofstream(path) << "{\"asset\":{\"version\":\"2.0\"},\"extras\":" << nested(100000, '{', '}').replace(1, 0, "\"a\":") << "}";
    const std::string e = errorOf([&] { scene::loadGltf(path.string()); });
    EXPECT_NE(e.find("ppr-deep-nesting.gltf: JSON nested deeper than 256 levels at byte"), std::string::npos) << e;
    std::filesystem::remove(path);
}
