#include "host/mapping/FrameTransform.hpp"

namespace nxtmap::mapping {
namespace {
void vec(sim::Heading h, int& dc, int& dr) {
  static const int kCol[4] = {0, 1, 0, -1};
  static const int kRow[4] = {-1, 0, 1, 0};
  dc = kCol[static_cast<int>(h)];
  dr = kRow[static_cast<int>(h)];
}
}  // namespace

FrameTransform::FrameTransform(int startCol, int startRow, sim::Heading heading)
    : startCol_(startCol), startRow_(startRow), heading_(heading) {
  vec(heading, fwdCol_, fwdRow_);
  vec(static_cast<sim::Heading>((static_cast<int>(heading) + 1) % 4), rightCol_, rightRow_);
}

void FrameTransform::toWorld(Cell c, int& col, int& row) const {
  col = startCol_ + c.x * rightCol_ + c.y * fwdCol_;
  row = startRow_ + c.x * rightRow_ + c.y * fwdRow_;
}

Cell FrameTransform::toExplorer(int col, int row) const {
  const int dc = col - startCol_, dr = row - startRow_;
  return Cell{static_cast<int16_t>(dc * rightCol_ + dr * rightRow_), static_cast<int16_t>(dc * fwdCol_ + dr * fwdRow_)};
}

sim::Heading FrameTransform::toWorld(Dir d) const {
  return static_cast<sim::Heading>((static_cast<int>(heading_) + static_cast<int>(d)) % 4);
}

}  // namespace nxtmap::mapping
