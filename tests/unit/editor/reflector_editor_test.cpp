// The reflector editor's document model (app/reflector_editor.cpp): undo/redo, drags as one step,
// the unsaved mark, snap creation, save/load and the handle math. Pure logic: no GPU, no UI.
#include "editor/reflector_editor.hpp"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <unistd.h>

using namespace ppr::app;
using ppr::scene::Reflector;
using ppr::scene::ReflectorKind;
namespace fs = std::filesystem;

namespace {

Reflector makeReflector(const std::string& name, glm::vec3 center = {0, 0, 0}) {
    Reflector r;
    r.name = name;
    r.center = center;
    r.normal = {0, 1, 0};
    r.tangent = {1, 0, 0};
    r.halfExtents = {1.0f, 0.5f};
    r.kind = ReflectorKind::Opaque;
    r.reflectance = 0.8f;
    return r;
}

// A tilted reflector, so the handle math is not just checked on axis-aligned planes.
Reflector tiltedReflector() {
    Reflector r = makeReflector("tilted", {1.0f, 2.0f, -3.0f});
    r.normal = glm::normalize(glm::vec3(0.3f, 0.8f, -0.5f));
    r.tangent = glm::normalize(glm::cross(glm::vec3(0, 0, 1), r.normal));
    r.halfExtents = {0.7f, 0.4f};
    return r;
}

std::string describe(const std::vector<Reflector>& v) {
    std::ostringstream s;
    for (const auto& r : v)
        s << "[" << r.name << " c=(" << r.center.x << "," << r.center.y << "," << r.center.z << ") t=(" << r.tangent.x << ","
          << r.tangent.y << "," << r.tangent.z << ") h=(" << r.halfExtents.x << "," << r.halfExtents.y << ") k="
          << int(r.kind) << " refl=" << r.reflectance << "] ";
    return s.str();
}

#define EXPECT_SAME(a, b) EXPECT_TRUE(sameReflectors((a), (b))) << "got " << describe(a) << "\nwant " << describe(b)

struct TempDir {
    fs::path path;
    TempDir() {
        static int counter = 0;
        path = fs::temp_directory_path() / ("ppr_editor_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string file(const std::string& name) const { return (path / name).string(); }
    std::vector<std::string> entries() const {
        std::vector<std::string> out;
        for (const auto& e : fs::directory_iterator(path)) out.push_back(e.path().filename().string());
        std::sort(out.begin(), out.end());
        return out;
    }
};

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

ReflectorDocument threeReflectors() {
    return ReflectorDocument({makeReflector("a", {0, 0, 0}), makeReflector("b", {3, 0, 0}), makeReflector("c", {6, 0, 0})});
}

void expectOrthonormal(const Reflector& r) {
    EXPECT_NEAR(glm::length(r.normal), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(r.tangent), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(r.normal, r.tangent), 0.0f, 1e-6f);
    EXPECT_EQ(ppr::scene::validateReflector(r), "");
}

}  // namespace

// --- undo/redo of every kind of edit -------------------------------------------------------------

TEST(ReflectorEditor, AddUndoRedoRestoresExactStates) {
    ReflectorDocument doc = threeReflectors();
    const auto s0 = doc.reflectors();
    EXPECT_FALSE(doc.canUndo());
    const size_t i = doc.add(makeReflector("d", {9, 0, 0}));
    EXPECT_EQ(i, 3u);
    EXPECT_EQ(doc.selection(), std::optional<size_t>(3));
    const auto s1 = doc.reflectors();
    ASSERT_TRUE(doc.undo());
    EXPECT_SAME(doc.reflectors(), s0);
    EXPECT_FALSE(doc.canUndo());
    ASSERT_TRUE(doc.redo());
    EXPECT_SAME(doc.reflectors(), s1);
    EXPECT_EQ(doc.selection(), std::optional<size_t>(3));
    EXPECT_FALSE(doc.redo());
}

TEST(ReflectorEditor, AddMakesAClashingOrEmptyNameUnique) {
    ReflectorDocument doc = threeReflectors();
    doc.add(makeReflector("a"));
    EXPECT_EQ(doc.at(3).name, "a_2");
    doc.add(makeReflector(""));
    EXPECT_EQ(doc.at(4).name, "reflector_1");
    EXPECT_EQ(doc.validate(), "");
}

TEST(ReflectorEditor, DuplicateOffsetsAlongTangentWithUniqueNames) {
    ReflectorDocument doc({tiltedReflector()});
    const Reflector orig = doc.at(0);
    const auto s0 = doc.reflectors();
    auto i = doc.duplicate(0);
    ASSERT_TRUE(i);
    EXPECT_EQ(*i, 1u);
    EXPECT_EQ(doc.selection(), i);
    const Reflector& copy = doc.at(1);
    EXPECT_EQ(copy.name, "tilted_2");
    const glm::vec3 off = copy.center - orig.center;
    EXPECT_NEAR(glm::dot(off, orig.tangent), ReflectorDocument::kDuplicateOffset, 1e-5f);
    EXPECT_NEAR(glm::length(off), ReflectorDocument::kDuplicateOffset, 1e-5f);
    EXPECT_EQ(copy.normal, orig.normal);
    EXPECT_EQ(copy.tangent, orig.tangent);
    EXPECT_EQ(copy.halfExtents, orig.halfExtents);
    EXPECT_EQ(copy.reflectance, orig.reflectance);
    EXPECT_EQ(doc.at(*doc.duplicate(0)).name, "tilted_3");
    EXPECT_EQ(doc.at(*doc.duplicate(1)).name, "tilted_4");  // copying a copy continues the numbering
    EXPECT_EQ(doc.validate(), "");
    EXPECT_FALSE(doc.duplicate(99));

    ASSERT_TRUE(doc.undo());
    ASSERT_TRUE(doc.undo());
    ASSERT_TRUE(doc.undo());
    EXPECT_SAME(doc.reflectors(), s0);
    EXPECT_FALSE(doc.canUndo());
}

TEST(ReflectorEditor, RemoveUndoRedoAndSelection) {
    ReflectorDocument doc = threeReflectors();
    const auto s0 = doc.reflectors();
    doc.select(2);
    ASSERT_TRUE(doc.remove(0));
    EXPECT_EQ(doc.size(), 2u);
    EXPECT_EQ(doc.selection(), std::optional<size_t>(1));  // still "c"
    EXPECT_EQ(doc.at(1).name, "c");
    ASSERT_TRUE(doc.remove(1));  // the selected one
    EXPECT_EQ(doc.selection(), std::nullopt);
    const auto s2 = doc.reflectors();
    EXPECT_FALSE(doc.remove(5));
    ASSERT_TRUE(doc.undo());
    ASSERT_TRUE(doc.undo());
    EXPECT_SAME(doc.reflectors(), s0);
    EXPECT_EQ(doc.selection(), std::optional<size_t>(2));
    ASSERT_TRUE(doc.redo());
    ASSERT_TRUE(doc.redo());
    EXPECT_SAME(doc.reflectors(), s2);
}

TEST(ReflectorEditor, ReplaceOfEveryFieldUndoesExactly) {
    ReflectorDocument doc({tiltedReflector(), makeReflector("b")});
    std::vector<std::vector<Reflector>> states{doc.reflectors()};
    auto edit = [&](auto change) {
        Reflector r = doc.at(0);
        change(r);
        ASSERT_TRUE(doc.replace(0, r));
        states.push_back(doc.reflectors());
    };
    edit([](Reflector& r) { r = moveAlongPlane(r, {0.1f, 0.2f, 0.3f}); });
    edit([](Reflector& r) { r = rotateAboutNormal(r, 0.3f); });
    edit([](Reflector& r) { r = resizeEdge(r, kEdgePlusV, 0.25f); });
    edit([](Reflector& r) { r.name = "renamed"; });
    edit([](Reflector& r) { r.kind = ReflectorKind::Glass; });
    edit([](Reflector& r) { r.reflectance = 0.123f; });
    EXPECT_EQ(doc.undoDepth(), 6u);

    for (size_t k = states.size() - 1; k-- > 0;) {
        ASSERT_TRUE(doc.undo());
        EXPECT_SAME(doc.reflectors(), states[k]);
    }
    EXPECT_FALSE(doc.canUndo());
    for (size_t k = 1; k < states.size(); ++k) {
        ASSERT_TRUE(doc.redo());
        EXPECT_SAME(doc.reflectors(), states[k]);
    }
    EXPECT_FALSE(doc.replace(7, makeReflector("x")));
}

TEST(ReflectorEditor, ReplaceWithIdenticalValueRecordsNothing) {
    ReflectorDocument doc = threeReflectors();
    EXPECT_TRUE(doc.replace(1, doc.at(1)));
    EXPECT_FALSE(doc.canUndo());
    EXPECT_FALSE(doc.dirty());
}

TEST(ReflectorEditor, SetAllIsOneStep) {
    ReflectorDocument doc = threeReflectors();
    const auto s0 = doc.reflectors();
    doc.select(2);
    std::vector<Reflector> fitted = s0;
    for (auto& r : fitted) r.halfExtents *= 2.0f;
    fitted.pop_back();
    doc.setAll(fitted);
    EXPECT_SAME(doc.reflectors(), fitted);
    EXPECT_EQ(doc.selection(), std::nullopt);  // index 2 no longer exists
    EXPECT_EQ(doc.undoDepth(), 1u);
    ASSERT_TRUE(doc.undo());
    EXPECT_SAME(doc.reflectors(), s0);
    EXPECT_EQ(doc.selection(), std::optional<size_t>(2));
    ASSERT_TRUE(doc.redo());
    EXPECT_SAME(doc.reflectors(), fitted);
}

TEST(ReflectorEditor, SnapCreateUndoRedo) {
    ReflectorDocument doc = threeReflectors();
    const auto s0 = doc.reflectors();
    auto res = doc.snapCreate({1, 0, 1}, {0, 1, 0}, "puddle");
    ASSERT_TRUE(res) << res.error;
    const auto s1 = doc.reflectors();
    ASSERT_TRUE(doc.undo());
    EXPECT_SAME(doc.reflectors(), s0);
    ASSERT_TRUE(doc.redo());
    EXPECT_SAME(doc.reflectors(), s1);
}

// --- drags, redo clearing, bounded history -------------------------------------------------------

TEST(ReflectorEditor, DragIsOneUndoStep) {
    ReflectorDocument doc = threeReflectors();
    const auto s0 = doc.reflectors();
    ASSERT_TRUE(doc.beginEdit(1));
    EXPECT_TRUE(doc.editing());
    const Reflector start = doc.at(1);
    for (int i = 1; i <= 100; ++i) ASSERT_TRUE(doc.replace(1, moveAlongPlane(start, {0.01f * i, 0.5f, 0.0f})));
    EXPECT_TRUE(doc.dirty());  // unsaved while dragging, before the step is recorded
    doc.endEdit();
    EXPECT_FALSE(doc.editing());
    EXPECT_EQ(doc.undoDepth(), 1u);
    const auto s1 = doc.reflectors();
    EXPECT_FLOAT_EQ(doc.at(1).center.x, 4.0f);
    EXPECT_EQ(doc.at(1).center.y, 0.0f);  // the normal component of the drag was dropped
    ASSERT_TRUE(doc.undo());
    EXPECT_SAME(doc.reflectors(), s0);
    EXPECT_FALSE(doc.canUndo());
    EXPECT_FALSE(doc.dirty());
    ASSERT_TRUE(doc.redo());
    EXPECT_SAME(doc.reflectors(), s1);
}

TEST(ReflectorEditor, DragBackToStartRecordsNothing) {
    ReflectorDocument doc = threeReflectors();
    const Reflector start = doc.at(0);
    ASSERT_TRUE(doc.beginEdit(0));
    doc.replace(0, moveAlongPlane(start, {1, 0, 0}));
    doc.replace(0, start);
    doc.endEdit();
    EXPECT_FALSE(doc.canUndo());
    EXPECT_FALSE(doc.dirty());
}

TEST(ReflectorEditor, UndoDuringDragRevertsTheWholeDrag) {
    ReflectorDocument doc = threeReflectors();
    const auto s0 = doc.reflectors();
    ASSERT_TRUE(doc.beginEdit(0));
    doc.replace(0, resizeEdge(doc.at(0), kEdgePlusU, 0.5f));
    doc.replace(0, resizeEdge(doc.at(0), kEdgePlusU, 0.5f));
    EXPECT_TRUE(doc.canUndo());
    EXPECT_FALSE(doc.canRedo());
    ASSERT_TRUE(doc.undo());
    EXPECT_FALSE(doc.editing());
    EXPECT_SAME(doc.reflectors(), s0);
    EXPECT_TRUE(doc.canRedo());
    EXPECT_FALSE(doc.beginEdit(9));
}

TEST(ReflectorEditor, NewEditClearsRedo) {
    ReflectorDocument doc = threeReflectors();
    doc.add(makeReflector("d"));
    doc.add(makeReflector("e"));
    ASSERT_TRUE(doc.undo());
    EXPECT_TRUE(doc.canRedo());
    ASSERT_TRUE(doc.remove(0));
    EXPECT_FALSE(doc.canRedo());
    EXPECT_FALSE(doc.redo());

    // A drag that changes something clears redo too.
    ASSERT_TRUE(doc.undo());
    EXPECT_TRUE(doc.canRedo());
    doc.beginEdit(0);
    doc.replace(0, rotateAboutNormal(doc.at(0), 0.1f));
    doc.endEdit();
    EXPECT_FALSE(doc.canRedo());
}

TEST(ReflectorEditor, HistoryIsBounded) {
    ReflectorDocument doc({makeReflector("a")});
    const size_t n = ReflectorDocument::kMaxHistory + 40;
    for (size_t i = 0; i < n; ++i) {
        Reflector r = doc.at(0);
        r.center.x = float(i + 1);
        doc.replace(0, r);
    }
    EXPECT_EQ(doc.undoDepth(), ReflectorDocument::kMaxHistory);
    size_t undone = 0;
    while (doc.undo()) ++undone;
    EXPECT_EQ(undone, ReflectorDocument::kMaxHistory);
    EXPECT_EQ(doc.at(0).center.x, float(n - ReflectorDocument::kMaxHistory));  // the oldest steps were dropped
    EXPECT_TRUE(doc.dirty());  // the saved state is no longer reachable
}

// --- dirty ---------------------------------------------------------------------------------------

TEST(ReflectorEditor, DirtyThroughEditSaveUndo) {
    TempDir dir;
    ReflectorDocument doc = threeReflectors();
    EXPECT_FALSE(doc.dirty());
    doc.add(makeReflector("d"));
    EXPECT_TRUE(doc.dirty());
    ASSERT_TRUE(doc.undo());
    EXPECT_FALSE(doc.dirty());  // back to the initial (clean) state
    ASSERT_TRUE(doc.redo());
    EXPECT_TRUE(doc.dirty());

    ASSERT_EQ(doc.saveAs(dir.file("r.json")), "");
    EXPECT_FALSE(doc.dirty());
    doc.remove(0);
    EXPECT_TRUE(doc.dirty());
    ASSERT_TRUE(doc.undo());
    EXPECT_FALSE(doc.dirty());  // undo returned exactly to the saved state
    ASSERT_TRUE(doc.undo());
    EXPECT_TRUE(doc.dirty());  // before the save
    ASSERT_TRUE(doc.redo());
    EXPECT_FALSE(doc.dirty());

    // Undo past the save, then a different edit: a new state, dirty, and the saved one unreachable.
    ASSERT_TRUE(doc.undo());
    doc.add(makeReflector("z"));
    EXPECT_TRUE(doc.dirty());
    ASSERT_TRUE(doc.undo());
    EXPECT_TRUE(doc.dirty());  // initial state, which was never saved to r.json

    ASSERT_EQ(doc.save(), "");
    EXPECT_FALSE(doc.dirty());
    doc.add(makeReflector("q"));
    ASSERT_EQ(doc.load(dir.file("r.json")), "");
    EXPECT_FALSE(doc.dirty());
    EXPECT_FALSE(doc.canUndo());
    EXPECT_FALSE(doc.canRedo());
}

// --- snap creation -------------------------------------------------------------------------------

TEST(ReflectorEditor, SnapCreateDefaultsAndUniqueNames) {
    ReflectorDocument doc;
    auto r1 = doc.snapCreate({1, 2, 3}, {0, 2, 0}, "puddle");
    ASSERT_TRUE(r1) << r1.error;
    EXPECT_EQ(r1.error, "");
    EXPECT_EQ(*r1.index, 0u);
    EXPECT_EQ(doc.selection(), r1.index);
    const Reflector& p = doc.at(0);
    EXPECT_EQ(p.name, "puddle_1");
    EXPECT_EQ(p.center, glm::vec3(1, 2, 3));
    EXPECT_EQ(p.normal, glm::vec3(0, 1, 0));
    EXPECT_EQ(p.tangent, glm::vec3(1, 0, 0));
    EXPECT_EQ(p.halfExtents, glm::vec2(0.5f, 0.5f));
    EXPECT_EQ(p.kind, ReflectorKind::Opaque);
    EXPECT_EQ(p.reflectance, 0.7f);
    EXPECT_EQ(doc.at(*doc.snapCreate({0, 0, 0}, {0, 1, 0}, "puddle").index).name, "puddle_2");
    EXPECT_EQ(doc.at(*doc.snapCreate({0, 0, 0}, {0, 1, 0}, "").index).name, "reflector_1");
    // A user-renamed "puddle_3" is skipped rather than clashed with.
    doc.add(makeReflector("puddle_3"));
    EXPECT_EQ(doc.at(*doc.snapCreate({0, 0, 0}, {0, 1, 0}, "puddle").index).name, "puddle_4");
    EXPECT_EQ(doc.at(*doc.duplicate(0)).name, "puddle_5");  // copy of puddle_1: 2..4 taken
    EXPECT_EQ(doc.validate(), "");
}

TEST(ReflectorEditor, SnapCreateOrientation) {
    const glm::vec3 normals[] = {
        {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -3}, {1, 0, 0}, {-1, 0, 0}, {0.999f, 0.02f, 0.0f},
        {-0.95f, 0.1f, 0.3f}, {0.3f, 0.8f, -0.5f}, {1e-3f, 0, 0}, {1, 1, 1},
    };
    for (const glm::vec3& n : normals) {
        SCOPED_TRACE(testing::Message() << "normal (" << n.x << "," << n.y << "," << n.z << ")");
        ReflectorDocument doc;
        auto res = doc.snapCreate({0.5f, 0, -2}, n, "s");
        ASSERT_TRUE(res) << res.error;
        const Reflector& r = doc.at(*res.index);
        EXPECT_NEAR(glm::length(glm::normalize(n) - r.normal), 0.0f, 1e-6f);
        expectOrthonormal(r);
        EXPECT_NEAR(glm::length(r.bitangent()), 1.0f, 1e-5f);
    }
    // A normal parallel to X cannot use X: the tangent comes from Z, exactly.
    ReflectorDocument doc;
    const Reflector& wall = doc.at(*doc.snapCreate({0, 0, 0}, {1, 0, 0}, "wall").index);
    EXPECT_EQ(wall.tangent, glm::vec3(0, 0, 1));
    // Stable: slightly different normals give nearly the same tangent (no flipping between frames).
    Reflector a, b;
    ASSERT_EQ(makeSnappedReflector({0, 0, 0}, {0.01f, 1, 0}, a), "");
    ASSERT_EQ(makeSnappedReflector({0, 0, 0}, {0.011f, 1, 0.001f}, b), "");
    EXPECT_GT(glm::dot(a.tangent, b.tangent), 0.9999f);
}

TEST(ReflectorEditor, SnapCreateRejectsInvalidInput) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    ReflectorDocument doc = threeReflectors();
    const auto s0 = doc.reflectors();
    struct Case {
        glm::vec3 point, normal;
        std::string error;
    } cases[] = {
        {{nan, 0, 0}, {0, 1, 0}, "snap: surface point is not finite"},
        {{0, inf, 0}, {0, 1, 0}, "snap: surface point is not finite"},
        {{0, 0, 0}, {0, nan, 0}, "snap: surface normal is not finite"},
        {{0, 0, 0}, {0, 0, 0}, "snap: surface normal has zero length"},
        {{0, 0, 0}, {1e-9f, 0, 0}, "snap: surface normal has zero length"},
    };
    for (const auto& c : cases) {
        auto res = doc.snapCreate(c.point, c.normal, "puddle");
        EXPECT_FALSE(res);
        EXPECT_EQ(res.error, c.error);
    }
    EXPECT_SAME(doc.reflectors(), s0);
    EXPECT_FALSE(doc.canUndo());
    EXPECT_FALSE(doc.dirty());
}

// --- save / load ---------------------------------------------------------------------------------

TEST(ReflectorEditor, SaveRefusesInvalidReflectorNamingIt) {
    TempDir dir;
    const std::string path = dir.file("scene.reflectors.json");
    ReflectorDocument doc = threeReflectors();
    ASSERT_EQ(doc.saveAs(path), "");
    const std::string before = readText(path);

    ASSERT_TRUE(doc.snapCreate({0, 0, 0}, {0, 1, 0}, "puddle"));
    Reflector bad = doc.at(3);
    bad.halfExtents.x = 0.0f;
    ASSERT_TRUE(doc.replace(3, bad));
    const std::string expected = "reflector 3 'puddle_1': half_extents: must be > 0.0001 m, got [0, 0.5]";
    EXPECT_EQ(doc.validate(), expected);
    EXPECT_EQ(doc.save(), expected);
    EXPECT_EQ(doc.saveAs(dir.file("other.json")), expected);
    EXPECT_EQ(readText(path), before);  // previous file untouched
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"scene.reflectors.json"});  // no temp, no other.json
    EXPECT_TRUE(doc.dirty());
    EXPECT_EQ(doc.path(), path);

    // Other fields name themselves the same way.
    bad = doc.at(3);
    bad.halfExtents.x = 0.5f;
    bad.reflectance = 1.5f;
    doc.replace(3, bad);
    EXPECT_EQ(doc.save(), "reflector 3 'puddle_1': reflectance: must be within 0..1, got 1.5");
    bad.reflectance = 0.5f;
    bad.tangent = bad.normal;
    doc.replace(3, bad);
    EXPECT_EQ(doc.save(), "reflector 3 'puddle_1': tangent: parallel to normal");
    bad = doc.at(0);
    bad.name = "";
    doc.replace(0, bad);
    EXPECT_EQ(doc.save(), "reflector 0 '': name: must not be empty");
    EXPECT_EQ(readText(path), before);
}

