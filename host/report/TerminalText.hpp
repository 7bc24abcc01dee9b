// TerminalText: makes text from outside (file names, YAML fields, radio bytes) safe to print on a terminal.
#pragma once
#include <string>

namespace nxtmap::report {

// Returns `text` with every byte a terminal could act on made visible: C0 controls (0x00-0x1f, except that
// '\n' and '\r' become a space so a message stays one line), DEL (0x7f), the C1 controls U+0080-U+009F
// (UTF-8 C2 80-C2 9F) and every byte that is not part of well-formed UTF-8 are written as "\xNN", one per byte.
// Well-formed UTF-8 outside the C1 range passes unchanged. A backslash stays a single backslash.
std::string escapeForTerminal(const std::string& text);

}  // namespace nxtmap::report
