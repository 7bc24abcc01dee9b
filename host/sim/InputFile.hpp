// InputFile: the bytes of an input file (a world, a map image, a firmware image), read only when it is a
// regular file of at most a stated size. The file is opened first and looked at through the open
// descriptor (fstat), so a directory, a device such as /dev/zero, a pipe or a file larger than the bound is
// refused before a byte is read, and a file that grows while it is read is refused at the bound: the memory
// taken is never more than maxBytes. A pipe with no writer does not block the open (O_NONBLOCK).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace nxtmap::sim {

// The whole file; nullopt with `error` ("PATH: <reason>") when it cannot be opened or read, is not a regular
// file, or holds more than maxBytes bytes. `what` names the file in the messages ("file", "image file",
// "firmware file"), e.g. "PATH: cannot open image file (No such file or directory)".
std::optional<std::string> readInputFile(const std::string& path, size_t maxBytes, const std::string& what,
                                         std::string& error);

}  // namespace nxtmap::sim