TEST(ReflectorEditor, SaveRefusesDuplicateNames) {
    TempDir dir;
    ReflectorDocument doc = threeReflectors();
    Reflector r = doc.at(2);
    r.name = doc.at(0).name;  // (not a literal: sidesteps a GCC 12 -Wrestrict false positive)
    doc.replace(2, r);
    EXPECT_EQ(doc.saveAs(dir.file("x.json")), "reflector 2 'a': name: duplicate name (also reflector 0)");
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ReflectorEditor, SaveWithoutPathAsksForSaveAs) {
    ReflectorDocument doc = threeReflectors();
    doc.add(makeReflector("d"));
    EXPECT_EQ(doc.save(), "save: the document has no file yet (use Save As)");
    EXPECT_EQ(doc.saveAs(""), "save: empty file path");
    EXPECT_TRUE(doc.dirty());
}

TEST(ReflectorEditor, SaveLoadRoundTrip) {
    TempDir dir;
    const std::string path = dir.file("round.json");
    ReflectorDocument doc({tiltedReflector()});
    ASSERT_TRUE(doc.snapCreate({0.1f, -0.2f, 0.3f}, {0.2f, 0.9f, 0.1f}, "puddle"));
    Reflector g = rotateAboutNormal(doc.at(1), 1.234f);
    g.kind = ReflectorKind::Glass;
    g.reflectance = 0.04f;
    g = resizeEdge(g, kEdgeMinusV, 0.333f);
    doc.replace(1, g);
    doc.duplicate(0);
    ASSERT_EQ(doc.saveAs(path), "");
    EXPECT_EQ(doc.path(), path);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"round.json"});  // the temp file was renamed away

    ReflectorDocument loaded;
    ASSERT_EQ(loaded.load(path), "");
    EXPECT_SAME(loaded.reflectors(), doc.reflectors());
    EXPECT_EQ(loaded.path(), path);
    EXPECT_EQ(loaded.selection(), std::nullopt);
    EXPECT_FALSE(loaded.dirty());

    // load replaces the document and its history.
    ASSERT_EQ(doc.load(path), "");
    EXPECT_FALSE(doc.canUndo());
    EXPECT_SAME(doc.reflectors(), loaded.reflectors());
}

