#include "host/sim/World.hpp"

#include "host/sim/PgmImage.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <utility>

namespace nxtmap::sim {

namespace {

std::string stemOf(const std::string& path) { return std::filesystem::path(path).stem().string(); }

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

WorldLoad fail(std::string message) { return WorldLoad{std::nullopt, std::move(message)}; }

std::string at(const std::string& path, size_t lineIndex) {
    return path + ":" + std::to_string(lineIndex + 1) + ": ";
}

// Trinary YAML flag: 0/1/true/false.
bool readFlag(const YAML::Node& node) {
    const std::string s = node.as<std::string>();
    if (s == "0" || s == "false" || s == "False") return false;
    if (s == "1" || s == "true" || s == "True") return true;
    throw YAML::Exception(node.Mark(), "negate must be 0 or 1, got '" + s + "'");
}

}  // namespace

World::World(int width, int height, double resolutionM, std::string name, std::vector<uint8_t> cells)
    : width_(width), height_(height), resolutionM_(resolutionM), name_(std::move(name)), cells_(std::move(cells)) {}

World World::fromRows(const std::vector<std::string>& rows, double resolutionM) {
    size_t w = 0;
    for (const auto& r : rows) w = std::max(w, r.size());
    std::vector<uint8_t> cells(w * rows.size(), 0);
    for (size_t r = 0; r < rows.size(); ++r) {
        for (size_t c = 0; c < rows[r].size(); ++c) {
            const char ch = rows[r][c];
            cells[r * w + c] = (ch == '.' || ch == ' ') ? 0 : 1;
        }
    }
    return World(static_cast<int>(w), static_cast<int>(rows.size()), resolutionM, "rows", std::move(cells));
}

WorldLoad World::load(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".map") return loadMovingAi(path);
    if (ext == ".yaml" || ext == ".yml") return loadRosYaml(path);
    return fail(path + ": unknown world format (expected .map, .yaml or .yml)");
}

WorldLoad World::loadMovingAi(const std::string& path, double resolutionM) {
    if (!(resolutionM > 0.0)) return fail(path + ": resolution must be > 0");
    std::ifstream in(path, std::ios::binary);
    if (!in) return fail(path + ": cannot open file");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::vector<std::string> lines = splitLines(text);

    size_t li = 0;
    if (li >= lines.size()) return fail(path + ":1: missing 'type' header (file is empty)");
    const auto typeWords = words(lines[li]);
    if (typeWords.empty() || typeWords[0] != "type") return fail(at(path, li) + "missing 'type' header");
    if (typeWords.size() != 2 || typeWords[1] != "octile") return fail(at(path, li) + "unsupported map type (expected 'type octile')");
    int h = 0;
    int w = 0;
    bool haveH = false;
    bool haveW = false;
    for (++li;; ++li) {
        if (li >= lines.size()) return fail(at(path, li) + "missing 'map' header");
        const auto ws = words(lines[li]);
        if (ws.size() == 1 && ws[0] == "map") break;
        if (ws.size() == 2 && (ws[0] == "height" || ws[0] == "width")) {
            int v = 0;
            if (!parseInt(ws[1], v)) return fail(at(path, li) + "bad " + ws[0] + " '" + ws[1] + "'");
            if (v <= 0 || v > kMaxSide) {
                return fail(at(path, li) + ws[0] + " " + ws[1] + " out of range 1.." + std::to_string(kMaxSide));
            }
            (ws[0] == "height" ? h : w) = v;
            (ws[0] == "height" ? haveH : haveW) = true;
            continue;
        }
        return fail(at(path, li) + "unexpected header line '" + lines[li] + "'");
    }
    if (!haveH) return fail(at(path, li) + "missing 'height' header before 'map'");
    if (!haveW) return fail(at(path, li) + "missing 'width' header before 'map'");

    std::vector<uint8_t> cells(static_cast<size_t>(w) * static_cast<size_t>(h), 0);
    for (int r = 0; r < h; ++r) {
        ++li;
        if (li >= lines.size()) {
            return fail(at(path, li) + "expected " + std::to_string(h) + " map rows, found " + std::to_string(r));
        }
        const std::string& row = lines[li];
        if (row.size() != static_cast<size_t>(w)) {
            return fail(at(path, li) + "map row " + std::to_string(r) + " has " + std::to_string(row.size()) +
                        " characters, expected width " + std::to_string(w));
        }
        for (int c = 0; c < w; ++c) {
            const char ch = row[static_cast<size_t>(c)];
            uint8_t v = 0;
            if (ch == '.' || ch == 'G') {
                v = 0;
            } else if (ch == '@' || ch == 'O' || ch == 'T' || ch == 'S' || ch == 'W') {
                v = 1;
            } else {
                return fail(at(path, li) + "unknown character '" + std::string(1, ch) + "' at column " + std::to_string(c + 1));
            }
            cells[static_cast<size_t>(r) * static_cast<size_t>(w) + static_cast<size_t>(c)] = v;
        }
    }
    for (++li; li < lines.size(); ++li) {
        if (!isBlank(lines[li])) {
            return fail(at(path, li) + "extra data after " + std::to_string(h) + " map rows");
        }
    }
    return WorldLoad{World(w, h, resolutionM, stemOf(path), std::move(cells)), {}};
}

