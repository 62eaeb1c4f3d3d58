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
        if (m.level == LogLevel::Info)
            std::fprintf(stderr, "lit: %s\n", m.text.c_str());
        else
            std::fprintf(stderr, "lit: %s: %s\n", toString(m.level), m.text.c_str());
    };
}

void Log::setSink(Sink sink) {
    std::lock_guard lock(mutex_);
    sink_ = std::move(sink);
}

void Log::write(LogLevel level, std::string_view text) {
    std::lock_guard lock(mutex_);
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
        if (m.level >= level) ++n;
    return n;
}

}  // namespace lit
