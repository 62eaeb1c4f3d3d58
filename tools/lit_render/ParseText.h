#pragma once
// The strict readings of command-line words that lit-render's flags share: a number is spelled
// exactly (no sign where none is allowed, no spaces, no trailing text), so "2.5" is not a frame
// count and "1.5x" is not an exposure.

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

namespace lit::cli {

// An integer in [lo, hi] spelled exactly, else nullopt.
inline std::optional<int> parseInt(std::string_view text, int lo, int hi) {
    int value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || value < lo || value > hi)
        return std::nullopt;
    return value;
}

// A finite number spelled exactly, else nullopt.
inline std::optional<float> parseFloat(std::string_view text) {
    float value = 0.0f;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

inline std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

}  // namespace lit::cli
