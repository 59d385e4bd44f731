// One source, checked: every declared setting and technique appears in `ppr --help`, is accepted by
// --set / --technique, and shows up in report.json (settings block, technique name, its cost passes).
#include "gpu_test_util.hpp"
#include "settings/settings.hpp"
#include "techniques/technique_table.hpp"

#include <nlohmann/json.hpp>

#include <fstream>

namespace ppr::test {
namespace {

nlohmann::json readReport(const std::filesystem::path& dir) {
    std::ifstream f(dir / "report.json");
    return nlohmann::json::parse(f);
}

TEST(Declarations, HelpNamesEverySettingAndTechnique) {
    const RunResult r = runPpr("--help");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const app::SettingDecl& d : app::settingDecls()) {
        EXPECT_NE(r.output.find("    " + d.key + "="), std::string::npos) << d.key;
        EXPECT_NE(r.output.find(d.help.substr(0, 40)), std::string::npos) << d.key;
    }
    for (const app::TechniqueDesc& t : app::techniqueTable()) EXPECT_NE(r.output.find("    " + t.name + " "), std::string::npos) << t.name;
}

TEST(Declarations, EverySettingIsAcceptedAndReported) {
    // Every key at a value other than its default where it has one, in one capture.
    std::string sets;
    std::map<std::string, std::string> expected;
    for (const app::SettingDecl& d : app::settingDecls()) {
        std::string value = d.defaultValue;
        if (!d.choices.empty()) {
            for (const std::string& c : d.choices)
                if (c != d.defaultValue && c != "atlas") value = c;  // any other choice
        } else if (d.kind == app::SettingKind::Integer) {
            value = std::to_string(static_cast<long long>(d.min));
        }
        sets += " --set " + d.key + "=" + value;
        expected[d.key] = value;
    }
    const auto dir = tempDir("declared-settings");
    const RunResult r = runPpr("capture --validation --camera stairs --size 96x54 --frames 1 --out " + dir.string() + sets);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json report = readReport(dir);
    EXPECT_EQ(report["validation_errors"], 0);
    ASSERT_EQ(report["settings"].size(), app::settingDecls().size()) << report["settings"].dump();
    for (const auto& [key, value] : expected) EXPECT_EQ(report["settings"][key], value) << key;
    std::filesystem::remove_all(dir);
}

TEST(Declarations, EveryTechniqueIsAcceptedAndReportedWithItsCost) {
    for (const app::TechniqueDesc& t : app::techniqueTable()) {
        if (t.name == "raytraced" && !rayQueryMissing().empty()) continue;  // refused, as RaytracedCli checks
        const auto dir = tempDir("declared-" + t.name);
        const RunResult r = runPpr("capture --validation --camera stairs --size 96x54 --frames 1 --technique " + t.name + " --out " + dir.string());
        ASSERT_EQ(r.exitCode, 0) << t.name << "\n" << r.output;
        const nlohmann::json report = readReport(dir);
        EXPECT_EQ(report["technique"], t.name);
        EXPECT_EQ(report["validation_errors"], 0) << t.name;
        bool ownPass = false;
        for (const auto& [pass, timing] : report["passes"].items()) ownPass |= app::isTechniquePass(t.name, pass);
        EXPECT_EQ(ownPass, t.make != nullptr) << t.name << ": a technique with a module has passes that are its cost";
        if (t.make) EXPECT_GT(report["technique_gpu_ms"].get<double>(), 0.0) << t.name;
        std::filesystem::remove_all(dir);
    }
}

}  // namespace
}  // namespace ppr::test