TEST(ReflectorEditor, LoadErrorsNameTheFileAndLeaveTheDocument) {
    TempDir dir;
    ReflectorDocument doc = threeReflectors();
    doc.add(makeReflector("d"));
    const auto s = doc.reflectors();

    const std::string missing = dir.file("missing.json");
    EXPECT_EQ(doc.load(missing), missing + ": no such file");

    const std::string broken = dir.file("broken.json");
    std::ofstream(broken) << R"({"version":1,"reflectors":[{"name":"x","center":[0,0,0],"normal":[0,2,0],"tangent":[1,0,0],"half_extents":[1,1]}]})";
    const std::string msg = doc.load(broken);
    EXPECT_EQ(msg.rfind(broken + ": reflectors[0].normal: not unit length", 0), 0u) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos);

    EXPECT_SAME(doc.reflectors(), s);
    EXPECT_TRUE(doc.canUndo());
    EXPECT_TRUE(doc.dirty());
    EXPECT_EQ(doc.path(), "");
}

// A failed or interrupted save must never cost the previous file.
TEST(ReflectorEditor, FailedSaveKeepsTheExistingFile) {
    TempDir dir;
    const std::string path = dir.file("keep.json");
    ReflectorDocument doc = threeReflectors();
    ASSERT_EQ(doc.saveAs(path), "");
    const std::string before = readText(path);
    doc.add(makeReflector("d"));

    // Unwritable destination (a missing directory; works even as root, unlike chmod).
    const std::string nowhere = dir.file("no/such/dir/x.json");
    const std::string err = doc.saveAs(nowhere);
    EXPECT_EQ(err.rfind(nowhere + ": cannot save", 0), 0u) << err;
    EXPECT_EQ(doc.path(), path);
    EXPECT_TRUE(doc.dirty());

    // The rename step fails (destination is a non-empty directory): the temp file is cleaned up.
    const std::string blocked = dir.file("blocked.json");
    fs::create_directories(fs::path(blocked) / "inside");
    const std::string err2 = doc.saveAs(blocked);
    EXPECT_EQ(err2.rfind(blocked + ": cannot save: rename", 0), 0u) << err2;
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"blocked.json", "keep.json"}));
    EXPECT_EQ(readText(path), before);
    EXPECT_TRUE(doc.dirty());
}

