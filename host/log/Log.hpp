// Log: the host's one logging facility. A message has a level (error, warn, info, debug) and an area
// ("house", "emu", "link", ...) and is printed as one line on stderr:
//   [debug] house: room 3: end 2, pose 4,5
// when its level is at or above the level in force (default warn; more verbose = higher in the enum).
// The level is read once from NXTMAP_LOG=error|warn|info|debug before main runs, and `nxtmap --log LEVEL`
// overrides it. A message that is off costs one relaxed atomic load and a compare (its arguments are
// still evaluated: guard expensive ones with `if (log::enabled(log::Level::Debug))`).
//
//   log::debug("house", "room %zu: end %d, pose %d,%d", rooms, end, x, y);   // printf-style
//   log::warn("emu", "unmapped read at %08x", address);
//
// Thread-safe: lines from several threads never interleave. Tests redirect the sink (setSink).
#pragma once
#include <functional>
#include <optional>
#include <string>

namespace nxtmap::log {

enum class Level { Error = 0, Warn = 1, Info = 2, Debug = 3 };

// The level in force: messages at this level or a lower (more severe) one are printed.
Level level();
void setLevel(Level level);
// Whether a message at `level` would be printed now.
bool enabled(Level level);

// "error", "warn", "info", "debug" (also "warning"); nothing for any other text.
std::optional<Level> parseLevel(const std::string& text);
const char* levelName(Level level);
// The level NXTMAP_LOG names (unset or empty: warn); a value parseLevel refuses gives warn and `bad` set.
Level levelFromEnvironment(bool& bad);

// Where whole lines go (each ends with '\n'); the default (or an empty function) writes to stderr.
using Sink = std::function<void(const std::string& line)>;
void setSink(Sink sink);

// One line "[level] area: message" (a trailing '\n' in the message is dropped).
std::string formatLine(Level level, const char* area, const std::string& message);

// printf-style messages; nothing is formatted when the level is off.
void write(Level level, const char* area, const char* format, ...) __attribute__((format(printf, 3, 4)));
void error(const char* area, const char* format, ...) __attribute__((format(printf, 2, 3)));
void warn(const char* area, const char* format, ...) __attribute__((format(printf, 2, 3)));
void info(const char* area, const char* format, ...) __attribute__((format(printf, 2, 3)));
void debug(const char* area, const char* format, ...) __attribute__((format(printf, 2, 3)));

}  // namespace nxtmap::log
