#pragma once
// lit-render's flags as one table: each entry names a flag, the value it takes, the --help group it
// is listed under, its help text and how it is stored in Options. parseOptions reads flags only
// through this table and usageText prints every entry, so no flag is accepted without being
// documented.

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "Options.h"

namespace lit::cli {

// The --help headings, in the order printed: the render-settings groups of RenderSettings.h
// (output, sky, shadows, gi, indirect, debug) amid the program's own.
enum class FlagGroup {
    General,
    Files,
    Settings,
    Output,
    Sky,
    Shadows,
    Gi,
    Indirect,
    Debug,
    Benchmarks,
    Paths,
    Reference
};
inline constexpr FlagGroup kLastFlagGroup = FlagGroup::Reference;

// The heading --help prints over a group; "" for General, which comes first without one.
std::string_view title(FlagGroup group);

// How a flag is read and stored. A switch takes no value and sets its member; an on|off flag reads
// "on" or "off" into its member; any other value is checked and stored by a function, which
// throws UsageError naming `flag` (the flag's first name) when the value is wrong.
using Switch = bool Options::*;
using OnOff = std::optional<bool> Options::*;
using ParseValue = std::function<void(Options& options, const std::string& flag, const std::string& value)>;

struct Flag {
    std::vector<std::string> names;  // the first is the name messages use; the others are aliases ("-o")
    std::string value{};             // the value as --help shows it ("FILE.png", "WxH"); empty for switches and on|off
    std::string expects{};  // the value in words, for "missing value for --x (expects ...)"; on|off: "on or off"
    FlagGroup group = FlagGroup::General;
    std::string help;  // one paragraph; --help wraps it
    std::variant<Switch, OnOff, ParseValue> store;

    bool takesValue() const { return !std::holds_alternative<Switch>(store); }
    // What follows the names in --help: "FILE.png", "on|off" or nothing.
    std::string shownValue() const { return std::holds_alternative<OnOff>(store) ? "on|off" : value; }
    std::string expected() const { return std::holds_alternative<OnOff>(store) ? "on or off" : expects; }
};

// Every flag lit-render accepts, in --help order within each group. Built on each call: help
// texts quote the defaults of RenderSettings, so they are never copied by hand.
std::vector<Flag> flagTable();

// The flags that were replaced by others: a usage error that names the replacement, so an old
// script fails with a way forward. Not listed in --help (they are not accepted).
std::optional<std::string_view> replacementOf(std::string_view flag);

}  // namespace lit::cli
