#include "host/mapio/OccupancyMap.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace nxtmap::mapio {

OccupancyMap::OccupancyMap(int width, int height, Occupancy fill, double resolutionM, MapOrigin origin)
    : width_(width), height_(height), resolutionM_(resolutionM), origin_(origin) {
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
    throw std::invalid_argument("map size " + std::to_string(width) + "x" + std::to_string(height) +
                                " out of range 1.." + std::to_string(kMaxSide));
  }
  if (!(resolutionM > 0.0) || !std::isfinite(resolutionM)) throw std::invalid_argument("resolution must be > 0");
  cells_.assign(static_cast<size_t>(width) * static_cast<size_t>(height), fill);
}

size_t OccupancyMap::count(Occupancy state) const {
  return static_cast<size_t>(std::count(cells_.begin(), cells_.end(), state));
}

bool OccupancyMap::validLabelName(const std::string& name) {
  if (name.empty() || name.size() > 64) return false;
  const char first = name[0];
  if (!((first >= 'a' && first <= 'z') || (first >= 'A' && first <= 'Z'))) return false;
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "null") return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
}

bool OccupancyMap::setLabel(const std::string& name, const CellBlock& b) {
  if (!validLabelName(name)) return false;
  if (b.width < 1 || b.height < 1 || !inside(b.col, b.row)) return false;
  if (b.width > width_ - b.col || b.height > height_ - b.row) return false;
  labels_[name] = b;
  return true;
}

bool OccupancyMap::operator==(const OccupancyMap& o) const {
  return width_ == o.width_ && height_ == o.height_ && resolutionM_ == o.resolutionM_ && origin_ == o.origin_ &&
         cells_ == o.cells_ && labels_ == o.labels_;
}

}  // namespace nxtmap::mapio
