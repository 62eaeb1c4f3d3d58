#pragma once
// The renderer's message log. Not a global: the Renderer owns one and the loaders take one by
// reference. Front ends attach a sink (stderr for lit-render, the log panel in the editor).

#include <functional>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace lit {

enum class LogLevel { Info, Warning, Error };

struct LogMessage {
    LogLevel level;
    std::string text;
};

class Log {
public:
    using Sink = std::function<void(const LogMessage&)>;

    // By default messages go to stderr; a front end may replace that.
    Log();

    void setSink(Sink sink);
    void info(std::string_view text) { write(LogLevel::Info, text); }
    void warning(std::string_view text) { write(LogLevel::Warning, text); }
    void error(std::string_view text) { write(LogLevel::Error, text); }
    void write(LogLevel level, std::string_view text);

    // The most recent messages, oldest first (bounded, for the editor's log panel and tests).
    std::vector<LogMessage> recent() const;
    std::size_t countAtLeast(LogLevel level) const;

private:
    static constexpr std::size_t kKeep = 512;
    mutable std::mutex mutex_;  // texture decoding may log from worker threads
    Sink sink_;
    std::vector<LogMessage> recent_;
};

const char* toString(LogLevel level);

}  // namespace lit
