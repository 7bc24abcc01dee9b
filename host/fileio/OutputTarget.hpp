// OutputTarget: where an output file may be written, checked before anything is written.
//
// A target is accepted when it names a regular file that exists, or a new file in a folder that exists.
// Refused, with a message that names the path and the reason:
//  - a path ending in '/' (a folder, not a file);
//  - an existing target that is not a regular file (a device such as /dev/full, a directory, a pipe);
//  - a missing folder (nothing is created), or one that cannot be looked at (the system's reason);
//  - a symbolic link to nothing.
// A symbolic link to a regular file is followed: the file it points to is replaced, the link stays.
// "/dev/stdout" and "/dev/stderr" are the process's own streams: written in place, never replaced.
#pragma once

#include <optional>
#include <string>

namespace nxtmap::fileio {

struct OutputTarget {
  std::string file;     // the file to replace (the link's target for a symbolic link)
  int streamFd = -1;    // 1 or 2 for /dev/stdout, /dev/stderr: written in place; -1 for a file
  bool exists = false;  // file exists now (a regular file)
  unsigned mode = 0;    // its permission bits when it exists
};

// The checked target of `path`; nullopt with `error` ("cannot write PATH: <reason>") when refused.
std::optional<OutputTarget> resolveOutputTarget(const std::string& path, std::string& error);

// The text of a system error number, e.g. "No space left on device" for ENOSPC.
std::string systemErrorText(int errorNumber);

}  // namespace nxtmap::fileio
