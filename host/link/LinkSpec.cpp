#include "host/link/LinkSpec.hpp"

#include <cctype>
#include <algorithm>
#include <regex>

namespace nxtmap::link {
namespace {
const char* kForms = "use bt:00:16:53:XX:XX:XX, serial:/dev/rfcomm0, tcp:HOST:PORT or sim:WORLD[@COL,ROW]";

int parseInt(const std::string& s, int lo, int hi, const std::string& what) {
  if (s.empty() || s.size() > 6 ||
      !std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
    throw LinkError(what + " '" + s + "' is not a number");
  }
  const int v = std::stoi(s);
  if (v < lo || v > hi)
    throw LinkError(what + " " + s + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
  return v;
}
}  // namespace

LinkSpec parseLinkSpec(const std::string& text) {
  LinkSpec spec;
  spec.text = text;
  const size_t colon = text.find(':');
  if (colon == std::string::npos) throw LinkError("link '" + text + "' has no kind: " + kForms);
  const std::string kind = text.substr(0, colon), rest = text.substr(colon + 1);
  if (kind == "bt") {
    static const std::regex mac("^[0-9A-Fa-f]{2}(:[0-9A-Fa-f]{2}){5}$");
    if (!std::regex_match(rest, mac))
      throw LinkError("Bluetooth address '" + rest + "' is not six hex pairs like 00:16:53:0A:1B:2C");
    spec.kind = LinkSpec::Kind::Bluetooth;
    spec.address = rest;
    spec.port = 1;
  } else if (kind == "serial") {
    if (rest.empty() || rest[0] != '/')
      throw LinkError("serial device '" + rest + "' must be an absolute path like /dev/rfcomm0");
    spec.kind = LinkSpec::Kind::Serial;
    spec.address = rest;
  } else if (kind == "tcp") {
    const size_t last = rest.rfind(':');
    if (last == std::string::npos || last == 0) throw LinkError("TCP link '" + rest + "' needs HOST:PORT");
    spec.kind = LinkSpec::Kind::Tcp;
    spec.address = rest.substr(0, last);
    if (spec.address.size() > 2 && spec.address.front() == '[' && spec.address.back() == ']') {
      spec.address = spec.address.substr(1, spec.address.size() - 2);  // [::1]:5000
    }
    spec.port = parseInt(rest.substr(last + 1), 1, 65535, "TCP port");
  } else if (kind == "sim") {
    spec.kind = LinkSpec::Kind::Sim;
    const size_t at = rest.rfind('@');
    spec.address = rest.substr(0, at);
    if (spec.address.empty()) throw LinkError("sim link needs a world file: sim:worlds/room.map");
    if (at != std::string::npos) {
      const std::string cell = rest.substr(at + 1);
      const size_t comma = cell.find(',');
      if (comma == std::string::npos) throw LinkError("sim start '" + cell + "' must be COL,ROW");
      spec.col = parseInt(cell.substr(0, comma), 0, 4095, "start column");
      spec.row = parseInt(cell.substr(comma + 1), 0, 4095, "start row");
    }
  } else {
    throw LinkError("unknown link kind '" + kind + "': " + kForms);
  }
  return spec;
}

}  // namespace nxtmap::link