TEST(ReflectorEditor, CrashDuringSaveLeavesTheOldFileLoadable) {
    TempDir dir;
    const std::string path = dir.file("crash.json");
    ReflectorDocument doc = threeReflectors();
    ASSERT_EQ(doc.saveAs(path), "");
    const std::string before = readText(path);

    // A crash between writing the temp file and the rename leaves a half-written temp behind; the
    // target itself is never written in place.
    const std::string staleTmp = path + ".tmp-" + std::to_string(::getpid());
    std::ofstream(staleTmp) << R"({"version":1,"reflectors":[{"name":"tru)";
    ReflectorDocument reopened;
    ASSERT_EQ(reopened.load(path), "");
    EXPECT_SAME(reopened.reflectors(), doc.reflectors());
    EXPECT_EQ(readText(path), before);

    // The next save overwrites the leftover and renames it into place.
    doc.add(makeReflector("d"));
    ASSERT_EQ(doc.save(), "");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"crash.json"});
    ASSERT_EQ(reopened.load(path), "");
    EXPECT_SAME(reopened.reflectors(), doc.reflectors());
}

// --- handle math ---------------------------------------------------------------------------------

TEST(ReflectorHandles, MoveAlongPlaneKeepsThePlane) {
    const Reflector r = tiltedReflector();
    const glm::vec3 delta{0.4f, -1.3f, 2.2f};
    const Reflector m = moveAlongPlane(r, delta);
    EXPECT_NEAR(r.planeDistance(m.center), 0.0f, 1e-5f);
    // The in-plane part of the drag is applied in full.
    const glm::vec3 moved = m.center - r.center;
    EXPECT_NEAR(glm::dot(moved, r.tangent), glm::dot(delta, r.tangent), 1e-5f);
    EXPECT_NEAR(glm::dot(moved, r.bitangent()), glm::dot(delta, r.bitangent()), 1e-5f);
    EXPECT_EQ(m.normal, r.normal);
    EXPECT_EQ(m.tangent, r.tangent);
    EXPECT_EQ(m.halfExtents, r.halfExtents);
    // A purely normal drag does nothing; a NaN drag is ignored.
    EXPECT_NEAR(glm::length(moveAlongPlane(r, r.normal * 3.0f).center - r.center), 0.0f, 1e-5f);
    EXPECT_TRUE(sameReflector(moveAlongPlane(r, {std::nanf(""), 0, 0}), r));
}

