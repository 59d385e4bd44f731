#pragma once
// Settings declared once: each `--set key=value` has a key, a kind, a default, its range or choices,
// help text, an owner and the typed field it decodes into (FrameSettings). `--set` parsing and its
// errors, `ppr --help`, the viewer's widgets, report.json's and bench.json's "settings" blocks all
// read settingDecls(); nothing else lists a key.
#include "settings/frame_settings.hpp"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace ppr::app {

enum class SettingKind { Toggle, Choice, Number, Integer };

struct SettingDecl {
    std::string key;
    SettingKind kind = SettingKind::Number;
    std::string defaultValue;          // as text, parsed like any --set value
    std::vector<std::string> choices;  // Toggle: {"0","1"}; Choice: the names; numbers: empty
    double min = 0.0, max = 0.0;       // Number / Integer
    std::string owner;                 // the module that reads it (frame, tiles, ppr, ssr, glass)
    std::string help;
    std::vector<std::string> choiceHelp;  // Choice: optional, one line per choice (debug views)
    // The typed field: text (already validated) in, canonical text out.
    std::function<void(FrameSettings&, const std::string&)> write;
    std::function<std::string(const FrameSettings&)> read;
};

const std::vector<SettingDecl>& settingDecls();
const SettingDecl* findSetting(const std::string& key);
// The `--set` block of `ppr --help`, one line per key (choices or range, default, owner, help).
std::string settingsUsage();

class Settings {
public:
    Settings();  // every default
    // Applies "key=value"; throws std::runtime_error naming the key/value and what is accepted.
    void apply(const std::string& assignment);
    void set(const std::string& key, const std::string& value);
    std::string get(const std::string& key) const;  // canonical text (throws std::logic_error if unknown)
    double number(const std::string& key) const;
    const FrameSettings& values() const { return values_; }
    std::map<std::string, std::string> canonicalTexts() const;  // every key → canonical text (reports)

private:
    FrameSettings values_{};
};

}  // namespace ppr::app