WorldLoad World::loadRosYaml(const std::string& yamlPath) {
    std::string imageName;
    double resolution = 0.0;
    double occupiedThresh = 0.0;
    double freeThresh = 0.0;
    bool negate = false;
    try {
        const YAML::Node doc = YAML::LoadFile(yamlPath);
        if (!doc.IsMap()) return fail(yamlPath + ": not a YAML mapping");
        for (const char* key : {"image", "resolution", "occupied_thresh", "free_thresh"}) {
            if (!doc[key]) return fail(yamlPath + ": missing key '" + key + "'");
        }
        imageName = doc["image"].as<std::string>();
        resolution = doc["resolution"].as<double>();
        occupiedThresh = doc["occupied_thresh"].as<double>();
        freeThresh = doc["free_thresh"].as<double>();
        if (doc["negate"]) negate = readFlag(doc["negate"]);
        if (doc["origin"] && (!doc["origin"].IsSequence() || doc["origin"].size() != 3)) {
            return fail(yamlPath + ": origin must be [x, y, yaw]");
        }
        if (doc["mode"] && doc["mode"].as<std::string>() != "trinary") {
            return fail(yamlPath + ": mode '" + doc["mode"].as<std::string>() + "' not supported (only trinary)");
        }
    } catch (const YAML::Exception& e) {
        return fail(yamlPath + ": " + e.what());
    }
    if (!(resolution > 0.0) || !std::isfinite(resolution)) return fail(yamlPath + ": resolution must be > 0");
    if (!(freeThresh >= 0.0 && freeThresh <= occupiedThresh && occupiedThresh <= 1.0)) {
        return fail(yamlPath + ": thresholds must satisfy 0 <= free_thresh <= occupied_thresh <= 1");
    }

    std::filesystem::path imagePath(imageName);
    if (imagePath.is_relative()) imagePath = std::filesystem::path(yamlPath).parent_path() / imagePath;
    std::string error;
    const std::optional<PgmImage> img = readPgm(imagePath.string(), error);
    if (!img) return fail(yamlPath + ": " + error);

    std::vector<uint8_t> cells(img->pixels.size(), 1);
    for (size_t i = 0; i < img->pixels.size(); ++i) {
        const double shade = static_cast<double>(img->pixels[i]) / img->maxval;
        const double occ = negate ? shade : 1.0 - shade;
        // occ > occupied_thresh: blocked; occ < free_thresh: free; in between unknown, kept blocked.
        if (occ < freeThresh && !(occ > occupiedThresh)) cells[i] = 0;
    }
    // Image row 0 is the top of the map, which is our row 0 as well (rows grow down).
    return WorldLoad{World(img->width, img->height, resolution, stemOf(yamlPath), std::move(cells)), {}};
}

}  // namespace nxtmap::sim