TEST(ReflectorHandles, EdgeResizeKeepsTheOppositeEdgeFixed) {
    const Reflector r = tiltedReflector();
    const glm::vec3 u = r.tangent, v = r.bitangent();
    struct Edge {
        int edge;
        glm::vec3 dir;
        int axis;
    } edges[] = {{kEdgePlusU, u, 0}, {kEdgeMinusU, -u, 0}, {kEdgePlusV, v, 1}, {kEdgeMinusV, -v, 1}};
    for (const auto& e : edges) {
        for (float amount : {0.3f, -0.2f}) {
            SCOPED_TRACE(testing::Message() << "edge " << e.edge << " amount " << amount);
            const Reflector s = resizeEdge(r, e.edge, amount);
            const glm::vec3 oppBefore = r.center - e.dir * r.halfExtents[e.axis];
            const glm::vec3 oppAfter = s.center - e.dir * s.halfExtents[e.axis];
            EXPECT_NEAR(glm::length(oppAfter - oppBefore), 0.0f, 1e-5f);
            const glm::vec3 edgeAfter = s.center + e.dir * s.halfExtents[e.axis];
            const glm::vec3 edgeBefore = r.center + e.dir * r.halfExtents[e.axis];
            EXPECT_NEAR(glm::dot(edgeAfter - edgeBefore, e.dir), amount, 1e-5f);
            EXPECT_NEAR(s.halfExtents[e.axis], r.halfExtents[e.axis] + 0.5f * amount, 1e-6f);
            EXPECT_EQ(s.halfExtents[1 - e.axis], r.halfExtents[1 - e.axis]);
            EXPECT_NEAR(r.planeDistance(s.center), 0.0f, 1e-5f);
            EXPECT_EQ(s.normal, r.normal);
            EXPECT_EQ(s.tangent, r.tangent);
        }
    }
    // Shrinking past zero stops at the minimum width, still with the opposite edge fixed.
    const Reflector tiny = resizeEdge(r, kEdgePlusU, -10.0f);
    EXPECT_FLOAT_EQ(tiny.halfExtents.x, kMinEditHalfExtent);
    EXPECT_NEAR(glm::length((tiny.center - u * tiny.halfExtents.x) - (r.center - u * r.halfExtents.x)), 0.0f, 1e-5f);
    EXPECT_EQ(ppr::scene::validateReflector(tiny), "");
    // Bad edge index or amount: unchanged.
    EXPECT_TRUE(sameReflector(resizeEdge(r, 4, 1.0f), r));
    EXPECT_TRUE(sameReflector(resizeEdge(r, kEdgePlusU, std::nanf("")), r));
}

