#pragma once
// Strict parsing of the words of editor text input (script lines, property values, command-line
// options): one definition of "a number" so the script parser, the property setters and the
// command line agree on what they accept. Window-free (lit_editor_core).

#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>
#include <type_traits>
#include <vector>

namespace lit::editor {

inline bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

inline std::string_view trim(std::string_view text) {
    while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
    while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
    return text;
}

// The whitespace-separated words of `text`.
inline std::vector<std::string_view> splitWords(std::string_view text) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && isSpace(text[i])) ++i;
        std::size_t end = i;
        while (end < text.size() && !isSpace(text[end])) ++end;
        if (end > i) words.push_back(text.substr(i, end - i));
        i = end;
    }
    return words;
}

// The whole word as a T, or nullopt: "1.5x", "", " 1" and out-of-range values are not numbers,
// nor (for floating-point T) "nan" and "inf".
template <class T>
std::optional<T> parseNumber(std::string_view word) {
    T value{};
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (ec != std::errc() || end != word.data() + word.size()) return std::nullopt;
    if constexpr (std::is_floating_point_v<T>)
        if (!std::isfinite(value)) return std::nullopt;
    return value;
}

}  // namespace lit::editor
