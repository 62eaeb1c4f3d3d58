#include "Log.h"

#include <cstdio>

namespace lit {

const char* toString(LogLevel level) {
    switch (level) {
        case LogLevel::Info: return "info";
        case LogLevel::Warning: return "warning";
        case LogLevel::Error: return "error";
    }
    return "?";
}

Log::Log() {
    sink_ = [](const LogMessage& m) {
        const std::string repeats = m.repeats > 1 ? " (" + std::to_string(m.repeats) + " times)" : std::string();
        if (m.level == LogLevel::Info)
            std::fprintf(stderr, "lit: %s%s\n", m.text.c_str(), repeats.c_str());
        else
            std::fprintf(stderr, "lit: %s: %s%s\n", toString(m.level), m.text.c_str(), repeats.c_str());
    };
}

void Log::setSink(Sink sink) {
    std::lock_guard lock(mutex_);
    sink_ = std::move(sink);
}

bool sameButNumbers(std::string_view a, std::string_view b) {
    auto isNumberChar = [](char c) { return (c >= '0' && c <= '9') || c == '.'; };
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        const bool na = isNumberChar(a[i]), nb = isNumberChar(b[j]);
        if (na && nb) {
            while (i < a.size() && isNumberChar(a[i])) ++i;
            while (j < b.size() && isNumberChar(b[j])) ++j;
            continue;
        }
        if (a[i] != b[j]) return false;
        ++i;
        ++j;
    }
    return i == a.size() && j == b.size();
}

void Log::write(LogLevel level, std::string_view text, Fold fold) {
    std::lock_guard lock(mutex_);
    const bool folds = !recent_.empty() && recent_.back().level == level && fold == lastFold_ &&
                       (fold == Fold::IgnoringNumbers ? sameButNumbers(recent_.back().text, text) : recent_.back().text == text);
    lastFold_ = fold;
    if (folds) {
        LogMessage& last = recent_.back();
        last.text = std::string(text);
        ++last.repeats;
        lastRunReported_ = false;
        return;
    }
    // The run before this message ends: the sink hears its last text and count once.
    if (!lastRunReported_ && !recent_.empty() && sink_) sink_(recent_.back());
    lastRunReported_ = true;
    LogMessage message{level, std::string(text)};
    if (sink_) sink_(message);
    if (recent_.size() == kKeep) recent_.erase(recent_.begin());
    recent_.push_back(std::move(message));
}

std::vector<LogMessage> Log::recent() const {
    std::lock_guard lock(mutex_);
    return recent_;
}

std::size_t Log::countAtLeast(LogLevel level) const {
    std::lock_guard lock(mutex_);
    std::size_t n = 0;
    for (const auto& m : recent_)
        if (m.level >= level) n += static_cast<std::size_t>(m.repeats);  // a folded run counts each time
    return n;
}

}  // namespace lit
