// AtomicFile: an output file that is written whole or not at all.
//
// open() checks the target (OutputTarget: a regular file or a new one in an existing folder) and creates
// a temporary file beside it (same folder, unique name TARGET.tmp-<pid>-<n>). write() appends to the
// temporary file; commit() flushes it to the disk (fsync), closes it, renames it over the target and
// flushes the folder, so the target holds the old bytes or the new ones, never a mixture. On any error
// the temporary file is removed, the target is untouched and the error says why ("No space left on
// device"). An AtomicFile destroyed without commit() removes its temporary file.
// /dev/stdout and /dev/stderr are written in place (there is nothing to rename).
#pragma once

#include <cstddef>
#include <string>

namespace nxtmap::fileio {

class AtomicFile {
 public:
  AtomicFile() = default;
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // False with `error` ("cannot write PATH: <reason>") when the target is refused or no temporary file can be made.
  bool open(const std::string& target, std::string& error);
  // The temporary file's path (a program may write it by name while this object is open).
  const std::string& tempPath() const { return temp_; }
  bool write(const void* data, size_t size, std::string& error);
  bool write(const std::string& bytes, std::string& error) { return write(bytes.data(), bytes.size(), error); }
  // Flushes, closes and renames over the target. False with `error` (the temporary file removed).
  bool commit(std::string& error);

 private:
  bool fail(const std::string& why, std::string& error);
  void discard();

  std::string shown_;   // the target as the caller named it (for messages)
  std::string target_;  // the file to replace
  std::string temp_;    // the temporary file beside it; "" when none
  int fd_ = -1;
  bool stream_ = false;  // writing to stdout / stderr in place
};

// open + write + commit.
bool writeFileAtomically(const std::string& target, const std::string& bytes, std::string& error);

// fsync of a folder, so renames and new entries in it survive a crash; false with `error` set.
bool syncDirectory(const std::string& folder, std::string& error);

}  // namespace nxtmap::fileio
