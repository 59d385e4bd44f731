#include "graph/blackboard.hpp"

#include <gtest/gtest.h>

using namespace ppr::graph;

namespace {
struct Lit {
    int id = 0;
};
struct Reflection {
    int id = 0;
};
}  // namespace

TEST(Blackboard, ValuesAreKeyedByType) {
    Blackboard bb;
    EXPECT_FALSE(bb.has<Lit>());
    EXPECT_EQ(bb.find<Lit>(), nullptr);
    bb.put(Lit{3});
    bb.put(Reflection{7});
    ASSERT_TRUE(bb.has<Lit>());
    EXPECT_EQ(bb.get<Lit>().id, 3);
    EXPECT_EQ(bb.get<Reflection>().id, 7);
}

TEST(Blackboard, PutReplacesAndEraseRemoves) {
    Blackboard bb;
    bb.put(Lit{1});
    bb.put(Lit{2});
    EXPECT_EQ(bb.get<Lit>().id, 2);
    bb.erase<Lit>();
    EXPECT_FALSE(bb.has<Lit>());
}

TEST(Blackboard, MissingValueNamesTheType) {
    Blackboard bb;
    try {
        bb.get<Reflection>();
        FAIL() << "expected a throw";
    } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("Reflection"), std::string::npos) << e.what();
    }
}