TEST(ReflectorHandles, EdgeResizeToPoint) {
    const Reflector r = tiltedReflector();
    // Drag the -V edge to a point 0.5 m beyond it (plus some off-axis and off-plane noise).
    const glm::vec3 target = r.center - r.bitangent() * (r.halfExtents.y + 0.5f) + r.tangent * 0.2f + r.normal * 0.1f;
    const Reflector s = resizeEdgeTo(r, kEdgeMinusV, target);
    EXPECT_NEAR(s.halfExtents.y, r.halfExtents.y + 0.25f, 1e-5f);
    EXPECT_EQ(s.halfExtents.x, r.halfExtents.x);
    const glm::vec3 plusVBefore = r.center + r.bitangent() * r.halfExtents.y;
    const glm::vec3 plusVAfter = s.center + s.bitangent() * s.halfExtents.y;
    EXPECT_NEAR(glm::length(plusVAfter - plusVBefore), 0.0f, 1e-5f);
}

TEST(ReflectorHandles, RotationKeepsOrthonormality) {
    const Reflector r = tiltedReflector();
    const Reflector q = rotateAboutNormal(r, glm::half_pi<float>());
    EXPECT_NEAR(glm::length(q.tangent - r.bitangent()), 0.0f, 1e-5f);  // +90 deg: tangent -> bitangent
    EXPECT_EQ(q.normal, r.normal);
    EXPECT_EQ(q.center, r.center);
    EXPECT_EQ(q.halfExtents, r.halfExtents);
    expectOrthonormal(q);

    // Many small steps (a long drag applied incrementally) do not drift and add up.
    Reflector acc = r;
    for (int i = 0; i < 1000; ++i) acc = rotateAboutNormal(acc, glm::two_pi<float>() / 1000.0f * 0.25f);
    expectOrthonormal(acc);
    EXPECT_NEAR(glm::length(acc.tangent - r.bitangent()), 0.0f, 1e-3f);
    EXPECT_TRUE(sameReflector(rotateAboutNormal(r, std::nanf("")), r));
    for (float a : {-2.0f, 0.1f, 3.0f, 100.0f}) expectOrthonormal(rotateAboutNormal(r, a));
}
