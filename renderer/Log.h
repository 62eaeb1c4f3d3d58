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
    // Messages that repeat back to back are folded into one entry holding the newest text and
    // how many times it was written: the same level and text, or, for messages written with
    // Fold::IgnoringNumbers, the same text once numbers are ignored ("re-voxelized 64³ ...:
    // voxelize 3.1 ms" on every frame of a gizmo drag).
    int repeats = 1;
};

// How a message may fold into the one before it (see LogMessage::repeats). Loader warnings that
// differ in an index ("image 4 ...", "image 9 ...") must stay separate, so ignoring numbers is
// asked for by the writer of a per-frame status line.
enum class Fold { Identical, IgnoringNumbers };

// Whether two message texts are the same but for their numbers (the folding rule above).
bool sameButNumbers(std::string_view a, std::string_view b);

class Log {
public:
    using Sink = std::function<void(const LogMessage&)>;

    // By default messages go to stderr; a front end may replace that. The sink sees a folded run
    // once when it starts (repeats = 1) and once when it ends (the last text, repeats = N > 1),
    // not once per repeat.
    Log();

    void setSink(Sink sink);
    void info(std::string_view text, Fold fold = Fold::Identical) { write(LogLevel::Info, text, fold); }
    void warning(std::string_view text, Fold fold = Fold::Identical) { write(LogLevel::Warning, text, fold); }
    void error(std::string_view text, Fold fold = Fold::Identical) { write(LogLevel::Error, text, fold); }
    void write(LogLevel level, std::string_view text, Fold fold = Fold::Identical);

    // The most recent messages, oldest first (bounded, for the editor's log panel and tests).
    std::vector<LogMessage> recent() const;
    // Messages written at `level` or above among recent() (a folded run counts every repeat).
    std::size_t countAtLeast(LogLevel level) const;

private:
    static constexpr std::size_t kKeep = 512;
    mutable std::mutex mutex_;  // texture decoding may log from worker threads
    Sink sink_;
    std::vector<LogMessage> recent_;
    bool lastRunReported_ = true;  // the sink has seen the end of the last folded run
    Fold lastFold_ = Fold::Identical;  // how the last message was written
};

const char* toString(LogLevel level);

}  // namespace lit
