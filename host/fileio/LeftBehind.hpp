// LeftBehind: the files and folders a killed writer leaves beside its target, and their removal.
//
// A writer names what it stages after the target, its kind and its process: "<target>.saving-<pid>" (a house
// directory being written) or "<target>.tmp-<pid>-<n>" (an output file being written). A kill -9 leaves such an
// entry behind; the next writer of the same target removes every one whose process is no longer alive.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>

namespace nxtmap::fileio {

// The pid in `entry` when it is "<name><infix><pid>" or "<name><infix><pid>-<anything>", else 0.
pid_t writerPid(const std::string& entry, const std::string& name, const std::string& infix);

// True while a process with that pid exists (or cannot be signalled by us).
bool processAlive(pid_t pid);

// Removes (recursively) every entry beside `target` left by a writer of it with `infix` whose process is gone,
// and, when `includingOwn`, this process's own. Best effort: what cannot be removed stays.
void removeLeftBehind(const std::filesystem::path& target, const std::string& infix, bool includingOwn);

}  // namespace nxtmap::fileio
