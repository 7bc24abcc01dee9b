#include "host/log/Log.hpp"

#include <atomic>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <vector>

namespace nxtmap::log {
namespace {

// The level read from NXTMAP_LOG during static initialisation (a bad value is said once on stderr).
int initialLevel() {
  bool bad = false;
  const Level l = levelFromEnvironment(bad);
  if (bad) std::fprintf(stderr, "[warn] log: NXTMAP_LOG is not error, warn, info or debug; using warn\n");
  return static_cast<int>(l);
}

std::atomic<int> gLevel{initialLevel()};

std::mutex& sinkMutex() {
  static std::mutex m;
  return m;
}

Sink& sink() {
  static Sink s;
  return s;
}

void emit(const std::string& line) {
  std::lock_guard<std::mutex> lock(sinkMutex());
  if (sink()) {
    sink()(line);
  } else {
    std::fputs(line.c_str(), stderr);
    std::fflush(stderr);
  }
}

__attribute__((format(printf, 3, 0))) void vwrite(Level level, const char* area, const char* format, va_list args) {
  va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  std::vector<char> text(static_cast<size_t>(n > 0 ? n : 0) + 1);
  std::vsnprintf(text.data(), text.size(), format, again);
  va_end(again);
  emit(formatLine(level, area, text.data()));
}

}  // namespace

Level level() { return static_cast<Level>(gLevel.load(std::memory_order_relaxed)); }

void setLevel(Level l) { gLevel.store(static_cast<int>(l), std::memory_order_relaxed); }

bool enabled(Level l) { return static_cast<int>(l) <= gLevel.load(std::memory_order_relaxed); }

std::optional<Level> parseLevel(const std::string& text) {
  if (text == "error") return Level::Error;
  if (text == "warn" || text == "warning") return Level::Warn;
  if (text == "info") return Level::Info;
  if (text == "debug") return Level::Debug;
  return std::nullopt;
}

const char* levelName(Level l) {
  switch (l) {
    case Level::Error: return "error";
    case Level::Warn: return "warn";
    case Level::Info: return "info";
    case Level::Debug: return "debug";
  }
  return "?";
}

Level levelFromEnvironment(bool& bad) {
  bad = false;
  const char* text = std::getenv("NXTMAP_LOG");
  if (!text || !*text) return Level::Warn;
  const std::optional<Level> l = parseLevel(text);
  bad = !l;
  return l.value_or(Level::Warn);
}

void setSink(Sink s) {
  std::lock_guard<std::mutex> lock(sinkMutex());
  sink() = std::move(s);
}

std::string formatLine(Level l, const char* area, const std::string& message) {
  std::string line = std::string("[") + levelName(l) + "] " + area + ": " + message;
  if (!line.empty() && line.back() == '\n') line.pop_back();
  return line + "\n";
}

void write(Level l, const char* area, const char* format, ...) {
  if (!enabled(l)) return;
  va_list args;
  va_start(args, format);
  vwrite(l, area, format, args);
  va_end(args);
}

#define NXTMAP_LOG_AT(name, lvl)                         \
  void name(const char* area, const char* format, ...) { \
    if (!enabled(lvl)) return;                           \
    va_list args;                                        \
    va_start(args, format);                              \
    vwrite(lvl, area, format, args);                     \
    va_end(args);                                        \
  }
NXTMAP_LOG_AT(error, Level::Error)
NXTMAP_LOG_AT(warn, Level::Warn)
NXTMAP_LOG_AT(info, Level::Info)
NXTMAP_LOG_AT(debug, Level::Debug)
#undef NXTMAP_LOG_AT

}  // namespace nxtmap::log
