#pragma once
// The `--set key=value` registry: one table of known keys, their allowed values and defaults, used
// by the CLI, the viewer's panels and report.json. Unknown keys and bad values are errors that list
// what is accepted.
#include <map>
#include <string>
#include <vector>

namespace ppr::app {

struct SettingSpec {
    std::string key;
    std::string defaultValue;
    std::vector<std::string> choices;  // empty = numeric in [min, max]
    double min = 0.0, max = 0.0;
    std::string help;
};

const std::vector<SettingSpec>& settingSpecs();

class Settings {
public:
    Settings();  // all defaults
    // Applies "key=value"; throws std::runtime_error naming the key/value and what is accepted.
    void apply(const std::string& assignment);
    void set(const std::string& key, const std::string& value);
    const std::string& get(const std::string& key) const;
    double number(const std::string& key) const;
    const std::map<std::string, std::string>& all() const { return values_; }

private:
    std::map<std::string, std::string> values_;
};

}  // namespace ppr::app
