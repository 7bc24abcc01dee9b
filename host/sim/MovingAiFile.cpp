#include "host/sim/MovingAiFile.hpp"

#include "host/sim/InputFile.hpp"
#include "host/sim/World.hpp"

#include <algorithm>
#include <charconv>
#include <sstream>
#include <utility>

namespace nxtmap::sim {

namespace {

// Splits on '\n', drops one trailing '\r' per line; a final newline does not make an extra line.
std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

bool parseInt(const std::string& s, int& out) {
  const char* end = s.data() + s.size();
  const auto res = std::from_chars(s.data(), end, out);
  return res.ec == std::errc() && res.ptr == end;
}

bool isBlank(const std::string& s) {
  return std::all_of(s.begin(), s.end(), [](char c) { return c == ' ' || c == '\t'; });
}

std::string at(const std::string& path, size_t lineIndex) { return path + ":" + std::to_string(lineIndex + 1) + ": "; }

// 0 free, 1 blocked, -1 not a map character.
int cellValue(char ch) {
  if (ch == '.' || ch == 'G') return 0;
  if (ch == '@' || ch == 'O' || ch == 'T' || ch == 'S' || ch == 'W') return 1;
  return -1;
}

// Reads the header lines up to "map"; li is left on the "map" line. "" or the error.
std::string readHeader(const std::string& path, const std::vector<std::string>& lines, size_t& li, int& w, int& h) {
  li = 0;
  if (lines.empty()) return path + ":1: missing 'type' header (file is empty)";
  const auto typeWords = words(lines[li]);
  if (typeWords.empty() || typeWords[0] != "type") return at(path, li) + "missing 'type' header";
  if (typeWords.size() != 2 || typeWords[1] != "octile")
    return at(path, li) + "unsupported map type (expected 'type octile')";
  bool haveH = false;
  bool haveW = false;
  for (++li;; ++li) {
    if (li >= lines.size()) return at(path, li) + "missing 'map' header";
    const auto ws = words(lines[li]);
    if (ws.size() == 1 && ws[0] == "map") break;
    if (ws.size() == 2 && (ws[0] == "height" || ws[0] == "width")) {
      int v = 0;
      if (!parseInt(ws[1], v)) return at(path, li) + "bad " + ws[0] + " '" + ws[1] + "'";
      if (v <= 0 || v > World::kMaxSide) {
        return at(path, li) + ws[0] + " " + ws[1] + " out of range 1.." + std::to_string(World::kMaxSide);
      }
      (ws[0] == "height" ? h : w) = v;
      (ws[0] == "height" ? haveH : haveW) = true;
      continue;
    }
    return at(path, li) + "unexpected header line '" + lines[li] + "'";
  }
  if (!haveH) return at(path, li) + "missing 'height' header before 'map'";
  if (!haveW) return at(path, li) + "missing 'width' header before 'map'";
  return "";
}

}  // namespace

std::optional<MovingAiGrid> readMovingAiFile(const std::string& path, std::string& error) {
  const std::optional<std::string> text = readInputFile(path, kMaxMovingAiBytes, "file", error);
  if (!text) return std::nullopt;
  const std::vector<std::string> lines = splitLines(*text);

  MovingAiGrid grid;
  size_t li = 0;
  error = readHeader(path, lines, li, grid.width, grid.height);
  if (!error.empty()) return std::nullopt;
  const int w = grid.width;
  const int h = grid.height;
  grid.blocked.assign(static_cast<size_t>(w) * static_cast<size_t>(h), 0);
  for (int r = 0; r < h; ++r) {
    ++li;
    if (li >= lines.size()) {
      error = at(path, li) + "expected " + std::to_string(h) + " map rows, found " + std::to_string(r);
      return std::nullopt;
    }
    const std::string& row = lines[li];
    if (row.size() != static_cast<size_t>(w)) {
      error = at(path, li) + "map row " + std::to_string(r) + " has " + std::to_string(row.size()) +
              " characters, expected width " + std::to_string(w);
      return std::nullopt;
    }
    for (int c = 0; c < w; ++c) {
      const char ch = row[static_cast<size_t>(c)];
      const int v = cellValue(ch);
      if (v < 0) {
        error = at(path, li) + "unknown character '" + std::string(1, ch) + "' at column " + std::to_string(c + 1);
        return std::nullopt;
      }
      grid.blocked[static_cast<size_t>(r) * static_cast<size_t>(w) + static_cast<size_t>(c)] = static_cast<uint8_t>(v);
    }
  }
  for (++li; li < lines.size(); ++li) {
    if (!isBlank(lines[li])) {
      error = at(path, li) + "extra data after " + std::to_string(h) + " map rows";
      return std::nullopt;
    }
  }
  return grid;
}

}  // namespace nxtmap::sim
